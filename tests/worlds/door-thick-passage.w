# door-thick-passage.w: a wall 3 thick down column 20, a door 6 wide near its
# north end (doorsure.h, the doorway; /tmp/s27/door27's grid,
# v20-t3-d6-x21-s1-north). Facing north, "go ne-corner": the passage through the
# door scores as well as the west room's corner, and the model's door line lay at
# its far end, so Utak's square in the passage was of his room on every reading.
# To the judge the doorway belongs to no room (doc/verdicts.md): after a look at
# the jambs he claimed it, a false success. A square in a door cell's doorway
# (the judge's rule restated, with a square of margin) is not claimed: golden
# door-thick-passage-ne, failed with his doubt, as before the look.
table 40 30
wall 20 1 23 1 23 21 20 21
wall 20 27 23 27 23 29 20 29
utak 8.5 24.5 north
