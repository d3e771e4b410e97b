; M99 P in the main program jumps to that N of the main program (spec
; §5.8), forward or back, also from a variable; plain M99 still ends it.
O1000
#100 = 0
#1 = 20
M99 P10
DPRNT[SKIPPED]
N10 #100 = #100 + 1
DPRNT[PASS*#100[20]]
IF [#100 GE 3] GOTO 30
M99 P#1
DPRNT[SKIPPED]
N20 G91 G01 X1. F100
M99 P10
N30 #101 = #5041
M99
DPRNT[AFTER*M99]
M30
%
