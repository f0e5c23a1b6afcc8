# push-blocked-corner.w - a square to be pushed into the north-east corner, and a
# brick (7 x 4) standing in that corner, two squares off each wall (paper task
# (v); issue 13: an object in the way is moved out of it, pushclear.h). The square
# (4 x 4) pressed against the east wall stops under the brick, 8 short. Utak draws
# it off, lets go, pushes the brick out of the way (west, off the square's way up
# the east wall), fetches the square again and seats it in the corner.
table 40 30
object square A 8 8 12 8 12 12 8 12
object brick C 29 22 36 22 36 26 29 26
utak 20.5 12.5 north
