# near-tie.w - two true squares at nearly the same distance from the start (issue 13
# item 6; objects.h, NEARER THE START): squareA 3 x 3 straight ahead, 12.0 from the
# start; squareB 2.6 on a side, turned 0.3 radians, at 110 degrees to his right and
# 11.4 from it: the judge's square. Utak chooses squareA first and keeps it (a goal
# changes only for one OBJECTS_SWITCH nearer); squareB, seen whole later and read a
# square beyond doubt, lies nearer by less. Before, he touched squareA and believed
# the task done (a false success); now the nearer square is his doubt and he fails
# honestly.
table 60 50
object squareA K 32.000 34.000 29.000 34.000 29.000 31.000 32.000 31.000
object squareB M 42.070 18.227 39.586 17.459 40.355 14.975 42.839 15.743
utak 30.5 20.5 north
