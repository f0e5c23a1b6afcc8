# pen.w - three rooms in a row, joined by doors; Utak faces west in the middle
# room, with the brick and an L-shaped object.
table 78 30
wall 25 1 27 1 27 11 25 11
wall 25 17 27 17 27 29 25 29
wall 51 1 53 1 53 18 51 18
wall 51 23 53 23 53 29 51 29
object brick C 34 5 42 5 42 8 34 8
object lshape D 38 18 41 18 41 21 46 21 46 24 38 24
utak 40.5 13.5 west
