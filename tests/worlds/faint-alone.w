# faint-alone.w - the only square seen only faint (faint.h, FAINT): a square 3
# wide lies across four of the eye's cells of 4 as Utak first sees it (levels 0,
# 1, 1 and 2), and his sweep of the TABLE passes it only with the same coarse
# cells. Before faint.h he ended "no square seen, and nothing left unseen".
table 60 60
object square A 20 20 23 20 23 23 20 23
utak 30.5 30.5 north
