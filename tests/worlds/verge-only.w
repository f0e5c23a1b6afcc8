# verge-only.w - an L-shaped verge outline, Utak facing south, no objects.
table 30 30
verge 1 1 29 1 29 12 12 12 12 29 1 29
utak 5.5 20.5 south
