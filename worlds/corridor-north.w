# corridor-north.w - task (viii): corridor-east.w with x and y exchanged: Utak faces
# north along the first leg, and the bend turns east.
table 60 56
wall 1 1 1 42 4 42 4 1
wall 16 1 16 30 59 30 59 1
wall 1 42 1 55 59 55 59 42
object brick C 8 10 8 24 11 24 11 10
utak 9.5 5.5 north
