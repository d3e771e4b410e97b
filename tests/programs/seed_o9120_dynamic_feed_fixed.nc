O0120 (FIXED: TEST DRIVER - G66 IS NOT SUPPORTED YET, SO G65 AFTER AN ARC)
G90 G17 G02 X10. Y0 I5. J0 F500.
G65 P9120 F500. R5. D10.
M30
O9120 (DYNAMIC FEED CONTROL)
; Adjusts feed based on arc radius and chip load
; Call modally with G66 during contour milling
;
; G66 P9120 F_ R_ D_
; F = Base feedrate
; R = Minimum radius threshold
; D = Tool diameter (or from offset)
;
IF [#9 EQ #0] THEN #9 = 500.     ; Base feed
IF [#18 EQ #0] THEN #18 = 5.     ; Min radius threshold
;
; Get tool diameter
IF [#7 NE #0] GOTO 10
#7 = #[2400 + #4120] * 2
(FIXED: THEN M99 IS NOT MACRO B - JUMP TO N900 M99 INSTEAD)
IF [#7 EQ 0] GOTO 900            ; No tool data
N10
;
; Read current move type
#30 = #4001                      ; G00/G01/G02/G03
;
IF [#30 LT 2] GOTO 900           ; Linear moves - no adjustment
;
; Arc move - calculate effective radius
; For arcs, we need the radius
; This is approximate - uses position delta
#31 = ABS[#5001 - #5021]         ; X delta
#32 = ABS[#5002 - #5022]         ; Y delta
#33 = SQRT[#31*#31 + #32*#32]    ; Chord length
;
; Estimate radius from chord (approximate)
(FIXED: #34 #35 ARE NOT VARIABLES - LOCALS END AT #33 - NOW #134 #135)
#134 = #33 / 2                    ; Half chord = rough radius estimate
;
; Feed adjustment based on radius
; Smaller radius = slower feed
IF [#134 GT #18] GOTO 100
; Small radius - reduce feed
#135 = #9 * [#134 / #18]           ; Linear reduction
IF [#135 LT #9 * 0.3] THEN #135 = #9 * 0.3  ; Minimum 30%
GOTO 200
;
N100 (LARGER RADIUS)
#135 = #9                         ; Full feed
;
N200
; Apply feed (this affects next block)
; Note: Direct feed override not available in standard Macro B
; This stores recommended feed in #100 for reference
#100 = #135
;
N900
M99
%
