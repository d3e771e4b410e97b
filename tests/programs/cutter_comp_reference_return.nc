; G28, G29 and G30 under cutter compensation: the vector is deleted on the
; way to the intermediate point (a cancel move: here an inner corner, so the
; tool leaves from the intersection), and the next move in the plane - the
; G29 return - starts the offset again like a start-up.
%
O7100(REFERENCE RETURN IN OFFSET MODE)
G17G21G40G90
G10L12P1R5.
G0X0Y-10.Z5.
G1Z-2.F500.
G41D1Y0
X30.
G28X40.Y10.
G29X50.Y0
X70.
G0X80.Y-10.
G40X90.Y-20.
#100=#4007
M30
%
