# piece-square.w - a piece read as the square, and the square farther on (issue 13,
# items 1 and 6; objects.h, ANOTHER OF THE SHAPE). The piece, five corners that no
# name fits, covers exactly the squares a square would (worldgen 134's piece1, moved
# by whole squares, which keeps the squares it covers); the judge's square is the
# true one, 13 from Utak's start. The eye cannot tell which of the two is the
# square, so Utak may claim the piece only with a doubt.
table 40 40
object square1 P 27.304 20.824 21.892 21.235 21.48 15.823 26.893 15.411
object piece1 M 29.485 24.734 30.169 27.418 28.359 28.873 26.065 26.852 27.742 24.127
utak 33.5 26.5 west
