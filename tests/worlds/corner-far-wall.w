# corner-far-wall.w - four rooms in a grid; the south wall of Utak's start room is
# never seen in part before he stands in its north-east corner (paper task (i);
# issue 13 items 3 and 6: a corner is the starting room's, and Utak claims only
# what his model can tell). Made by worldgen (random g241 of the rates, /tmp/rk24),
# kept as it came. Utak, facing north, walks east to his room's north-east corner
# beside the door (6 wide) into the east room. His model has not seen 16 squares
# of his room's south wall, nor the east room's south wall: on the verdict's
# watershed restated on his model (the unseen as space) both rooms run on into the
# unseen south of them, his through an opening too wide for a door by the ratio
# (his room's peak clearance under twice the opening's), so the east room's floor
# beats his corner. Restated with the unseen as wall, his corner holds: the doubt
# owes to the unseen, and he goes to look at the never-seen square beside his
# room nearest him (hallsplit.h, CLOSED), sees the wall, and claims the corner,
# which the judge counts reached. Before CLOSED his four looks went along the way
# to the east room's far corner, square by square, and he doubted it (62 cycles).
table 101 57
wall 1 27 11 27 11 29 1 29
wall 18 27 63 27 63 29 18 29
wall 65 27 94 27 94 29 65 29
wall 98 27 100 27 100 29 98 29
wall 63 27 65 27 65 29 63 29
wall 63 1 65 1 65 6 63 6
wall 63 9 65 9 65 27 63 27
wall 63 29 65 29 65 48 63 48
wall 63 54 65 54 65 56 63 56
object square1 S 41.206 36.343 40.434 31.388 45.389 30.617 46.161 35.572
object square2 D 33.679 39.952 33.679 35.563 38.068 35.563 38.068 39.952
object brick I 39.933 13.653 35.886 13.653 35.886 11.574 39.933 11.574
object lshape O 19.794 52.638 13.221 52.638 13.221 49.703 16.535 49.703 16.535 47.481 19.794 47.481
object piece1 R 33.988 17.593 36.128 15.757 37.197 14.283 39.752 16.178 39.169 18.765 37.368 21.009 35.846 19.058
utak 7.5 30.5 north
