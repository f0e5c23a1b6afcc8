# corridor-east.w - task (viii): an L-shaped corridor 12 wide, its bend to the
# north-east; the brick (14 x 3) is longer than the corridor is wide, so it must
# turn at the bend. Utak faces east along the first leg.
table 56 60
wall 1 1 42 1 42 4 1 4
wall 1 16 30 16 30 59 1 59
wall 42 1 55 1 55 59 42 59
object brick C 10 8 24 8 24 11 10 11
utak 5.5 9.5 east
