; Start-up and cancel type B (5003#0 SUP = 1): outer corners take the
; intersection (obtuse) or two vectors joined by a line (acute) at the
; start-up and the cancel move too. Look-ahead of five blocks (19625 = 5):
; three blocks without motion in the plane keep the intersection.
%
O5500(TYPE B START-UP)
G17G21G40G90
G10L12P5R4.
G0X40.Y-10.
G1Z-3.F600.
(ACUTE START-UP: THE CONTOUR TURNS BACK OVER THE LEAD-IN)
G41D5X0Y0
X50.
M8
G4P100
Z-3.5
Y30.
G3X20.Y30.R15.
(ACUTE CANCEL FROM THE ARC: TWO VECTORS)
G40G1X10.Y45.
G0Z10.
M30
%
