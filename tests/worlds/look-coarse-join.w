# look-coarse-join.w - two rooms of a grid, Utak at his room's corner with floor seen
# in the next room that beats it, joined to his room on the model only where the
# wall between was seen by the outer zones of the retina (paper task (i); 3.4.2;
# issue 13 item 6). Cut down from random g41 of the rates (tests/gen/worldgen.c):
# the walls and objects that do not bear on it taken away. Before, he ended with
# the doubt "floor that would beat it ... may be of the room he started in, joined
# to it by squares seen only coarsely" (roomdoubt_hidden) though the judge counts
# the corner reached; now he first looks at those squares from nearby
# (roomdoubt_hidden_look, hallsplit_hidden_look), sees the wall in the fovea, and
# claims the corner.
table 194 104
wall 1 57 50 57 50 59 1 59
wall 56 57 80 57 80 59 56 59
wall 82 57 88 57 88 59 82 59
wall 80 57 82 57 82 59 80 59
wall 80 24 82 24 82 57 80 57
wall 80 59 82 59 82 70 80 70
wall 80 74 82 74 82 103 80 103
object square1 C 58.348 87.528 56.455 91.784 52.199 89.891 54.092 85.635
object bit9 R 45.02 67.674 46.314 68.152 46.008 68.98 44.715 68.502
utak 37.5 88.5 east
