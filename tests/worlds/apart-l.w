# apart-l.w - MERGED settled by motion (apart.h): perturbed room.w (variant 2 of
# tests/rates.sh). The L (lshape, 42 squares) lies nearer the start than the square;
# its squares are no convex polygon's and hold a 2 x 2 block where a square's
# centroid could lie nearer than the square's, so the model cannot say it is not a
# square merged with a neighbour. Before, Utak touched the square and doubted it
# for that L; now he goes to the L, draws it back two squares twice, sees it come
# away whole, leaving floor behind (one object: no square), pushes it back, and
# claims the square.
table 40 30
object square A 7.714 19.742 11.714 19.742 11.714 23.742 7.714 23.742
object brick C 25.76 17.97 34.76 17.97 34.76 20.97 25.76 20.97
object lshape D 8.151 4.773 11.151 4.773 11.151 8.773 17.151 8.773 17.151 11.773 8.151 11.773
utak 20.5 12.5 east
