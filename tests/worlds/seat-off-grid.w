# seat-off-grid.w - a 4 x 4 square a fraction of a square off the grid (it covers 5 x 5
# squares): seated into the north-east corner, its pushes halt against the verge part
# of the way, and the held set must not take in the squares the model then misplaces
# (push.c, push_seat_finish: the set as carried to the corner is judged).
table 36 28
object square A 14.2 10.45 18.2 10.45 18.2 14.45 14.2 14.45
utak 8.5 6.5 north
