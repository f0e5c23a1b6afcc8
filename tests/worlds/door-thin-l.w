# door-thin-l.w - task (ix) on a world written by hand: a wall 1 thick with a door
# 6 wide, an L of arms 8, 3 thick (7.8 wide at its narrowest): it must turn in the
# doorway. The model misplaced Utak by a square mid-turn, no carry was left from
# his grasp, and he let the L go straddling the doorway, where the model reads it
# as one with the wall; he then explored until the cycles ran out. Now he first
# tries to carry it back to open floor, and when the object let go is no longer
# told from the wall he says so (carrytask.c). Utak faces south.
table 80 50
wall 40 0 41 0 41 20 40 20
wall 40 26 41 26 41 50 40 50
object sq A 50 30 54 30 54 34 50 34
object L C 60 10 68 10 68 13 63 13 63 18 60 18
utak 70.5 40.5 south
