# hall-stub-far-object.w - hall-stub-far.w with the stub an object (letter S)
# instead of wall: the control. The verdict counts objects as space, so the hall is
# one room, and the square pushed into its south-west corner is achieved; Utak
# claims it without doubt, as before push.c held_room_split.
table 43 110
object stub S 23 57 15 57 15 55 23 55
object square1 Y 8 12 13 12 13 17 8 17
utak 38.5 92.5 south
