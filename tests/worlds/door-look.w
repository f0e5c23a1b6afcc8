# door-look.w: two rooms parted by a wall 2 thick running north-south, a door 3
# wide in it (doorlook.h). From the start the door's jambs are seen only
# coarsely: on one reading of doorsure.h they may lie a coarse cell back, the door
# be no door, and the far room's better floor be of his room, so Utak doubted the
# corner he had reached ("go nw-corner", facing east: the TABLE's north-west of
# the west room; achieved, 4 cycles, with his doubt). Now he first goes and looks
# at the jambs from nearby, comes back, and claims it (golden door-look-nw).
table 40 30
wall 20 1 22 1 22 12 20 12
wall 20 15 22 15 22 29 20 29
utak 5.5 15.5 east
