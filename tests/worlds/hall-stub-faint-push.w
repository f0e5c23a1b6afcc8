# hall-stub-faint-push.w - a hall 44 wide parted by two free-standing wall stubs,
# each 1 thick, offset by 5 squares (paper task (v); issue 13: rooms that are
# rooms, an honest belief). Made by the hall-stub variant generator of the
# adversarial runs (/tmp/c11adv/gen.py, variant 27), kept as it came.
# The verdict's rooms count the stubs as wall: the hall narrows between them and
# the verge to about 6 and 10 between regions over 40 wide, so it is two rooms,
# and the square stands in the north one. Utak, facing north in the south room,
# finds the square, pushes it to the north-east corner of the hall and claimed it
# (a false success: the judge finds the square not in his starting room). The
# eye's 4 x 4 and 2 x 2 cells read the stubs, straddled, as floor but not empty
# ("faint" squares, hallsplit.h FAINT); task (i) asked them since stub13, task
# (v) now too (push.c held_room_split: hallsplit_faint_parts_all): a set of faint
# squares, taken for wall, parts his start from the held squares that reach the
# corner, so he doubts the corner: an honest failure.
table 46 115
wall 20 72 7 72 7 71 20 71
wall 35 67 25 67 25 66 35 66
object square1 Y 3 83 8 83 8 88 3 88
utak 15.5 14.5 north
