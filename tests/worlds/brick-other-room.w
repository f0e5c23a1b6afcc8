# brick-other-room.w - task (vii) on a world written by hand: a wall across the
# TABLE with a door 6 wide; a square (5 x 5) in Utak's room, the brick (10 x 4) in
# the other. Seen from afar the square read as the brick, and the place beyond was
# fixed as the room next to the square's: the brick's own room. Found later, the
# brick was pushed a few squares within its room and believed through the door (a
# false success). Until the object is first grasped, its start follows the task's
# object, and a new one sends Utak to look again (carrytask.c): the brick goes
# through the door. Utak faces north.
table 50 40
wall 0 20 20 20 20 22 0 22
wall 26 20 50 20 50 22 26 22
object sq A 30 5 35 5 35 10 30 10
object br C 5 30 15 30 15 34 5 34
utak 10.5 10.5 north
