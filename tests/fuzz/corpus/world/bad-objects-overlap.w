table 20 20
object a A 4 4 8 4 8 8 4 8
object b C 7.5 7.5 12 7.5 12 12
utak 2.5 2.5 north
