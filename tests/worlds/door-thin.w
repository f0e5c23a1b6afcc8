# door-thin.w: two rooms parted by a wall 1 thick with a door 6 wide (doorsure.h).
# Seen from afar, a 4 x 4 cell over the wall holds 4 of its 16 squares, level 2,
# and the world model reads all 16 as floor below half occupied: the two rooms
# were one, and "go nw-corner" (facing east: the TABLE's north-east, across the
# wall) walked through the door and claimed the far room's corner (a false
# success). Now such faint floor read as wall parts him from the start: he
# doubts.
table 40 30
wall 1 18 5 18 5 19 1 19
wall 11 18 39 18 39 19 11 19
utak 15.5 7.5 east
