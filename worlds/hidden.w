# hidden.w - the north-east corner is hidden behind a block: from where Utak
# starts, the block fills that part of his view and he must go round it.
table 44 36
wall 28 22 34 22 34 35 28 35
object square A 10 8 14 8 14 12 10 12
object brick C 18 26 26 26 26 29 18 29
utak 12.5 20.5 north
