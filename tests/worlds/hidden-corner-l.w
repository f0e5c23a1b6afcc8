# hidden-corner-l.w - a larger table (60 x 40) with an L-shaped object in its
# north-east, its arms three squares off the north and east walls (paper tasks (i),
# (v); issue 13 item 6, an honest belief). Seen from Utak's start, the coarse cells
# over the three-square gaps join the L to both walls, and the space inside its
# bend and the true corner read as a pocket behind a door of their own. "go
# ne-corner": Utak stops short of the L, 11 short of the true corner; before
# roomdoubt_hidden he claimed it (a false success), then he doubted it; now he first
# looks at the coarse squares from nearby (hallsplit_hidden_look), sees the gaps,
# and goes on to the true corner. "push square
# ne-corner": the square cannot pass the gaps; he fails honestly, short (no change).
table 60 40
object lshape E 46 24 56 24 56 28 50 28 50 36 46 36
object square A 10 10 14 10 14 14 10 14
utak 30.5 16.5 north
