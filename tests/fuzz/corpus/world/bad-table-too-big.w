table 9000 20
utak 5.5 5.5 north
