table 20 20
table 20 20
utak 5.5 5.5 north
