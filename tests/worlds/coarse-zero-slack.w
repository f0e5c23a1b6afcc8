# coarse-zero-slack.w - open floor, two squares at slants (issue 13: an honest
# belief; worldmodel.c's disparity, paper 3.5). Utak faces east; "go round square"
# starts with a leg of 12 squares, after which the fovea lands on squares seen only
# in 4 x 4 cells. One of them, a zero cell, holds one square of the near square's
# corner (a 4 x 4 cell at level 0 allows one of its 16). That one foveal cell once
# "corrected" Utak 2.24 squares off a move nothing stopped; he closed his loop on
# the wrong square and claimed the task the judge said he failed.
table 100 100
object near A 57.030 36.106 57.451 39.145 54.412 39.567 53.990 36.528
object far A 44.001 65.785 44.405 69.889 40.300 70.293 39.897 66.188
utak 50.5 50.5 east
