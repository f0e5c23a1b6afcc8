# door-thin-lost.w: a wall 1 thick across at row 10, a door 3 wide at column 15
# (thinwall.h; /tmp/s27/door27's grid, h10-t1-d3-x15-s0-east). Facing east,
# "go nw-corner" is the TABLE's north-east of the south room. The wall beside
# the door, seen in the fovea, was an object to the model: its two ends, seen
# only from afar in 4 x 4 cells (4 of their 16 squares), were faint floor, and
# the screen counts objects as space to the rooms, so the door was a gap 12
# squares wide. Utak walked through it into the north room's corner and claimed
# it (a false success, 7 cycles). Now doorsure's readings that take faint floor
# for wall take that object for wall too (thinwall.h), and doubt that corner; the
# looks that follow (doorlook.h's, then hallsplit.h's trip to the object) show
# the wall, and he goes to the south room's corner, reached in 81 cycles, where
# one reading still doubts it (golden door-thin-lost-nw: achieved, his doubt).
table 40 30
wall 1 10 15 10 15 11 1 11
wall 18 10 39 10 39 11 18 11
utak 15.5 7.5 east
