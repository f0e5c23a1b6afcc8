# big600.w - a TABLE of 600 x 600 squares, one open room (issue 13, part 5: the
# world model grows with what Utak sees, whatever the TABLE's size; across open
# floor seen confidently empty he moves up to 12 squares a cycle). The square is
# in the far corner from Utak, some 460 squares east and 490 north; a brick lies
# near the middle.
table 600 600
object square A 520 540 524 540 524 544 520 544
object brick C 300 300 309 300 309 303 300 303
utak 60.5 50.5 north
