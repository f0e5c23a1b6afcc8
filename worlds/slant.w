# slant.w - one room with a square, a brick, an L-shaped object and a triangle, each
# turned off the grid (20, 35, 115 and 250 degrees), for naming shapes at any angle
# (issue 13). Utak stands in the middle facing north.
table 44 34
object square A 7.66 22.12 11.88 23.66 10.34 27.88 6.12 26.34
object brick C 28.17 21.19 35.55 26.35 33.83 28.81 26.45 23.65
object lshape D 16.07 6.40 14.81 9.12 11.18 7.43 8.65 12.87 5.93 11.60 9.73 3.44
object triangle E 31.80 11.56 29.75 5.93 37.44 9.51
utak 22.5 17.5 north
