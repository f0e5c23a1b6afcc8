table 20 20
wall 10 1 11 1 11 19 10 19
object a A 8 4 10.5 4 10.5 8
utak 2.5 2.5 north
