table 20 20
utak 25 5.5 north
