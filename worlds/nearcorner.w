# nearcorner.w - Utak close to the TABLE's south-west corner, facing west, so that
# the verge fills much of his field and squares off the TABLE are seen as verge.
# A small square lies to his right (north of him) and a slanted triangle behind
# him (east), for the eye to see at every resolution.
table 30 24
object square A 4 8 7 8 7 11 4 11
object triangle E 11.5 2.2 16.3 4.1 12.1 7.7
utak 3.5 3.5 west
