# push-corner-triangle.w - a triangle pressed into the corner a square is to be
# pushed into (paper task (v); issue 13: an honest belief; hand-written world set 2
# h107). Utak faces south, so his north-east corner is the TABLE's south-west,
# where tri1 lies with its slanted face toward the room. The eye reads the triangle
# as part of the verge it leans on (paper 3.4.2): its staircase of partly occupied
# squares is the wall to the model, whose best floor is beside it, and the square
# pushed against the slanted face stops 5 short of the judge's corner (which counts
# an object's squares as the room's). No corner of the wall of wallbump.h's kind
# shows there (the steps are one square). Before pushseen_felt_object Utak claimed
# it (a false success); surveying the corner before the push, touch felt the
# triangle's letter beyond where the square stops, and now he doubts it (exit 1).
table 40 30
object sq0 A 10 11 16 11 16 17 10 17
object tri1 C 1 1 6 1 1 6
object br2 D 33 14 39 14 39 17 33 17
object sq3 E 33 23 39 23 39 29 33 29
utak 20.5 27.5 south
