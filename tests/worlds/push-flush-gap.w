# push-flush-gap.w - a square turned 20 degrees (perturb.c's slant.w, variant 1) to be
# pushed into the north-east corner past a brick: 5.76 squares across, it covers 7
# columns of the TABLE at any whole-square offset and 6 only pressed flush against
# the east wall, and the gap between the brick and that wall is 6 columns. Utak's
# plan on his squares can never take it through and goes round in circles; seating
# from there (push.c, push_in_circles) presses it flush and slides it up along the
# wall into the corner (the judge: 1 short, achieved). His held set keeps a row of
# the wall after the last push, which halts part way, and no longer reads as a
# square; it read as one when grasped and has stayed within a square of that set's
# box, which is what a rigid push allows (push.c, push_held_is_task_shape): he
# claims it, rightly.
table 44 34
object square A 6.473 20.686 10.693 22.226 9.153 26.446 4.933 24.906
object brick C 29.191 23.179 36.571 28.339 34.851 30.799 27.471 25.639
object lshape D 17.003 6.275 15.743 8.995 12.113 7.305 9.583 12.745 6.863 11.475 10.663 3.315
object triangle E 30.385 13.399 28.335 7.769 36.025 11.349
utak 22.5 17.5 north
