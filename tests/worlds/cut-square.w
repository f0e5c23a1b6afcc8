# cut-square.w - a square with one corner cut, read as the square, and the square
# farther on (issue 13, items 1 and 6; probe.h). The piece, five corners (a square
# 2.6 on a side whose one corner a side of 1.4 cuts off), covers exactly the squares
# a square would (random world g258's piece2 of tests/rates.sh, moved by whole
# squares, which keeps the squares it covers). Pushed a quarter square to three
# corners it covers squares no square would, each look's error of motion taken as
# one displacement of the whole look; with the slack spread over each cell on its
# own it passed for the square (probe7). The judge's square is the true one.
table 24 24
object square1 M 15.298 13.681 19.991 13.681 19.991 18.375 15.298 18.375
object piece2 H 8.359 8.303 6.092 9.546 4.273 7.823 4.537 6.477 6.908 5.67
utak 5.5 2.5 north
