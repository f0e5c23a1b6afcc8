# narrow-bit-under.w - a square under 2 wide nearer the start than the square
# (issue 13, items 1 and 6; probe.h, PROBE_MIN_SIDE). bit2 is a square 1.56 on a
# side turned 30 degrees: no square to the judge (under 2 wide), a crumb Utak
# cannot tell from a small square by sight, so it raised "what may be another
# square lies nearer the start" over square1, as worldgen's bits of 1.5 to 2 do in
# random worlds (g103, g138 and g193 of tests/rates.sh stop at one). Probed as a
# rival, no rectangle of a square's proportions and sides of 1.82 or more owns what
# the looks showed: it is no square, and Utak claims square1 without doubt.
table 24 24
object square1 M 15.298 13.681 19.991 13.681 19.991 18.375 15.298 18.375
object bit2 H 5.765 7.535 7.115 8.315 6.335 9.665 4.985 8.885
utak 5.5 2.5 north
