table 20 20
utak 0.5 5.5 north
