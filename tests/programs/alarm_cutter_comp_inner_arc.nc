; An inside arc whose radius is smaller than the offset: the tool centre
; would have to run a negative radius (PS0041).
%
O5302(FILLET SMALLER THAN TOOL)
G17G21G40G90
G10L12P4R6.
G0X-10.Y-10.
G1Z-3.F250.
G41D4X0Y0
X30.
G3X35.Y5.R5.
G1Y30.
G40X-10.Y-10.
M30
%
