%
O1000 (Posted blocks, all constant: compiled as runs of steps. Calls,)
(modal calls and returns in the middle of a run go on after the block;)
(an M99 P landing starts a new run.)
G90 G17 G21 G00 X0 Y0 Z5.
G01 Z-1. F200
X10. Y0
M98 P2000 L2
X10. Y10.
G66 P9000 A1.
X0 Y10.
X0 Y0
G67
X5. Y5.
G02 X15. Y5. R5.
G03 X5. Y5. I-5. J0
M98 P3000
X99. (skipped: O3000 returns to N50)
N50 G00 Z5.
M30
O2000
G91 X1.
Y1.
G90
M99
O3000
G01 X20.
M99 P50
O9000
#100 = [#100 + #1]
G01 X[#5001 + 0.5] Y#5002
M99
%
