# push-slant-corner.w - a square (4 x 4) turned 33 degrees, to be pushed into the
# north-east corner of a 56 x 32 table, a brick (5 x 3) standing five squares off
# the east wall and six off the north one (paper task (v); issue 13, pushes that
# stop short: pushturn.h). A push never turns the object: seated against both
# walls at its slant, the square stayed 2 short (slack 1), and Utak said so. Now he
# draws it back out of the corner, turns it square to the walls (-33 degrees about
# his point) and pushes it in again: 0 short, claimed. From an adversarial set of
# slanted squares by corners, piers, pockets and bricks.
table 56 32
object brick C 46 23 51 23 51 26 46 26
object square A 29.521 6.866 32.884 9.032 30.719 12.395 27.356 10.229
utak 37.5 2.5 east
