# to-and-fro.w - Utak going to and fro between two goals, each chosen afresh from
# where the other leads him (paper 3.1 steps 12-13; issue 13: tasks on worlds
# nobody tuned for). Cut down from random g238 (tests/gen/worldgen.c): its two
# rooms, the square, the brick and the small bit F (about 1.1 x 0.7) kept, the
# other objects gone. Looking for the square Utak takes F, seen coarsely, for a
# hypothesis and goes to look at the squares of it the fovea has not seen; from
# beside one the other is the nearer, and the goals near each (about 3.6 apart)
# drew him back and forth with nothing new seen until the cycles ran out (450 in
# the golden; 1200 did not end it either). controller.c's round_trips gives the
# goal up as reached on the third visit to one square within 8 such moves, and he
# goes on to find the square (324 cycles: the golden task-to-and-fro-square).
table 92 47
wall 1 21 21 21 21 24 1 24
wall 23 21 91 21 91 24 23 24
object square1 C 28.604 34.497 31.993 34.497 31.993 37.886 28.604 37.886
object brick U 77.774 30.874 73.402 31.175 73.258 29.09 77.63 28.789
object bit3 F 68.06 16.176 69.208 16.176 69.208 16.919 68.06 16.919
utak 27.5 11.5 west
