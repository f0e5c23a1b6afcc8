# square-behind.w - task (vi): the door (5 wide) is behind Utak: he faces south and
# the wall is to his north, out of his first field of view; the square (3 x 3) lies
# ahead of him. He must look round before he knows where to push it.
table 40 44
wall 1 20 15 20 15 22 1 22
wall 20 20 39 20 39 22 20 22
object square A 24 8 27 8 27 11 24 11
utak 20.5 12.5 south
