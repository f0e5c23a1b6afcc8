# swing-one.w - SWING (swing.h): a brick 7 x 3 on open floor, no wall near enough
# to place Utak after a pull (apart.h). "go brick": touched, grasped, turned a
# quarter about his point and looked at: it comes round whole, and the claim stands.
table 40 30
object brick C 15 12 22 12 22 15 15 15
utak 5.5 5.5 north
