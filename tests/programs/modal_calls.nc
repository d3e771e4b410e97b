; G66 calls its macro after every block with axis words, with the G66
; arguments; G67 cancels. G66.1 passes every block's words instead.
O0001
#4 = #4012
DPRNT[GROUP12*#4[21]]
G66 P9050 L2 Z-5. R1.
#5 = #4012
DPRNT[GROUP12*#5[21]]
G00 X10. Y10.
F500             ; no axis word: no call
G01 X20.
G67
G00 X30.
; A G66 inside the called macro stacks on the first one.
G66 P9051 A7.
X40.
G67
; M99 P from the modal macro comes back at N20, skipping N10.
G66 P9052
X50.
N10 DPRNT[SKIPPED]
N20 G67
; G66.1: every block is the macro's arguments, G, L and P included.
G66.1 P9053 A3.
G01 X60. Y5. P2 L9
#6 = #4012
DPRNT[GROUP12*#6[21]]
G67
G00 X0 Y0
M30

O9050
DPRNT[MODAL*Z#26[33]*R#18[33]*AT*X#5041[33]*Y#5042[33]]
M99

O9051
G91 G00 Z1.      ; moves inside the macro do not call it again
G90
DPRNT[OUTER*A#1[10]]
G66 P9050 Z-2. R0.5
G00 Z10.         ; but the macro's own G66 calls
G67
M99

O9052
DPRNT[JUMP]
M99 P20

O9053
DPRNT[EVERY*G#10[21]*X#24[33]*Y#25[33]*P#16[10]*L#12[10]*A#1[10]]
G#10 X#24 Y#25 F100.
M99
