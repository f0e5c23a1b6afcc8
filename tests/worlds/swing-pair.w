# swing-pair.w - SWING (swing.h): two squares 3 x 3 pressed into the squares of a
# brick 6 x 3, on open floor. "go brick": the turn leaves the square not held where
# it was, and the model parts them: he finds no brick, and there is none (the judge).
table 40 30
object s1 C 15 12 18 12 18 15 15 15
object s2 D 18 12 21 12 21 15 18 15
utak 17.5 25.5 north
