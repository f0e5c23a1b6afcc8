# near-merged-l.w - MERGED (objects.h): squareB, 2.6 turned 240 degrees, 6.5 from
# the start, lies beside a slanted bar (wallpiece, 5 x 0.8): the model holds one
# object of 27 squares that an L fits exactly, and an L is no convex polygon's
# squares. Before, Utak pushed squareA, 8 ahead, to the ne-corner and believed it
# done (the judge's square is squareB); now that L is his doubt.
table 60 50
object squareA K 32.000 30.000 29.000 30.000 29.000 27.000 32.000 27.000
object squareB M 25.562 18.954 23.167 17.941 24.180 15.546 26.574 16.559
object wallpiece R 25.786 20.665 28.286 16.335 28.979 16.735 26.479 21.065
utak 30.5 20.5 north
