; G28 returns through the intermediate point to machine zero; G53 moves in
; machine coordinates (ignored in G91). Both are one-shot.
G54 G90 G00 X10. Y20. Z5.
#1 = #5021
#2 = #5023
G91 G28 Z0
#3 = #5023
#4 = #5003
G90 G28 X0 Y0
#5 = #5021
#6 = #5041
G53 Z-50.
#7 = #5023
#8 = #5043
G91 G53 Z0
G90
DPRNT[#1[33]*#2[33]*#3[33]*#4[33]*#5[33]*#6[33]*#7[33]*#8[33]]
M30
