table 20.5 20
utak 5.5 5.5 north
