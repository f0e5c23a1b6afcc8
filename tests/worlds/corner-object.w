# corner-object.w: a brick pressed into the north-east corner (controller.c,
# corner_felt_object). The eye reads it as part of the verge it leans on (paper
# 3.4.2), so the best floor the model sees is 5 squares short of the judge's corner,
# which counts an object's squares as the room's. Before, Utak claimed "go
# ne-corner" there (a false success); now touch feels the brick's C beside him and
# he says he cannot tell.
table 40 30
object sq A 10 10 14 10 14 14 10 14
object br C 34 24 39 24 39 29 34 29
utak 5.5 5.5 north
