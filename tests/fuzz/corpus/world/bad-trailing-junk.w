table 20 20
utak 2.5 2.5 north east
