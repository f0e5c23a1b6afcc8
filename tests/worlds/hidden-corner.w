# hidden-corner.w - a triangle filling the north-east of the table, two squares
# off the east wall at its foot and under the north wall at its tip (paper task (v);
# issue 13 item 6, an honest belief). Seen from afar, the coarse cells between its
# foot and the east wall read occupied: the model joins the triangle to the wall,
# and the space between its long side and the corner reads as a pocket behind a
# door of its own (the two-square gap over the tip). The square, pushed up against
# the north wall beside the tip, is a square short of the best floor of Utak's room
# as his model draws it, 12 short of the room's true corner. Before roomdoubt_hidden
# Utak claimed it (a false success); now he doubts it: that floor may be of his
# room, joined to it by the squares seen only coarsely. "go ne-corner" (task (i))
# likewise: he stopped beside the tip, 11 short, and doubted it; now, free to walk,
# he first looks at those squares from nearby (hallsplit_hidden_look), sees the
# gap between the triangle's foot and the wall, and goes on to the true corner.
table 40 30
object triangle E 27 17 36.5 17 27 26.5
object square A 8 8 12 8 12 12 8 12
utak 20.5 12.5 north
