# push-slant-verge.w - a square of side 7.6 turned 22 degrees, to be pushed into the
# north-east corner (paper task (v); issue 13 item 6, an honest belief); from
# /tmp/held14/adv/h38.w (held14's adversarial set). Pressed into the corner, its
# pushes halt ("blocked by the verge"), but the verge beside and beyond a slanted
# object is seen mostly in coarse cells half on it (never surely enough for
# worldmodel.c's wm_solid_tie), and the impression showed each halt better than a
# square gained by less than the disparity's margin: two halted pushes were read
# as squares gained and Utak claimed the corner the judge measures 2 short (a
# false success). Now a push that would carry the object into squares the model
# believes occupied has no margin to stand on (wm_pressed): the halts are found
# (cycles 42-44 and 46-48, "position corrected"), and Utak doubts the corner: the
# squares nearest it are seen only in part or coarsely (an honest failure).
table 56 26
object square A 13.932 7.481 21.013 10.377 18.117 17.457 11.037 14.562
utak 23.5 2.5 north
