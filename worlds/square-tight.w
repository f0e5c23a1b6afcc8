# square-tight.w - task (vi): a square of side 4 and a door of 5: little to spare.
# Utak faces west, toward the door.
table 44 36
wall 20 1 22 1 22 14 20 14
wall 20 19 22 19 22 35 20 35
object square A 30 10 34 10 34 14 30 14
utak 36.5 20.5 west
