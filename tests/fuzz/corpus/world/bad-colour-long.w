table 20 20
object a AC 4 4 8 4 8 8
utak 2.5 2.5 north
