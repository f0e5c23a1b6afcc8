# pocket-south.w - worlds/pocket.w with Utak facing south: the square in its pocket
# of the north wall lies behind him, and his frame is turned half round. Which
# corner he probes and from where he feels the square must not depend on that
# (paper 3.4.2; tug.h): before, he stood beside each corner on the pier's face,
# out of touch of the square, and ended "no square seen".
table 40 30
wall 13 21 16 21 16 29 13 29
wall 20 21 23 21 23 29 20 29
object square A 16 25 20 25 20 29 16 29
object brick C 27 8 35 8 35 11 27 11
utak 10.5 8.5 south
