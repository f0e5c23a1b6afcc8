# lshape-roomy-north.w - task (ix): lshape-roomy.w with x and y exchanged: Utak
# faces north.
table 40 54
wall 1 28 1 30 16 30 16 28
wall 26 28 26 30 39 30 39 28
object lshape L 12 12 12 20 15 20 15 15 22 15 22 12
utak 19.5 8.5 north
