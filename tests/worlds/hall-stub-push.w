# hall-stub-push.w - hall-stub.w with a square to push (paper task (v); issue 13
# items 3 and 6: a corner is the starting room's, and an honest belief). The hall,
# 42 wide, is parted by a free-standing wall stub 8 long and 2 thick, 13 squares
# from the west wall and 20 from the east (hall-stub.w's stub a square west); Utak
# starts at the north-west facing south, so his north-east corner is the TABLE's
# south-west, and the square lies in his half, beside the west gap. The verdict's
# rooms count the stub as wall: two rooms, and the corner he pushes the square into
# is the south room's. He sees the stub only with the outer zones of the retina,
# as an object (space to his rooms), and pushes the square through the west gap:
# before hallsplit_parts_all he claimed the south room's corner (a false success);
# now, the stub taken for wall parting the square's squares from his start, he
# doubts it (push.c held_room_split). The control: hall-stub-push-object.w.
table 43 110
wall 22 57 14 57 14 55 22 55
object square1 Y 8 62 13 62 13 67 8 67
utak 5.5 100.5 south
