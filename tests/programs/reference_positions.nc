; G30 P2/P3 go through the intermediate point to the 2nd/3rd reference
; position of parameters 1241/1242; G29 comes back through the last
; intermediate point (in G91 the words count from it). G93 inverse time and
; G95 feed per revolution time the feed moves; G61 is a mode only.
G54 G90 G00 X10. Y20. Z5.
G30 Z50.
#1 = #5023
#2 = #5003
G30 P3 X10.
#3 = #5021
#4 = #5022
G29 X30.
#5 = #5001
G91 G29 Z-10.
G90
#6 = #5003
#3001 = 0
G93 G01 X40. F2.
#7 = #3001
#3001 = 0
G95 S500 X50. F0.04
#8 = #3001
#9 = #4005
G94 G61
#10 = #4015
G64 F1000
#11 = #4005
DPRNT[#1[33]*#2[33]*#3[33]*#4[33]*#5[33]*#6[33]]
DPRNT[#7[50]*#8[50]*#9[20]*#10[20]*#11[20]]
G93 X60.
M30
