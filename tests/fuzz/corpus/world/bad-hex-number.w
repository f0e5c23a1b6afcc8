table 20 20
object a A 4 4 8 4 8 0x8
utak 2.5 2.5 north
