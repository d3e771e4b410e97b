; Two G66 in force (spec §5.6, the NCT manual's example): a move of the
; main program calls the later macro, whose moves call the earlier one;
; each G67 cancels the latest G66.
O0001
N10 G66 P0002 A1.
N11 G91 G01 X1. F100
N12 G66 P0003 A2.
N13 X1.
N14 G67
N15 G67
N16 X1.
M30

O0002
N20 DPRNT[O2*FROM*#1[10]*X#5041[33]]
M99

O0003
N30 Y1.
N31 Y1.
N32 DPRNT[O3*A#1[10]]
M99
