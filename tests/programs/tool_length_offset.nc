; G43/G44/G49: H selects geometry + wear of a tool offset. The control point
; (mz, #5023) carries the offset; the programmed z and #5003 do not; #5043
; and #5083 show it. The offset is taken when H is given: a later table
; write does not move the tool. H alone in G43 mode changes the offset and
; moves by the difference; G49 alone moves back.
G54 G90 G00 X0 Y0 Z100.
G43 H1 Z50.
#1 = #5003
#2 = #5043
#3 = #5083
#4 = #5023
#5 = #4008
#6 = #4111
#11001 = 160.
G01 Z10. F500
H2
#7 = #5083
G44 H1 Z20.
#8 = #5083
#9 = #5043
G43 H1
G91 G28 Z0
#10 = #5003
#11 = #5023
G90 G49 G00 Z50.
#12 = #5083
#13 = #4008
DPRNT[#1[33]*#2[33]*#3[33]*#4[33]*#5[20]*#6[20]]
DPRNT[#7[33]*#8[33]*#9[33]*#10[33]*#11[33]*#12[33]*#13[20]]
G43 H4 Z10.
M30
