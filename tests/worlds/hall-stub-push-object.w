# hall-stub-push-object.w - hall-stub-push.w with the stub an object (letter S)
# instead of wall: the control, and the rule's cost (hallsplit.h, push.c
# held_room_split). The verdict counts objects as space, so the hall is one room
# and the square pushed into the south-west corner is achieved; but Utak's eye,
# seeing the stub only coarsely and never touching it, cannot tell it from the
# wall of hall-stub-push.w, so he claims the corner with a doubt.
table 43 110
object stub S 22 57 14 57 14 55 22 55
object square1 Y 8 62 13 62 13 67 8 67
utak 5.5 100.5 south
