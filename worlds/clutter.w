# clutter.w - a room cluttered with small objects; the square is among them, the
# only square: the clutter is bricks and triangles, so "the square" names one object.
table 48 40
object a1 C 8 8 11 8 11 10 8 10
object a2 D 15 12 17 12 17 16 15 16
object a3 E 22 6 25 6 23.5 9
object a4 F 30 10 34 10 34 12 30 12
object a5 C 9 20 13 20 13 22 9 22
object a6 D 20 18 22 18 22 22 20 22
object a7 G 28 22 30 22 30 27 28 27
object a8 E 36 18 40 18 38 21
object a9 F 14 28 18 28 18 30 14 30
object a10 C 24 30 28 30 28 32 24 32
object square A 34 30 38 30 38 34 34 34
utak 6.5 4.5 north
