; #4114 reads the N number of the last NC block (spec §6.4), a block of
; only an N number included; macro statements leave it alone.
O1000
#100 = #4114
N10 G91 G01 X1. F100
#101 = #4114
N20
#102 = #4114
N30 #103 = #4114
M98 P2000
#105 = #4114
M30

O2000
N40 Y1.
#104 = #4114
M99
