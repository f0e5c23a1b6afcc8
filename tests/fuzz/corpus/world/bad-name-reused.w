table 20 20
object a A 4 4 8 4 8 8
object a C 10 10 14 10 14 14
utak 2.5 2.5 north
