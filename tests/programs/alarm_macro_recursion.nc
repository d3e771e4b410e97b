%
O1000 (A macro that calls itself without end: PS0122 at the sixth level)
G65 P9000 A1.
M30
O9000
#100 = #100 + 1
G65 P9000 A[#1 + 1]
M99
%
