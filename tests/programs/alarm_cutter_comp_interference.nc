; A slot narrower than the tool under G41: the tool path of the slot's floor
; runs backwards, so PS0041 stops the run before it, at the end of the move
; into the slot (FANUC's interference check, 5008#3 CNV = 0).
%
O5300(NARROW SLOT)
G17G21G40G90
G10L12P1R6.
G0X-20.Y0
G1Z-2.F300.
G41D1X0Y0
X20.
Y-15.
X28.
Y0
X50.
G40X60.Y10.
M30
%
