# lshape-north.w - task (ix): lshape-turn.w turned a quarter: Utak faces north.
table 40 54
wall 39 28 39 30 24 30 24 28
wall 17 28 17 30 1 30 1 28
object lshape L 28 12 28 21 25 21 25 15 19 15 19 12
utak 20.5 8.5 north
