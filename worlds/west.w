# west.w - a long room; Utak faces west (his north is the TABLE's west). The
# square lies far to his east, beyond his first 32 x 32 field of view.
table 72 24
object square A 60 9 64 9 64 13 60 13
object brick C 30 4 38 4 38 7 30 7
utak 20.5 12.5 west
