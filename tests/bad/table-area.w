# 8192 x 4097 squares: each side within 8192, the area one row past 33554432
table 8192 4097
utak 5.5 5.5 north
