# room.w - one room with a square, a brick and an L-shaped object, after the
# paper's Figure 1. Utak stands near the middle facing north.
table 40 30
object square A 6 20 10 20 10 24 6 24
object brick C 24 19 33 19 33 22 24 22
object lshape D 8 4 11 4 11 8 17 8 17 11 8 11
utak 20.5 12.5 north
