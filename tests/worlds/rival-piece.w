# rival-piece.w - the square near the start, and farther on a piece that reads a
# square too (issue 13 item 6; rival.h). The two objects of piece-square.w moved
# by whole squares (which keeps the squares each covers): the square 7 squares
# from the start, the piece 12. The judge's square is the nearer. The eye cannot
# tell which of the two is the square; shape by motion can: for "go square" Utak
# probes the square (it may be one), goes to the piece and probes it (it is
# none), and claims the square with no doubt left.
table 40 40
object square1 P 29.304 28.824 23.892 29.235 23.48 23.823 28.893 23.411
object piece1 M 25.485 14.734 26.169 17.418 24.359 18.873 22.065 16.852 23.742 14.127
utak 33.5 26.5 west
