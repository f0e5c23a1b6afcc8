# carry-wall-corner.w - task (vi) on a world written by hand (carry26): a wall 2
# thick with two doors, near each end; the square 5 wide in the west room, and the
# wall's end beside the south door nearer Utak's start than the square. Beside the
# square, Utak doubts the corner of that wall's end: it may be another square
# pressed against the wall, nearer the start, the task's square then (wallbump.h).
# He set off to feel it (controller.c), but the carry's goal (the grasp) came first
# and sent him back where he stood, again and again: "no progress". Now the carry's
# goal is that corner first (carrytask.c, as goals.c's for any push): he feels it,
# B, and carries the square through. Utak faces north.
table 52 36
wall 24 1 26 1 26 3 24 3
wall 24 9 26 9 26 26 24 26
wall 24 32 26 32 26 35 24 35
object sq A 10 15 15 15 15 20 10 20
utak 15.5 5.5 north
