# push-blocked-triangle.w - a right triangle (legs 10) near the north-east corner,
# three squares off each wall, its long side toward the corner: a square (4 x 4)
# passes neither between it and the east wall nor between it and the north wall.
# Pressed against it, the square stops 14 short; Utak draws it off, lets go,
# pushes the triangle out of the way (south, off the square's way), fetches the
# square again and seats it in the corner (pushclear.h). Moved, the triangle
# lies nearer the start than the square does then: the doubt judged at the first
# grasp, with both where they began, stands (controller.c).
table 40 30
object triangle E 26 16 36 16 26 26
object square A 8 8 12 8 12 12 8 12
utak 20.5 12.5 north
