# one character past the limit of 31 in a name
table 20 20
object nnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnn A 4 4 8 4 8 8
utak 2.5 2.5 north
