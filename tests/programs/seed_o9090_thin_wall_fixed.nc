O0090 (FIXED: TEST DRIVER - TOOL 1 ACTIVE - ITS D GEOMETRY IS PRESET)
T1 M06
G65 P9090 X0. Y0. I50. J5. Q1. W2. F500.
M30
O9090 (THIN WALL MILLING)
(FIXED: #34-#37 ARE NOT VARIABLES - LOCALS END AT #33 - NOW #134-#137)
; G65 P9090 X_ Y_ Z_ I_ J_ Q_ W_ F_
; X, Y = Start corner
; I = Wall length
; J = Wall height (Z depth)
; Q = Depth per pass
; W = Wall thickness
; F = Feed
;
; Adjusts parameters for thin wall stability
;
IF [#4 EQ #0] THEN #3000 = 190 (THIN WALL - I LENGTH REQUIRED)
IF [#5 EQ #0] THEN #3000 = 190 (THIN WALL - J HEIGHT REQUIRED)
IF [#17 EQ #0] THEN #17 = 1.     ; 1mm per pass default
IF [#23 EQ #0] THEN #3000 = 190 (THIN WALL - W THICKNESS REQUIRED)
IF [#9 EQ #0] THEN #9 = 500.
;
; Get tool diameter
(FIXED: #2401+ IS THE HAAS D LAYOUT - FANUC MEMORY C D GEOMETRY IS #13001+)
#30 = #[13000 + #4120] * 2
IF [#30 EQ 0] THEN #3000 = 190 (THIN WALL - NO TOOL DIAMETER)
;
; Calculate wall flexibility factor
; Thinner walls need slower feed and lighter cuts
#31 = #23 / #30                  ; Thickness/tool ratio
IF [#31 LT 0.5] THEN #31 = 0.5   ; Minimum ratio
IF [#31 GT 1] THEN #31 = 1       ; Maximum ratio
;
; Adjust parameters based on flexibility
#32 = #9 * #31                   ; Adjusted feed
#33 = #17 * #31                  ; Adjusted depth
;
; Climb milling recommended for thin walls
; Always machine from thick to thin side
;
; Calculate passes
#134 = FUP[#5 / #33]              ; Number of Z passes
;
; Position
G00 X#24 Y#25
G00 Z5.
;
; Main machining loop
#135 = 0                          ; Current Z
#136 = 0                          ; Pass counter
;
WHILE [#136 LT #134] DO 1
  #135 = #135 - #33
  IF [#135 LT [-#5]] THEN #135 = -#5
  ;
  G00 Z[#135 + 1]
  G01 Z#135 F[#32/2]
  ;
  ; Cut along wall (alternating direction)
  #137 = #136 MOD 2
  IF [#137 EQ 0] GOTO 100
  ; Return pass
  G01 X#24 F#32
  GOTO 200
  N100
  ; Forward pass
  G01 X[#24 + #4] F#32
  N200
  ;
  #136 = #136 + 1
END 1
;
G00 Z10.
M99
%
