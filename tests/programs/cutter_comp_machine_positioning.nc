; G53 and a reference return of Z alone under cutter compensation (0i-MB
; manual: the move before ends on its perpendicular vector; G53 of the
; plane's axes takes the vector away on its way and the next move in the
; plane starts it again; with Z alone the vector stays and the next move
; starts from it). Expected tool centre, derived by hand (G41, r 5, G54 at
; X100 Y50): N10 start-up to the inner corner (-5,5); N20 to (-5,40),
; perpendicular before the G28; N50 from there to (40,45), perpendicular
; before G53 Z; N60 to (45,0), perpendicular before G53 X Y; the rapid to
; machine 0,0 is work (-100,-50); N80 a type A start-up to (-100,5); N90
; to (0,5), ended perpendicular by the type A cancel N100 to (0,-20).
%
O2513(CRC WITH G53 AND G28 Z)
G17G21G40G49G80G90
G10L2P1X100.Y50.Z0
G10L12P1R5.
G54G0X-20.Y0
Z5.
N10G41D1G1X0Y0F600.
N20Y40.
N30G91G28Z0
N40G90G0Z5.
N50G1X40.
N55G53Z-2.
#101=#5001
#102=#5002
#103=#5041
#104=#5042
#105=#5043
N60Y0
N70G53X0Y0
#106=#5041
#107=#5042
N80G1X-100.Y0
N90X0
N100G40X0Y-20.
#108=#4007
G0Z50.
M30
%
