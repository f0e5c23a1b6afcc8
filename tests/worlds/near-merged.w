# near-merged.w - MERGED (objects.h): squareB, 2.6 turned 22 degrees, 6 behind the
# start, lies 0.8 from a bar (wallpiece, 7 x 1): the squares between them are owned
# by both, and the model holds one object of 24 squares that reads no shape.
# squareA, 8 ahead, is a square beyond doubt. Before, Utak touched squareA and
# believed it done (the judge's square is squareB, nearer the start); now an object
# nearer the start whose squares are no convex polygon's and hold a 2 x 2 block
# where a square's centroid may lie nearer is his doubt, and he fails honestly.
table 60 50
object squareA K 32.000 30.000 29.000 30.000 29.000 27.000 32.000 27.000
object squareB M 31.191 16.204 28.796 15.191 29.809 12.796 32.204 13.809
object wallpiece R 27.000 17.000 34.000 17.000 34.000 18.000 27.000 18.000
utak 30.5 20.5 north
