# apart-pair.w - MERGED, and a pull that shows part left (apart.h): apart-l.w with a
# square (squareM, 3 x 3) in the L's crook, on the squares next to the L's: the eye
# sees one object of the two, which reads no square, and squareM is the judge's
# square (nearer the start than the square). Utak pulls the set; what he grasped
# comes away and squareM stays, so where one object drawn back would leave floor
# the eye sees it occupied: the doubt stands, and he fails honestly (before, the
# same doubt with no pull; without MERGED, a false success).
table 40 30
object square A 7.714 19.742 11.714 19.742 11.714 23.742 7.714 23.742
object brick C 25.76 17.97 34.76 17.97 34.76 20.97 25.76 20.97
object lshape D 8.151 4.773 11.151 4.773 11.151 8.773 17.151 8.773 17.151 11.773 8.151 11.773
object squareM M 12 5 15 5 15 8 12 8
utak 20.5 12.5 east
