table 20 20
object a A 5 5 8 5 8 8
