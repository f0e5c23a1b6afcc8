# flush-corner.w: a square (7 x 7) pressed into the south-west corner of the
# table, nearer the start than another (7 x 7) in open floor (wallbump.h; from a
# hand-written world). The eye reads it as part of the verge it leans on: before,
# Utak touched the far square and claimed it, a false success. Now he goes beside
# the corner it makes, touch feels its letter, and he doubts the claim.
table 60 40
wall 1 14 47 14 47 16 1 16
wall 53 14 59 14 59 16 53 16
object sq0 A 52 32 59 32 59 39 52 39
object sq1 C 1 1 8 1 8 8 1 8
object br2 D 10 1 16 1 16 4 10 4
utak 32.5 8.5 south
