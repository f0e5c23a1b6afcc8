# big-square.w: a 10 x 10 square in an open room (objects.h, objects_seen_exactly).
# Its middle squares are 5 deep from every side; the fovea reaches 4 squares one way
# and 3 the other, so no place on the floor shows them in it: only the 2 x 2 cells'
# levels fix them, and before they counted, "go square" ran out of cycles and "go
# round square" ended in doubt ("no square seen whole in the fovea").
table 60 40
object big A 30 15 40 15 40 25 30 25
utak 10.5 20.5 north
