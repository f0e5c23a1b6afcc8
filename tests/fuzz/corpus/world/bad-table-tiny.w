table 2 2
utak 0.5 0.5 north
