# door-end-verge.w - task (vii) on a world written by hand (carry26): a wall 3 thick
# with its door 5 wide at its north end, against the verge. The judge floods by
# clearance, ties in the TABLE's order of squares: its door square falls just past
# the wall's east face, and the doorway round it runs along the verge 6 squares
# into the east room. Utak restated the rule in his own frame, on a model that saw
# the far room in part: the brick pushed 4 squares past the face was claimed, a
# false success. Now a cell is past the door line only if it is in every frame the
# TABLE may have, and beyond every cell along a face that a door square may move
# to (carryframe.h). Utak faces north.
table 52 36
wall 26 1 29 1 29 30 26 30
object brick C 8 8 16 8 16 11 8 11
utak 18.5 18.5 north
