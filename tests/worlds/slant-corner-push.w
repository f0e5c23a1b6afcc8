# slant-corner-push.w: a square 6 wide turned 30 degrees, on a table too small to
# turn it in the corner (pushslant.c). Pushed into the corner at that slant it
# touches each wall with a vertex and stays 2 short; the model's held squares,
# pressed against both walls, read it home (cells half wall, half object).
# Before, Utak claimed "push square nw-corner" (a false success); now the bound
# of a slanted rectangle seated in a corner says it stays at least 2 short.
table 24 18
object sq A 14.99 6.11 20.19 9.11 17.19 14.3 11.99 11.3
utak 3.5 11.5 north
