# door-knife.w: two rooms and a door 5 wide in a wall 3 thick (doorsure.h). The
# judge counts no door here (the far room, 8 rows, does not widen to twice the
# door's clearance), so the north-east corner is the far room's. From the start
# the door's jambs are seen only coarsely and read 2 squares too close: Utak's
# model had a door, and he claimed the near room's corner, 11 short (a false
# success). Now a reading with the coarse jambs set back opens the door, and the
# far room's better floor is of his room on it: he doubts the corner, 11 short
# (golden door-knife-ne). "go nw-corner" the same (door-knife-nw).
table 40 30
wall 1 18 15 18 15 21 1 21
wall 20 18 39 18 39 21 20 21
utak 15.5 7.5 north
