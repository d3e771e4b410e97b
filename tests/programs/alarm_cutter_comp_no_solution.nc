; An inner corner where the offset line and the offset arc never meet: the
; line's tool path at Y5 passes above a circle of radius 1 about X4 Y0
; (PS0033).
%
O5303(NO INTERSECTION)
G17G21G40G90
G10L12P2R5.
G0X-10.Y-10.
G41D2G1X-5.Y0F400.
X10.
G3X-2.Y0I-6.J0
G40G1X-10.Y-10.
M30
%
