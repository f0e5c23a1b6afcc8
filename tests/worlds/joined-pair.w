# joined-pair.w - JOINED (joined.h): two squares 5 x 5 side by side, their squares a
# 10 x 5 brick's, which no look parts (paper 3.4.2). There is no brick in this
# world. Before joined.h Utak touched the pair and believed "go brick" done (a
# false success); now he pulls the square he touches, the other stays where one
# brick drawn back would leave floor, and he doubts it (exit 1).
table 40 30
object s1 A 15 10 20 10 20 15 15 15
object s2 E 20 10 25 10 25 15 20 15
utak 5.5 5.5 north
