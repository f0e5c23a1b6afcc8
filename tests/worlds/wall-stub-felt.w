# wall-stub-felt.w: a stub of wall (2 x 11) standing out of the south verge nearer
# the start than the square (wallbump.h). Its end has the corners a square pressed
# against the verge would have, 2 squares each way; before he claims the square,
# Utak goes beside the nearer corner and touch feels B there: wall, and the claim
# stands.
table 40 30
wall 20 1 22 1 22 12 20 12
object far C 30 20 34 20 34 24 30 24
utak 12.5 12.5 north
