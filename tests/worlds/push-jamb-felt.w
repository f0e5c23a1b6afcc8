# push-jamb-felt.w - task (v) beside a door (wallbump.h, wallbump_corner_look): two
# rooms joined by a door 8 wide in a wall 2 thick. Utak faces east, so his
# north-east corner is the table's south-east corner of his room, beside the door's
# south jamb; the jamb's end is a corner of the wall toward that corner, which may
# be an object pressed into it. Pushing, behind the square, he could not feel it
# and doubted the corner; before he grasps, hands free, he goes beside it and touch
# feels B: the corner is claimed.
table 50 30
wall 24 1 26 1 26 11 24 11
wall 24 19 26 19 26 29 24 29
object square A 16 6 19 6 19 9 16 9
utak 8.5 15.5 east
