; M99 P to an N the main program does not have: PS0128 at the M99 block.
O1000
#100 = 1
M99 P77
#100 = 2
M30
