# lean-pocket.w: a wall across the table with a gap 7 wide in its middle; below it a
# square flush against the south verge, whose top leaves a passage 2 wide under the
# wall, and Utak in the pocket east of it (roomlean.h). The judge counts the square
# as space: one room. On Utak's model the square is verge (paper 3.4.2) and the
# pocket a room of its own behind a door 2 wide: he claimed the pocket's ne-corner,
# 10 short, and "go next-room" past that door, where the judge finds no next room
# (hand-written world h258, two false successes). Both claims rest on that door now:
# going to the corner he touches its jambs within reach first, going to the next
# room he passes beside them, and touch feels the square's A on one: he says he
# cannot tell.
table 30 20
wall 1 9 10 9 10 10 1 10
wall 17 9 29 9 29 10 17 10
object sq0 A 18 1 24 1 24 7 18 7
utak 25.5 5.5 north
