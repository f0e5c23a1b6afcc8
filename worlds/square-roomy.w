# square-roomy.w - task (vi): two rooms joined by a roomy door (8 squares) in a wall
# 2 thick. Utak faces east, the door 16 squares ahead; the square (3 x 3) is off to
# his left, so he finds the door first, then fetches it.
table 50 30
wall 24 1 26 1 26 11 24 11
wall 24 19 26 19 26 29 24 29
object square A 10 6 13 6 13 9 10 9
utak 8.5 15.5 east
