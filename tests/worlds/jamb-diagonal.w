# jamb-diagonal.w - go next-room: the next room must not be claimed through a
# narrowing that a square makes with a pier (issue 13 items 3 and 6; paper 3.4.2).
# Cut down from random world g147 of tests/gen/worldgen.c (its L-shape and two
# pieces dropped, Utak two squares west). The north room holds a square 6 squares
# from the pier east of the door at x 67-71; seen from afar, coarse cells join it
# to the north wall, so the model shows a narrowing between it and the pier, a
# diagonal one: the run across it is a column through the real door, and neither
# of its ends is the square. On 81d6c20 Utak went east past the square and
# believed himself in the next room (a false success). Now the faces that set the
# narrowing's clearance are weighed as jambs too: he touches the square, feels N,
# and goes on to the true next room through the door.
table 126 42
wall 1 23 29 23 29 24 1 24
wall 33 23 67 23 67 24 33 24
wall 71 23 125 23 125 24 71 24
object square1 N 61.561 36.217 61.561 30.305 67.474 30.305 67.474 36.217
object piece3 R 63.163 12.451 59.977 14.693 57.253 13.365 58.381 10.596 62.07 10.553
object bit1 R 68.197 9.905 68.197 12.17 65.932 12.17 65.932 9.905
utak 22.5 30.5 south
