table 20 20
wall 1 1 5 5
utak 2.5 2.5 north
