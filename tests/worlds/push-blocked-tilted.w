# push-blocked-tilted.w - a triangle turned about 20 degrees near the north-east
# corner, its lower tip 3 squares off the east wall. The square, pushed up the east
# wall, is stopped by it, 12 short. Seen from afar, the squares between the tip and
# the wall read occupied: the model joins the triangle to the wall, and only a few
# squares of its edge stand apart, too few to grasp (PUSHCLEAR_LEAST). Utak cannot
# tell it is an object he could move, begins no clearing, and fails honestly, as
# before (pushclear.h).
table 40 30
object triangle E 36.2 15.5 33.1 25.6 26.0 19.0
object square A 8 8 12 8 12 12 8 12
utak 20.5 12.5 north
