; The system constants of a 30i-B (#3100 vacant, #3101 pi, #3102 e) and the
; manual handle interruption amounts (#5121+: 0, no handle turns here), as
; a probing macro library uses them: the feed of a spiral entry from the
; circumference, and a start point corrected by the handle.
%
O8100(SPIRAL ENTRY FEED FROM PI)
(T2 D10 ENDMILL - POCKET R25.)
G17G21G40G90
#1=25.
#2=#3101*2.*#1
#3=#2/[#3102*#3102]
#4=#3100
IF[#4EQ#0]THEN#5=1.
G0X[#5121+#1]Y[#5122]Z5.
G1Z-1.F[ROUND[#3*10.]]
G3I-#1
G0Z5.
DPRNT[CIRC*#2[43]*FEED*#3[43]*VACANT*#5[10]]
M30
%
