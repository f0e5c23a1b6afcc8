# lshape-turn.w - task (ix): an L-shape (arms 9 and 9, 3 thick: 8.5 wide at its
# narrowest) and a door of 7 in a wall 2 thick: it must turn in the doorway
# (paper 5's open problem). Utak faces east.
table 54 40
wall 28 1 30 1 30 16 28 16
wall 28 23 30 23 30 39 28 39
object lshape L 12 12 21 12 21 15 15 15 15 21 12 21
utak 8.5 19.5 east
