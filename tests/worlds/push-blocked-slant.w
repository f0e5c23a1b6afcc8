# push-blocked-slant.w - push-blocked-corner.w with the brick turned 15 degrees
# (about 7 x 3): the same clearing on a slanted object in the way (pushclear.h).
table 40 30
object square A 8 8 12 8 12 12 8 12
object brick C 29.5 21.2 36.3 23.0 35.5 25.9 28.7 24.1
utak 20.5 12.5 north
