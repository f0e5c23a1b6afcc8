# door-corner-push.w - a square to push into the north-east corner of a room whose
# east wall has a door near that corner (paper task (v); issue 13: an honest
# belief; the push11 helper's adversarial world a24). The west room is 26 wide, the
# east room beyond the wall 10 wide, the door 5 wide at the north: the verdict's
# door rule (a room's peak clearance at least twice the door's and 2 more) counts
# no door there, so the judge's room is the whole TABLE and its north-east corner
# is the east room's. Utak, pushing the square north-east, presses it into the
# west room's corner beside the door: before push.c's held_in_start_watershed he
# claimed the corner while the judge found the square 11 short (a false success);
# now the verdict's watershed restated on his model joins the two rooms, floor he
# has seen of the east room beats the square, and he doubts it (exit 1).
table 38 33
wall 26 0 28 0 28 27 26 27
wall 26 32 28 32 28 33 26 33
object square A 12.116 13.959 17.112 14.134 16.938 19.131 11.941 18.956
utak 8.5 5.5 north
