; G52 local origin, G92/G92.1, G68 rotation, G51 scaling, G51.1 mirror and
; an offset write. x, y, z are workpiece coordinates (G54 after G92) with
; the local origin and the transforms applied; #5001 is the point as the
; program commanded it, #5041 the control point in local coordinates.
G54 G90 G17 G00 X0 Y0 Z10.
G52 X50. Y20.
G00 X10. Y5.
#1 = #5001
#2 = #5041
G52 X0 Y0
#3 = #5001
G00 X0 Y0
G92 X100. Y100.
#4 = #5001
#5 = #5021
G01 X110. F300
G92.1 X0 Y0
#6 = #5001
G00 X0 Y0
G68 X10. Y0 R90.
G01 X20. Y0
G91 X0 Y10.
G90
#7 = #5001
#8 = #5002
#9 = #5041
#10 = #5042
#11 = #4016
G03 X10. Y20. I-10.
G69
#12 = #5001
#13 = #5002
G51 X0 Y0 P2.
G01 X5. Y5.
G02 X15. Y5. I5. J0
#14 = #4011
G50
#15 = #5001
G51.1 X0
G01 X10. Y0
G02 X20. Y0 R5.
#16 = #4018
#17 = #5001
#18 = #5041
G50.1 X0
#19 = #5001
#5221 = -150.
#20 = #5001
G00 X0 Y0
DPRNT[#1[33]*#2[33]*#3[33]*#4[33]*#5[33]*#6[33]]
DPRNT[#7[33]*#8[33]*#9[33]*#10[33]*#11[20]*#12[33]*#13[33]]
DPRNT[#14[20]*#15[33]*#16[21]*#17[33]*#18[33]*#19[33]*#20[33]]
M30
