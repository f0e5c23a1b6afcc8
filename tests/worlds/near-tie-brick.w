# near-tie-brick.w - near-tie.w's squares, squareB at 90 degrees to his right, 11.4
# from the start (objects.h, ANOTHER NAME): squareB, 2.6 turned 0.3 radians, is seen
# in the fovea but not the floor round it, read a brick, and never asked whether a
# square owns its squares (that is asked only of a brick seen whole). Before, he
# pushed squareA to the ne-corner and believed it done (the judge's square is
# squareB); now such a brick nearer the start is his doubt and he fails honestly.
table 60 50
object squareA K 32.000 34.000 29.000 34.000 29.000 31.000 32.000 31.000
object squareB M 42.758 22.126 40.274 21.358 41.042 18.874 43.526 19.642
utak 30.5 20.5 north
