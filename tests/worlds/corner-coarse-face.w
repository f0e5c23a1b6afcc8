# corner-coarse-face.w - a table split by one wall with a door 7 wide; Utak starts
# in the west part, 15 wide (paper task (i); issue 13 items 3 and 6: a corner is
# the starting room's, and Utak claims only what his model can tell). Made by
# worldgen (random g291 of the rates, /tmp/rk24), kept as it came. By the
# verdict's ratio the door is one: the west room's peak clearance is twice the
# door's. Utak, facing east, reaches his north-east corner (the table's south-east
# of the west part) past the square, which the eye's coarse cells join to the
# verge beside it: his model reads the room a square narrower there, too narrow
# for the door to be one, and floor of the east room beats his corner on the
# verdict's watershed restated. With every verge square seen only coarsely beside
# floor taken for floor the corner holds, so he looks at the nearest such square
# beside his room (hallsplit.h, FACES), the fovea parts the square from the verge,
# and he claims the corner, which the judge counts reached. Before FACES his four
# looks went along the way into the east room, and he doubted it (205 cycles).
table 46 57
wall 16 1 18 1 18 11 16 11
wall 16 18 18 18 18 56 16 56
object square1 T 8.299 2.256 14.049 2.256 14.049 8.006 8.299 8.006
object brick Y 20.721 44.924 25.117 41.973 26.665 44.28 22.269 47.23
object triangle Z 26.373 18.553 29.047 12.823 34.822 16.048
object piece1 D 21.085 32.209 23.358 30.107 29.201 28.749 28.945 33.099 26.96 34.583
object piece2 F 35.829 44.48 33.276 46.165 31.072 45.384 30.297 43.165 30.156 39.656 34.345 38.808 37.807 40.839
object bit1 U 43.549 42.744 42.243 42.744 42.243 41.438 43.549 41.438
object bit2 P 19.566 14.394 17.643 15.053 18.19 14.238
object bit3 S 39.863 16.622 39.787 18.552 37.857 18.475 37.934 16.546
object bit4 V 32.09 54.208 29.959 53.498 30.409 52.149 32.54 52.859
utak 9.5 51.5 east
