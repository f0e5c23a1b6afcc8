# stack-tight.w - SEAM (seam.h) under noisy motion: worlds/square-tight.w's square of
# side 4 and door of 5. With --noise 0.05 --seed 10, "go square": the seam test's
# pushes (one object: it rides with him) leave the square off the grid, and the
# probe's last quarter-square push leaves him a square off it, touch feeling
# nothing. The claim "touches the square" rests on touch after the pushes
# (seam_felt_after): he goes beside it again, probes it again, feels it, and
# only then claims it (claimed where touch felt nothing, the judge would say he
# does not touch it: a false success, as seed 7 was before).
table 44 36
wall 20 1 22 1 22 14 20 14
wall 20 19 22 19 22 35 20 35
object square A 30 10 34 10 34 14 30 14
utak 36.5 20.5 west
