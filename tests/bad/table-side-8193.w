# one square past the limit of 8192 a side
table 8193 3
utak 1.5 1.5 north
