# hall-stub-fovea-push.w - task (v) in a hall 42 wide parted by a free-standing
# wall stub (6 squares long, 2 thick) that Utak sees in the fovea, with a square in
# his half (paper task (v), 3.4.2; issue 13 items 3 and 6). Derived from
# hall-stub.w (the stub shortened and moved, a square added, as in the made-up
# variant where the false success showed): Utak pushes the square past the stub
# into the other half's corner; seen closely, the stub read as an object and he
# claimed it. Now an object not felt that, taken for wall, would part his start from
# every held square that reaches the corner is a doubt, as a coarse blob was
# (push.c held_room_split; not settled by touch: he would have to let go of the
# square): an honest failure.
table 43 110
wall 24 57 18 57 18 55 24 55
object square1 Y 30 65 35 65 35 70 30 70
utak 38.5 92.5 south
