# push-pressed-slant.w - a slanted square (worldgen 85) pushed into a corner from the
# wrong side: Utak ends in the corner square himself, the square beside him, and his
# last seating push halts 0.3 of a square on, pressed against the verge, while his
# point crosses a square's edge. Its held set must not take in a row of the verge
# (worldmodel.c, wm_register_held): the judge measures the square 2 short, and so
# must Utak (issue 13: it was read 1 short, a false success). Since pushturn.h
# Utak squares the square up to the walls before he judges it (it reads 33 degrees
# off the axes, as when grasped), lets go (turned, it would leave him between it
# and the west wall), fetches it again and seats it 1 short: achieved.
table 33 54
object square1 Y 3.86 31.575 6.369 28.296 9.647 30.805 7.138 34.084
object brick E 28.667 12.345 28.667 19.925 25.266 19.925 25.266 12.345
object bit1 G 23.943 44.325 22.182 43.974 22.337 43.199 24.098 43.55
object bit2 U 12.195 24.498 11.066 24.013 12.461 22.66
utak 29.5 45.5 south
