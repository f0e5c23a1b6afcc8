# a concave object, walls and a given verge outline
table 40 30
verge 1 1 39 1 39 29 20 29 20 20 1 20
wall 10 5 12 5 12 15 10 15
object ell D 20 4 26 4 26 6 22 6 22 12 20 12
object tri E 30.25 8.5 35.75 9.125 31.5 14.875
object u F 14 14 18 14 18 18 17 18 17 15 15 15 15 18 14 18
utak 5.5 5.5 west
