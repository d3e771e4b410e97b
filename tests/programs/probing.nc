; G31 against the probe scene of the profile (machine coordinates of the
; ball centre, the control point less the tool length): a bore probed from
; inside, a sphere on the plate and the plane below the hole from above, a
; move without contact (it completes and #5061 holds its end) and one that
; starts in contact. #5061+ are local coordinates with the tool length in
; them (#5063 - #5083 is the ball centre's Z).
G54 G90 G43 H1 G00 X40. Y20. Z10.
Z-10.
G31 X60. F200
#1 = #5061
G00 X40.
G31 X20.
#2 = #5061
G00 X40.
G31 Y40.
#3 = #5062
G00 Y20.
G31 Y0
#4 = #5062
#5 = [#1 + #2] / 2
#6 = [#3 + #4] / 2
#7 = #1 - #2 + 2
G00 Z20.
G00 X100. Y50.
G31 Z-40.
#8 = #5063
#9 = #5003
#10 = #5063 - #5083
G00 Z20.
G00 X40. Y20.
G31 Z-100.
#11 = #5063 - #5083
G00 Z-20.
G91 G31 X5.
G90
#12 = #5061
G01 Z-59.
G31 X30.
#13 = #5061
DPRNT[#1[33]*#2[33]*#3[33]*#4[33]*#5[33]*#6[33]*#7[33]]
DPRNT[#8[33]*#9[33]*#10[33]*#11[33]*#12[33]*#13[33]]
M30
