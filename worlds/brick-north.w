# brick-north.w - task (vii): a brick (8 x 3) and a roomy door (8) in a wall to the
# north; Utak faces north.
table 40 46
wall 1 24 17 24 17 26 1 26
wall 25 24 39 24 39 26 25 26
object brick C 12 10 20 10 20 13 12 13
utak 22.5 8.5 north
