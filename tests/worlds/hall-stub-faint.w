# hall-stub-faint.w - a hall 42 wide parted, nearly, by two free-standing wall stubs
# 3 thick, overlapping by one square and offset by 2 (paper task (i); issue 13 items
# 3 and 6: rooms that are rooms, an honest belief). Made by the hall-stub variant
# generator of stub13's adversarial runs (variant 103), kept as it came.
# The verdict's rooms count the stubs as wall: the hall narrows to 10 and 11
# between regions 41 wide, so it is two rooms. Utak, facing south on the stubs'
# north side, walks to his north-east corner (the table's south-west) past their
# east end; the eye's 4 x 4 and 2 x 2 cells read the stubs, straddled, as floor,
# but not as empty (a cell not zero: "faint" squares, hallsplit.h FAINT). Before
# FAINT he claimed the corner of the south room (a false success). Now a set of
# faint squares, taken for wall, parts his start from the corner by the verdict's
# rule restated on his model, so he goes to look at its nearest square in the
# fovea; 4 looks (HALL_FAINT_LOOKS) each show a part of it and leave faint squares
# beyond, and he fails with the doubt: an honest failure.
table 43 117
wall 22 65 11 65 11 62 22 62
wall 31 63 21 63 21 60 31 60
object square1 Y 13 91 18 91 18 96 13 96
utak 37.5 66.5 south
