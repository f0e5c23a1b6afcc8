# apart-noise-notch.w - room.w with a 4 x 4 square pressed into the L's crook (touching both
# arms): under --noise the pull of the L is made again (apart.h, apart_redo), and
# every try shows the square stay: the MERGED doubt stands (merge29, issue 13).
table 40 30
object square A 6 20 10 20 10 24 6 24
object brick C 24 19 33 19 33 22 24 22
object lshape D 8 4 11 4 11 8 17 8 17 11 8 11
object hidden M 11 4 15 4 15 8 11 8
utak 20.5 12.5 north
