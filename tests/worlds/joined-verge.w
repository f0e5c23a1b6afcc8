# joined-verge.w - a square joined to the verge by the eye's coarse cells
# (coarsewall.h): a square 3.9 wide, turned 41 degrees, lies 2.3 squares off the face of
# the west verge, 16.1 from Utak's start; another, 3.6 wide, lies in open
# floor 26.5 from it.
# Seen only in cells of 4 x 4, the cells over the gap read at least half full, and
# the world model holds the near square as a bump of the verge, not an object.
# Before coarsewall.h Utak went to the far square and claimed it as the nearest
# (a false success: big14's joined.py, seed 2, world 6); now the bump, jutting
# out further than a face seen coarsely can, is looked at from close by first,
# the fovea shows the gap, and he claims the near square.
table 60 40
object near A 5.86 25.37 8.82 27.96 6.23 30.92 3.27 28.34
object far A 46.89 9.87 47.25 13.43 43.69 13.79 43.34 10.23
utak 21.5 23.5 south
