# joined-one.w - JOINED (joined.h): one brick 9 x 4 near a wall, which gives the look
# occupied squares to place Utak by (apart.h). "go brick": pulled twice straight
# back, it comes away whole, leaving floor behind: one object, and the claim stands.
table 40 30
wall 1 1 39 1 39 4 1 4
object brick C 15 10 24 10 24 14 15 14
utak 8.5 20.5 north
