%
O1000 (A subprogram that calls itself without end: PS0077 past the limit)
M98 P2000
M30
O2000
#100 = #100 + 1
M98 P2000
M99
%
