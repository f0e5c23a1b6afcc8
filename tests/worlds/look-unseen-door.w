# look-unseen-door.w - a wall from the east verge across a large table, seen from its
# east end only, the lshape beside Utak's start (paper task (i); 3.3 and 3.4.2:
# where the model cannot tell, Utak goes and looks; issue 13 item 6). Cut down from
# random g16 of the rates (tests/gen/worldgen.c): its other walls and objects taken
# away, keeping what shows the case. The lshape, were it wall, might part his hall
# from the corner: he touches it (hallsplit.h, SETTLING), and then, by the verdict's
# watershed restated on his model, floor seen beyond the wall beats his corner and
# is of his room only through the squares west of him he has never seen in the
# fovea (the watershed takes them for space). Before hallsplit.h's LOOKING he
# ended there with that doubt, 60 short of the true corner (the wall is a stub: the
# judge counts one room); now he looks along the way that joins the two, sees the
# floor past the wall's end, and goes on to the true corner, claimed.
table 118 120
wall 91 59 117 59 117 61 91 61
object lshape N 100.334 24.959 105.944 24.172 106.349 27.058 103.309 27.484 103.639 29.836 101.068 30.197
utak 98.5 18.5 north
