# rival-brick.w - a brick 4 x 2 nearer the start than the square, its edges 0.4
# into their squares (as clutter.w's bricks lie moved by fractions, perturbed
# clutter-p1 and -p2). Read from its squares standing still it may be a square
# (a 3.1 x 2.9 one owns the same 5 x 3 squares), so Utak's claim on the farther
# square is in doubt (rival.h). Pushed a quarter square either way no edge of it
# crosses a square's edge: the probe shows no change, nothing to judge. Going
# round the square, Utak probes it again by half a square (rival.h, HALF A
# SQUARE), which carries its edges across: its squares fit no square, and the
# claim stands with no doubt left. The judge's square is the farther object.
table 30 24
object brick C 8.4 10.4 12.4 10.4 12.4 12.4 8.4 12.4
object square A 20.3 14.6 23.3 14.6 23.3 17.6 20.3 17.6
utak 5.5 5.5 north
