# hall-stub-far.w - hall-stub.w with a square to push lying in the hall's far half
# (paper task (v); issue 13 items 3 and 6: a corner is the starting room's, and an
# honest belief). The verdict's rooms count the stub as wall: the hall is two rooms,
# and the corner Utak must push the square into (his north-east, the TABLE's
# south-west: he faces south) is that of the north room he starts in, at the mouth
# of the west gap beside the stub. Here his model holds the stub too, and parts the
# hall; he fetches the square from the south half and pushes it north toward that
# corner, seating it against the west wall 4 squares short of the stub's line, in
# the south room. There its squares score beyond every floor of his start's room
# (ahead of him is south): a negative shortfall, which push_seat_finish took for
# "in the corner" (a false success). Now, none of the squares that reach the
# corner lying in his start's room on his own room map (goals_in_start_room, push.c
# held_room_split), he doubts it: an honest failure. The control: hall-stub-far-object.w.
table 43 110
wall 23 57 15 57 15 55 23 55
object square1 Y 8 12 13 12 13 17 8 17
utak 38.5 92.5 south
