# near-hidden.w - a square hidden nearer the start behind an obstacle (issue 13;
# objects.h, THE NEARER UNSEEN; goals.c, goals_frontier_within/goals_unseen_within):
# squareA 3 x 3 straight ahead, 14.0 from the start, in view from it; squareB 2.6 on
# a side, turned 0.4 radians, 10.0 to his left: the judge's square (the nearest),
# hidden from the start behind wallpiece, a 1 x 7 brick across the line of sight
# 6 from the start. Utak must not claim squareA while the space behind the brick,
# nearer the start than squareA, is unseen: he looks there, finds squareB and goes
# to it. An adversarial variant of /tmp/near13b/adv2 (h7), not made for any rule.
table 60 50
object squareA K 32.000 36.000 29.000 36.000 29.000 33.000 32.000 33.000
object squareB M 21.191 22.204 18.796 21.191 19.809 18.796 22.204 19.809
object wallpiece R 24.000 24.000 24.000 17.000 25.000 17.000 25.000 24.000
utak 30.5 20.5 north
