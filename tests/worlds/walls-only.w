# walls-only.w - two rooms and a door, and no object to go to or push.
table 40 24
wall 19 1 21 1 21 9 19 9
wall 19 14 21 14 21 23 19 23
utak 8.5 6.5 east
