# bare.w - a TABLE with nothing on it but Utak: no objects, no walls (issue 14:
# a world without objects once made the sanitizer build abort).
table 24 18
utak 12.5 9.5 north
