table 20 20
object a A 4 4 8 4 8 8 4 8
utak 5.5 5.5 north
