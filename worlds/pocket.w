# pocket.w - a square in a pocket of the north wall: two piers of wall stand out
# from the verge, and the square fills the space between them, touching the piers
# and the verge. Seen from afar, square and wall are one occupied region joined to
# the verge (paper 3.4.2); a brick stands free in the room. Utak faces north.
table 40 30
wall 13 21 16 21 16 29 13 29
wall 20 21 23 21 23 29 20 29
object square A 16 25 20 25 20 29 16 29
object brick C 27 8 35 8 35 11 27 11
utak 10.5 8.5 north
