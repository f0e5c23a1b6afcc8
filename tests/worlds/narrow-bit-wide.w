# narrow-bit-wide.w - a square a little over 2 wide whose squares, standing still,
# may be those of a polygon under 2 wide, and a larger square farther on (issue 13,
# items 1 and 6; probe.h, probe_least_width). bit2 is a square 2.3 on a side turned
# 15 degrees, the judge's square (nearest the start); it covers 10 squares whose
# centres spread too little to rule out a polygon under 2 wide (from 1.00), as
# worldgen's bits of 2 to 2.5 do in random worlds g18, g43, g93 and g223 of
# tests/rates.sh. Probed (grasped, pushed a quarter square to three corners,
# looked at), it is shown 2 wide or more, and claimed without that doubt.
table 24 24
object square1 M 15.298 13.681 19.991 13.681 19.991 18.375 15.298 18.375
object bit2 H 5.737 7.192 7.958 7.787 7.363 10.008 5.142 9.413
utak 5.5 2.5 north
