# lean-door.w: two rooms 19 and 18 wide joined by a door 4 wide in a wall 2 thick:
# a true door by the judge's rule (roomlean.h's converse). "Go ne-corner": the east
# room's floor beats the west room's corner, so the claim rests on the door; its
# jamb within reach Utak touches first (6 cycles more), feels B, and claims. "Go
# next-room": he passes the door, touch finds no object at its jambs, and he claims.
table 40 20
wall 19 1 21 1 21 8 19 8
wall 19 12 21 12 21 19 19 19
utak 5.5 5.5 north
