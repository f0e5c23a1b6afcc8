# push-notch-corner.w - a square to be pushed into a north-east corner notched by a
# bay 2 squares deep (paper task (v); issue 13 item 6, an honest belief). The bay
# holds the room's best corner square (28, 22), and the square, 6.97 across, cannot
# enter it: pressed against the east wall below the bay and the north wall, its
# best square (26, 22) is 2 short (the judge: failed). Its y offset (.872) leaves
# it covering 8 rows until the last push presses it flush against the north wall,
# halting after 0.15 of a square; its trailing row is then floor, and a held set
# shifted a row north, into the wall (occupied either way), fits the impression
# as well: Utak read it 1 short and claimed a false success. The held set is no
# longer registered onto squares his model surely believes occupied
# (heldobject.c, wm_register_held); the trailing row is pruned, and he says the
# square can be pushed no nearer than 2 short.
table 30 24
verge 1 1 27 1 27 21 29 21 29 23 1 23
object square1 W 19.973 10.872 19.973 16.845 13.0 16.845 13.0 10.872
utak 12.5 13.5 north
