# push-stub-wall.w - two rooms split by a wall one square thick across the TABLE
# with two doors (tests/gen/worldgen.c, world 80 of the random set); Utak starts
# in the north room facing south, so his north-east corner is the TABLE's
# south-west corner of his room, beside the wall's west stub (x 1-17). Seen from
# afar, the stub reads as an object parted from the west wall by three squares of
# floor a coarse cell misread, and objects are space to rooms: the model joins
# the two rooms there and the square ends up in the next room's corner. The stub
# comes within a coarse cell of the wall over squares seen only coarsely, so it
# is doubtful whole (roomdoubt.h): Utak cannot tell the corner is of his room and
# fails honestly; before, he claimed it (a false success).
table 74 48
wall 1 29 17 29 17 30 1 30
wall 25 29 60 29 60 30 25 30
wall 68 29 73 29 73 30 68 30
object square1 Y 16.929 12.249 22.861 12.249 22.861 18.181 16.929 18.181
object brick V 63.827 3.143 63.472 8.818 59.999 8.6 60.354 2.926
object lshape E 32.742 40.729 33.726 34.327 37.228 34.865 36.654 38.603 41.181 39.299 40.771 41.963
object triangle I 47.663 20.885 52.841 22.31 50.371 23.701
object bit1 G 42.73 8.475 43.667 9.136 43.122 10.284
utak 44.5 35.5 south
