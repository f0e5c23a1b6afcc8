# turned-square-push.w: a square 8 wide turned 45 degrees, pressed against the
# west wall, then turned square and pushed into the corner (pushseen.c). After
# the turn the model's held set reached two squares farther than the object,
# into squares the eye saw only in 4 x 4 cells; the best floor it knew was then
# no better than those held squares. Before, Utak claimed "push square
# se-corner" 2 short (a false success); now the held squares that reach
# farthest must be ones the eye establishes, and he doubts.
table 64 48
wall 7 17 11 17 11 21 7 21
object sq0 A 60.96 10.4 62.96 13.86 59.5 15.86 57.5 12.4
object sq1 C 52.86 23 58.52 28.66 52.86 34.31 47.2 28.66
utak 60.5 31.5 south
