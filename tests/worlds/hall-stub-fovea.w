# hall-stub-fovea.w - a hall 42 wide parted by a free-standing wall stub, 6 squares
# long and 2 thick, 17 squares from the west wall and 18 from the east, that Utak
# sees in the fovea before he reaches the corner (paper task (i), 3.4.2: the eye
# cannot tell a wall from an object; issue 13 items 3 and 6). Derived from
# hall-stub.w (its stub shortened and moved east), as were the made-up variants
# where the false success showed: with the stub seen closely, no coarse blob raised
# hallsplit.h's doubt, and Utak took it for the object it looks like and claimed
# the corner of the other half. Now an object not felt that, taken for wall, would
# part his start from the corner is gone to and touched whether the fovea saw it or
# not; touch feels B, and by the verdict's rule restated on his model (the stub
# wall) he doubts the corner, floor of his own half beating it: an honest failure.
table 43 110
wall 24 57 18 57 18 55 24 55
utak 38.5 92.5 south
