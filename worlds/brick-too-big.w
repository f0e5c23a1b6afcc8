# brick-too-big.w - task (vii), impossible: a brick 5 wide at its narrowest and a
# door of 3. Utak must say so, with the reason, and exit 1.
table 50 30
wall 24 1 26 1 26 13 24 13
wall 24 16 26 16 26 29 24 29
object brick C 10 10 18 10 18 15 10 15
utak 8.5 20.5 east
