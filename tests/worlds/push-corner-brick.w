# push-corner-brick.w - a brick pressed into the corner a square is to be pushed
# into (paper task (v); issue 13: an honest belief; hand-written world set 2 h111).
# Utak faces west, so his north-east corner is the TABLE's north-west, where br2
# (3 x 6) fills it. The eye reads the brick as part of the verge (paper 3.4.2), and
# the squares beside it seen only coarsely blur its corner, so no corner of the
# wall of wallbump.h's kind shows there: the square pushed against the brick stops
# 3 short of the judge's corner (an object's squares are the room's). Before
# pushseen_felt_object Utak claimed it (a false success); surveying the corner
# before the push, touch felt the brick's letter beyond where the square stops, and
# now he doubts it (exit 1).
table 40 30
object sq0 A 22 8 28 8 28 14 22 14
object tri1 C 30 13 37 13 30 19
object br2 D 1 23 4 23 4 29 1 29
utak 28.5 4.5 west
