# door-look-drop.w: a wall 1 thick across at row 18, a door 4 wide at column 5
# (doorlook.h, SAFETY). Facing east, "go sw-corner" is the TABLE's north-west: Utak
# walks through the door, and his model, the wall seen from afar, loses most of it
# (doorsure.h, LIMITS). Only doorsure's jamb reading doubts there. A look set off
# on and dropped after two steps (the look's place out of reach on the next map)
# left him back at the same square with that reading sure: he claimed the far
# room's corner, a false success. A claim never rests on a look not reached: the
# look is set off on again while it can be reached, else he doubts (golden
# door-look-drop-sw: failed, with his doubt, as before the look).
table 40 30
wall 1 18 5 18 5 19 1 19
wall 9 18 39 18 39 19 9 19
utak 15.5 7.5 east
