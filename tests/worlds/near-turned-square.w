# near-turned-square.w - the judge's square, 2.4 on a side turned 30 degrees, nearer
# the start than a larger square that reads a square beyond doubt (issue 13, item 6;
# objects.h, NEARER THE START, ANOTHER NAME). The squares bit2 covers, the fit
# reads a brick (over 1.35 times as long as wide, the split between a square's 1.2 and a
# brick's 1.5): as worldgen's turned squares of 2.3 to 2.5 do. Some square of sides
# 1.82 or more owns exactly those squares (probe_square_consistent, no push), so
# it may be the square the task means: Utak probes square1 first, then bit2, which
# the probe cannot show to be no square, and the claim on square1 stays a doubt.
# Before, Utak passed it by and claimed square1, a false success.
table 18 20
object square1 M 11.5 11.5 15.5 11.5 15.5 15.5 11.5 15.5
object bit2 H 6.111 6.461 8.189 7.661 6.989 9.739 4.911 8.539
utak 5.5 2.5 north
