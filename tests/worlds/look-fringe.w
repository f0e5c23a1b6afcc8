# look-fringe.w - a square beside the east verge, and above it, across a gap one
# square wide, a seven-cornered piece that reads a square from afar (tests/gen/
# worldgen.c, world 258 of the random set, cut down to these two and Utak moved
# nearer). Utak goes to look at the piece's squares the fovea has not seen from
# the floor nearest them: the cells nearest on its north and west sides are each
# read occupied from the way to the other (the piece's fringe seen only in 2 x 2
# cells, which fall on other squares as he moves), and on main 39a11ca he stepped
# to and fro in the gap until the cycles ran out. A goal whose square reads
# occupied on the way, never seen in the fovea, is not chosen again (controller.c,
# shun): he reaches the piece and doubts it, and says why.
table 32 50
object square1 M 25.298 13.681 29.991 13.681 29.991 18.375 25.298 18.375
object piece1 V 24.153 22.414 25.589 21.022 26.788 20.694 29.043 21.152 28.468 23.227 27.444 24.271 25.333 24.64
utak 20.5 40.5 north
