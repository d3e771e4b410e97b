; Calls by codes, set by the machine profile: G100 calls O9010 (6050),
; G110 is a modal custom G code (6051 negative: O9011 after every move),
; M06 calls subprogram O9001 (6071), M50 macro O9020 (6080), T calls O9000
; (6001#5), S calls O9029 (6007#5), B calls O9028 (6007#4).
O0002
#1 = 11
G100 X5. Y6. L2          ; a macro with arguments, twice
G00 X1. M06              ; the move, then the subprogram
DPRNT[LOCAL1*#1[20]]     ; O9001 shares this level
T7
S1200
B45
M50 A9.
G110 R2.
G00 X10.
G00 X20.
G67
G00 X30.
M30

O9000
DPRNT[TOOL*#149[20]]
M06                      ; inside a code's program: an ordinary M06
M99

O9001
DPRNT[TOOLCHANGE*AT*X#5041[33]]
#1 = 22
M99

O9010
DPRNT[CUSTOMG*X#24[33]*Y#25[33]]
M99

O9011
DPRNT[MODALG*R#18[33]*AT*X#5041[33]]
M99

O9020
DPRNT[CUSTOMM*A#1[20]*X#24[33]]
M99

O9028
DPRNT[BCODE*#146[30]]
M99

O9029
DPRNT[SCODE*#147[40]]
M99
