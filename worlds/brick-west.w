# brick-west.w - task (vii): brick-turn.w mirrored: Utak faces west, and the brick
# must turn a quarter to pass the door of 4.
table 50 30
wall 26 1 24 1 24 13 26 13
wall 26 17 24 17 24 29 26 29
object brick C 38 12 36 12 36 19 38 19
utak 41.5 15.5 west
