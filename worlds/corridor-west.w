# corridor-west.w - task (viii): corridor-east.w mirrored: Utak faces west, and the
# bend turns north.
table 56 60
wall 55 1 14 1 14 4 55 4
wall 55 16 26 16 26 59 55 59
wall 14 1 1 1 1 59 14 59
object brick C 46 8 32 8 32 11 46 11
utak 50.5 9.5 west
