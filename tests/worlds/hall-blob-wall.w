# hall-blob-wall.w - hall-blob-square.w with the square a block of wall (colour B):
# the true parting wall (paper task (i); issue 13 items 3 and 6). The verdict's
# rooms count the block as wall, and with the pier it cuts the hall in two: the
# north-east corner Utak walks to lies in the other room. He goes and touches the
# blob (hallsplit.h), feels B, and the block is wall to his model from then on; by
# the verdict's rule restated on his model (carryroom_watershed) the floor he
# stands on is then beaten by floor of the room he started in, and he doubts the
# corner (an honest failure: his own room map, rooms.h, finds no door across the
# block's diagonal gap and still offers the far corner, so he does not go on).
table 40 70
wall 34 50 30 50 30 36 34 36
wall 20.88 37.012 16.259 38.832 14.44 34.211 19.06 32.392
utak 16.5 46.5 south
