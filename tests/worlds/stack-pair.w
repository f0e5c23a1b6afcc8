# stack-pair.w - SEAM (seam.h): two 6 x 3 bricks pressed together, their squares a
# 6 x 6 square's, which no look parts (paper 3.4.2). There is no square in this
# world. Before seam.h Utak probed the brick he touched by quarter-square pushes,
# the first halted against the other brick unseen, and a rectangle of square
# proportions explained every look: "go square" believed done (a false success).
# Now he grasps the brick he touches and pushes it two squares along, and back,
# each way, then across: pushed along, it slides off the other brick, which stays
# where one object would have gone with him; not the square, and he finds there is
# no square ("go square", exit 1); "go round square" likewise, from the loop.
table 40 30
object b1 C 10 10 16 10 16 13 10 13
object b2 D 10 13 16 13 16 16 10 16
utak 12.5 4.5 north
