# south.w - Utak faces south, so his north is the TABLE's south: his north-east
# corner is the TABLE's south-west. A square and a triangle in an open room.
table 36 28
object square A 24 6 28 6 28 10 24 10
object triangle E 8 17 14 17 10 23
utak 18.5 14.5 south
