O9090 (THIN WALL MILLING)
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
#30 = #[2400 + #4120] * 2
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
#34 = FUP[#5 / #33]              ; Number of Z passes
;
; Position
G00 X#24 Y#25
G00 Z5.
;
; Main machining loop
#35 = 0                          ; Current Z
#36 = 0                          ; Pass counter
;
WHILE [#36 LT #34] DO 1
  #35 = #35 - #33
  IF [#35 LT [-#5]] THEN #35 = -#5
  ;
  G00 Z[#35 + 1]
  G01 Z#35 F[#32/2]
  ;
  ; Cut along wall (alternating direction)
  #37 = #36 MOD 2
  IF [#37 EQ 0] GOTO 100
  ; Return pass
  G01 X#24 F#32
  GOTO 200
  N100
  ; Forward pass
  G01 X[#24 + #4] F#32
  N200
  ;
  #36 = #36 + 1
END 1
;
G00 Z10.
M99
%
