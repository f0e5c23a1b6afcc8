# hidden-corner-block.w - the control for hidden-corner.w: a wall block (9 x 9) fills
# the north-east of the table, so no space beyond it can beat the corners it leaves
# (paper task (v); issue 13 item 6). The checks of roomdoubt_hidden find no floor
# seen of another room that coarse cells might join to Utak's. The square is seated
# 0 short; but the block's corner facing the room is one an object pressed into the
# corner would have (wallbump.h, wallbump_in_corner), never felt, and Utak, behind
# the square, cannot feel it: he doubts the corner (an object block there would
# leave the judge's corner 9 further on: tests/worlds/corner-object.w).
table 40 30
wall 30 20 39 20 39 29 30 29
object square A 8 8 12 8 12 12 8 12
utak 20.5 12.5 north
