# stack-one.w - SEAM (seam.h): one 6 x 6 square on open floor, nothing fixed in view
# near it. Pushed two squares each way and back, every look fits one object riding
# with Utak: the claim stands, and "go square" is achieved and believed.
table 40 30
object sq C 10 10 16 10 16 16 10 16
utak 12.5 4.5 north
