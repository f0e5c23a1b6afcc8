# fovea-look.w - a rival looked at where the fovea holds it (fovealook.h, rival.h):
# random world g100 of tests/rates.sh. "push square ne-corner": piece2, 7 wide with
# 8 corners, lies as near the start as the square (within what the squares seen
# tell), and is seen only in part; it may be the square. Before, Utak went to the
# place nearest its first square not seen in the fovea, 4 rows south of it (the
# fovea reaches 3 north), saw nothing more there ("nothing more to see or touch
# from here") and pushed the square with the doubt. Now he goes where the fovea
# holds that square and the most of the piece's others not yet seen, sees it whole,
# no square (the doubt is gone), and pushes and claims the square.
table 51 45
wall 41 8 43 8 43 14 41 14
wall 10 31 15 31 15 38 10 38
object square1 N 21.89 22.068 20.394 18.918 23.544 17.422 25.04 20.572
object brick X 13.762 29.79 5.649 27.941 6.415 24.583 14.527 26.432
object lshape M 34.124 10.303 26.47 8.337 26.941 6.504 30.911 7.523 31.496 5.247 35.18 6.193
object piece1 O 45.327 24.827 44.088 27.063 41.581 26.69 40.297 26.535 39.958 23.73 40.887 21.808 42.931 21.544 44.194 22.388
object piece2 I 24.832 29.622 22.766 32.856 20.904 32.638 18.088 30.901 18.459 26.967 21.526 24.832 23.713 25.203 26.182 27.944
object bit1 G 28.732 33.384 29.831 35.07 28.073 34.251
utak 2.5 17.5 east
