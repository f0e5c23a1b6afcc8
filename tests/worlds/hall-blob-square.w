# hall-blob-square.w - a square (an object, letter J) at 20 degrees beside a pier
# of wall, in a hall 40 wide (paper task (i); issue 13 items 3 and 6: rooms that
# are rooms, an honest belief). Cut down from a random world of tests/gen/worldgen.c
# (g131 of the rates' run): the slanted wall made a pier square to the walls, the
# hall shortened, the other objects taken away. Utak, facing south, walks to his
# north-east corner (the table's south-west) and sees the square only with the outer
# zones of the retina, as a blob that, taken for wall, would part the hall with the
# pier (hallsplit.h). Before settling he claimed the corner with that doubt; now he
# goes and touches the blob, feels J, an object, and claims the corner without it
# (12 -> 30 cycles).
table 40 70
wall 34 50 30 50 30 36 34 36
object square1 J 20.88 37.012 16.259 38.832 14.44 34.211 19.06 32.392
utak 16.5 46.5 south
