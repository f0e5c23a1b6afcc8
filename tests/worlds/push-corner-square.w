# push-corner-square.w - a large square pressed into the corner a smaller one is to
# be pushed into (paper task (v); issue 13: an honest belief; hand-written world
# set 3 h231). Utak faces south, so his south-west corner is the TABLE's
# north-east, where sq0 (7 x 7) fills it; the judge's square is sq3 (4 x 4), nearer
# the start. The eye reads sq0 as part of the verge (paper 3.4.2), its edge seen
# only coarsely, so no corner of the wall of wallbump.h's kind shows there: sq3
# pushed against it stops 7 short of the judge's corner (an object's squares are
# the room's). Before pushseen_felt_object Utak claimed it (a false success);
# surveying the corner before the push, touch felt sq0's letter beyond where sq3
# stops, and now he doubts it (exit 1).
table 30 20
object sq0 A 22 12 29 12 29 19 22 19
object br1 C 1 16 7 16 7 19 1 19
object br2 D 23 2 29 2 29 5 23 5
object sq3 E 12 10 16 10 16 14 12 14
utak 18.5 12.5 south
