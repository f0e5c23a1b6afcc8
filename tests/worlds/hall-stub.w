# hall-stub.w - a hall 42 wide parted by a free-standing wall stub in its middle,
# 8 squares long and 2 thick, 14 squares from the west wall and 19 from the east
# (paper task (i); issue 13 items 3 and 6: rooms that are rooms, an honest belief).
# Cut down from a random world of tests/gen/worldgen.c (g191 of the rates' run):
# the stub made square to the walls, the hall shortened, the objects taken away.
# The verdict's rooms count the stub as wall: the hall narrows to 14 and 19
# between regions 42 wide, so it is two rooms. Utak, facing south at the north-east,
# walks to his north-east corner (the table's south-west) along the west wall and
# sees the stub only with the outer zones of the retina, as an object: space to his
# rooms, so his model holds one room. Before hallsplit.h he claimed the corner of
# the south room (a false success); then, the stub taken for wall parting his start
# from that corner, he doubted it; now he goes and touches the stub, feels B, and by
# the verdict's rule restated on his model (the stub wall) doubts the corner again,
# floor of his own half beating it: an honest failure (he does not yet go on).
table 43 110
wall 23 57 15 57 15 55 23 55
utak 38.5 92.5 south
