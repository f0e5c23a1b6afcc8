# hall-stub-object.w - hall-stub.w with the stub an object (letter S) instead of
# wall: the control, and the rule's cost (hallsplit.h). The verdict counts objects
# as space, so the hall is one room and Utak's corner is achieved; but his eye,
# seeing the stub only coarsely, cannot tell it from the wall of hall-stub.w: he
# claimed the corner with a doubt until he went to touch it (hallsplit.h, SETTLING);
# now he feels S, an object, and claims the corner without it (32 -> 53 cycles).
table 43 110
object stub S 23 57 15 57 15 55 23 55
utak 38.5 92.5 south
