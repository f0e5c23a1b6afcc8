# boxed.w - the square is boxed in by walls on all sides: Utak can see it but
# never reach it. Tasks on the square must end in an honest failure.
table 40 30
wall 22 12 32 12 32 13 22 13
wall 22 21 32 21 32 22 22 22
wall 22 13 23 13 23 21 22 21
wall 31 13 32 13 32 21 31 21
object square A 25 15 29 15 29 19 25 19
utak 10.5 10.5 north
