table 20 20
box 1 2 3
utak 5.5 5.5 north
