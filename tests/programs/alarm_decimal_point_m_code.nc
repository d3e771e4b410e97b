; M, S, T, H and D take whole numbers: M3. is PS0007 when the block runs
; (spec §1.5); a value (M[3.0], M#1) is rounded.
O1000
#1 = 3.4
M#1
M[5.0]
#100 = #4113
S1200.
#101 = 1
M30
