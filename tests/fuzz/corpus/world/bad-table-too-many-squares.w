table 8192 8192
utak 5.5 5.5 north
