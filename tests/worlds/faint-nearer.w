# faint-nearer.w - the nearest square seen only faint (faint.h, FAINT): a square
# 3 wide south-west of Utak lies across four of the eye's cells of 4 (1, 2, 2 and
# 4 of its squares to a cell: levels 0, 1, 1 and 2, each below half), so the world
# model believes all their squares floor; a square 4 wide, farther north-east,
# reads clearly. The judge's square is the nearer, 12.7 from the start against
# 16.3. Before faint.h Utak went to the farther one and believed it the nearest.
table 60 60
object near A 20 20 23 20 23 23 20 23
object far A 40 40 44 40 44 44 40 44
utak 30.5 30.5 north
