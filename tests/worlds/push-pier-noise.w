# push-pier-noise.w - a square turned 20 degrees, to be pushed into the north-east
# corner (Utak's frame: he faces east) with noisy motion, `--noise 0.05 --seed 2`
# (paper task (v), 3.5 uncertainty (2); issue 13 item 6, an honest belief). A pier
# stands off the far corner; from /tmp/p11/adv/a14.w (push11's adversarial set).
# Seated, the square is flush against the far verge but 2 short of the corner (the
# judge: failed): its turn leaves the corner square itself floor, and the noise
# turned each seating push along that verge into it. Utak claimed it: (1) four
# pushes into the verge, halted at once, each read as a square gained (the object
# rides with him, and the verge beyond it is hidden by it), and (2) the held square
# that reached the corner lay in a 2 x 2 cell of the eye whose level showed only 3
# of its 4 squares occupied. Now a halted push is found (worldmodel.c,
# wm_solid_tie: the object cannot have gone into the verge) and the claim rests on
# held squares the eye shows whole (pushseen.c): Utak doubts the corner.
table 43 27
wall 35 19 37 19 37 23 35 23
object square A 7.986 11.536 11.746 12.903 10.379 16.662 6.620 15.296
utak 4.5 24.5 east
