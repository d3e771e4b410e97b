%
O1000 (A runaway loop that writes: --max-output stops it with MBC0003)
(at the block whose output passed the limit; what it wrote is complete)
G90 G01 F500
#100 = 0
WHILE [1 GT 0] DO1
#100 = #100 + 1
X#100 Y[#100 * 2]
DPRNT[PASS*#100[40]]
END1
M30
%
