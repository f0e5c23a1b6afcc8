# near-tie-far.w - near-tie.w's squares, squareB at 50 degrees to his right and 11.7
# from the start (objects.h, AS NEAR): squareB is seen only from afar, in cells of 4,
# and its squares' centroid lies 12.5 from the start, farther than squareA's 12.0,
# though its true centroid is 0.3 nearer. Before, he pushed squareA to the ne-corner
# and believed it done (the judge's square is squareB); now a square within the two
# centroids' slack of the claimed one is his doubt and he fails honestly.
table 60 50
object squareA K 32.000 34.000 29.000 34.000 29.000 31.000 32.000 31.000
object squareB M 40.320 29.647 37.837 28.878 38.605 26.395 41.089 27.163
utak 30.5 20.5 north
