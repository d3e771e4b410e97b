O9050 (MULTI-PART FIXTURE)
(FIXED: #34-#36 ARE NOT VARIABLES - LOCALS END AT #33 - NOW #134-#136)
; Process multiple parts with presence detection
; Uses skip signal to detect part presence
;
; Arguments:
; A = Number of parts (fixture positions)
; I = X spacing between parts
; J = Y spacing between parts (rows)
; K = Parts per row
;
; Defaults
IF [#1 EQ #0] THEN #1 = 4        ; 4 parts default
IF [#4 EQ #0] THEN #4 = 100.     ; X spacing
IF [#5 EQ #0] THEN #5 = 150.     ; Y spacing
IF [#6 EQ #0] THEN #6 = 2        ; 2 parts per row
;
#30 = 0                          ; Part counter
#31 = 0                          ; Good parts
#32 = 0                          ; Missing parts
;
WHILE [#30 LT #1] DO 1
  ; Calculate position
  #33 = #30 MOD #6               ; Column (0 to K-1)
  #134 = FIX[#30 / #6]            ; Row
  #135 = #33 * #4                 ; X position
  #136 = #134 * #5                 ; Y position
  ;
  ; Move to position
  G00 X#135 Y#136
  G00 Z5.
  ;
  ; Probe for part presence (skip if no contact)
  G31 Z-2. F500.
  ;
  ; Check if part present
  IF [#5063 LT -1.5] GOTO 100    ; No contact = missing part
  ;
  ; Part present - run subprogram
  #31 = #31 + 1                  ; Count good
  M98 P1000                      ; Machine this part
  GOTO 200
  ;
  N100 (PART MISSING)
  #32 = #32 + 1                  ; Count missing
  ;
  N200 (NEXT PART)
  G00 Z50.
  #30 = #30 + 1
END 1
;
; Report
#100 = #31                       ; Good parts
#101 = #32                       ; Missing parts
G00 Z100.
;
IF [#32 GT 0] THEN #3006 = 1 (MISSING PARTS - CHECK FIXTURE)
M99
O1000 (FIXED: STAND-IN FOR THE PART PROGRAM THE SEED CALLS)
G01 Z-1. F200.
G00 Z5.
M99
%
