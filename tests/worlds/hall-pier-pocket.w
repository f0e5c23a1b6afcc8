# hall-pier-pocket.w - go next-room: a corner of a hall parted off by three
# free-standing piers (paper task (ii); issue 13 item 3, rooms that are rooms; paper
# 3.4.2, an object's letter is not B). Random world 292 of tests/gen/worldgen.c (the
# rates' set), kept as it came. By the verdict's rule (a watershed of clearance) the
# north-west corner, behind the piers at (7-10, 18-24), (16-19, 27-29) and (19-26,
# 37-41), is a room: the narrowings between them run across diagonals. Utak sees the
# piers as objects (space to rooms) until touch shows their B, and no one of them
# alone parts the hall, so on d27d521 he found no door and failed, saying so. Now
# he touches them all together (roomdoubt_felt, nextroom_felt), and with them wall
# his model's watershed shows the corner room past their door line; he goes there
# once every object in it and in his starting room has been touched and the faces
# in its doorway seen in the fovea (nextroom.h), and claims it.
table 86 49
wall 46 11 50 11 50 18 46 18
wall 16 27 19 27 19 29 16 29
wall 7 18 10 18 10 24 7 24
wall 19 37 26 37 26 41 19 41
wall 53 23 56 23 56 29 53 29
wall 61 19 64 19 64 25 61 25
object square1 P 11.904 3.897 15.665 8.941 10.621 12.702 6.86 7.658
object square2 K 56.251 3.279 56.251 7.304 52.226 7.304 52.226 3.279
object lshape P 59.085 37.379 54.475 37.379 54.475 33.749 57.082 33.749 57.082 31.016 59.085 31.016
object bit1 E 74.688 36.683 73.929 34.321 75.259 35.484
object bit2 Q 51.213 10.213 49.907 9.541 50.228 8.918 51.534 9.59
object bit3 S 83.662 43.546 81.851 43.437 82.901 42.824
object bit4 S 43.999 11.023 43.37 12.011 41.702 9.958
object bit5 Y 40.501 14.92 42.627 14.92 42.627 17.046 40.501 17.046
object bit6 H 23.438 3.88 20.846 4.701 20.922 2.857
utak 11.5 17.5 north
