# round-wall.w - a square one square south of a wall that meets the verge: the
# loop's corner points north of it (CONTROLLER_ROUND_MARGIN outside its rectangle)
# fall on the wall, and must move to the nearest reachable squares on the same
# side of it (round.c, round_goal): in the gap between the square and the wall.
table 32 26
wall 18 14 31 14 31 16 18 16
object square A 25 9 29 9 29 13 25 13
object brick C 3 18 9 18 9 21 3 21
utak 8.5 6.5 north
