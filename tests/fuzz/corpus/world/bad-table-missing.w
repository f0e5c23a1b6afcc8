utak 5.5 5.5 north
