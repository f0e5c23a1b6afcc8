table 0 20
utak 5.5 5.5 north
