# rooms-in-a-row.w - task (vi) on a world written by hand: three spaces in a row,
# joined by gaps 9 wide (one at the top of the first wall, one at the foot of the
# second), the spaces 19, 18 and 17 wide. To the judge (doc/verdicts.md: a door
# only where both sides widen to twice it and 2 squares more) it is ONE room: the
# middle space is 18 wide, short of twice a gap of 9. Utak read the top gap a
# square narrower (its far wall seen from afar a square off) and believed the
# square pushed through it in the next room: a false success. A door of the goal
# must now be one were a wall of it a square off (carrytask_door_sure): he finds
# none, and says so. Utak faces north.
table 60 40
wall 20 0 22 0 22 30 20 30
wall 40 10 42 10 42 40 40 40
object sq A 45 20 49 20 49 24 45 24
utak 10.5 10.5 north
