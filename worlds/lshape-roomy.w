# lshape-roomy.w - task (ix): an L-shape (arms 8 and 10, 3 thick) and a roomy door
# (10). Utak faces east.
table 54 40
wall 28 1 30 1 30 16 28 16
wall 28 26 30 26 30 39 28 39
object lshape L 12 12 20 12 20 15 15 15 15 22 12 22
utak 8.5 19.5 east
