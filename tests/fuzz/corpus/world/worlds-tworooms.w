# tworooms.w - two rooms joined by a door four squares wide in the wall between
# them. Utak starts in the west room facing east; a slanted triangle is in the east.
table 60 30
wall 29 1 31 1 31 13 29 13
wall 29 17 31 17 31 29 29 29
object square A 10 18 14 18 14 22 10 22
object brick C 40 5 48 5 48 8 40 8
object triangle E 44.5 18.2 52.3 20.1 46.1 25.7
utak 15.5 10.5 east
