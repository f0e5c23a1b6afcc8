# joined-one.w - JOINED (joined.h): one brick 9 x 4 near a wall. "go brick": no pull
# or turn can be made from where he first touches it; he goes beside it where it can
# be turned (swing.h; before, where it could be pulled, the wall giving the look
# occupied squares to place him by, apart.h), turns it a quarter, and it comes round
# whole, leaving floor behind: one object, and the claim stands.
table 40 30
wall 1 1 39 1 39 4 1 4
object brick C 15 10 24 10 24 14 15 14
utak 8.5 20.5 north
