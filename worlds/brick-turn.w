# brick-turn.w - task (vii): a brick 7 long lies across the way to a door only 4
# wide: it must turn a quarter before it can pass. Utak faces east.
table 50 30
wall 24 1 26 1 26 13 24 13
wall 24 17 26 17 26 29 24 29
object brick C 12 12 14 12 14 19 12 19
utak 8.5 15.5 east
