table 20 20
verge 1 1 19 19 19 1 1 19
utak 2.5 2.5 north
