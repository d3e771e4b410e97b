O9080 (TEXT ENGRAVING SYSTEM)
(FIXED: #40-#50 ARE NOT VARIABLES - LOCALS END AT #33 - NOW #140-#150)
; G65 P9080 X_ Y_ Z_ H_ S_ F_
; X, Y = Start position
; Z = Engraving depth
; H = Character height (default 5mm)
; S = String variable start (default #100)
; F = Feed
;
; Character data stored in permanent variables
; Each character = 20 strokes max, #600-#799
;
IF [#8 EQ #0] THEN #8 = 5.       ; 5mm height
IF [#19 EQ #0] THEN #19 = 100    ; String starts at #100
IF [#9 EQ #0] THEN #9 = 200.
IF [#26 EQ #0] THEN #26 = -0.2
;
#30 = #24                        ; Current X
#31 = #25                        ; Current Y
#32 = #8 * 0.6                   ; Character width
#33 = #8 / 5                     ; Stroke scale
;
G00 X#30 Y#31
G00 Z2.
;
; Process string (characters in #100-#119)
#140 = 0                          ; Character index
WHILE [#140 LT 20] DO 1
  #141 = #[#19 + #140]             ; Get character code
  IF [#141 EQ 0] GOTO 999         ; End of string
  IF [#141 EQ 32] GOTO 500        ; Space
  ;
  ; Get stroke data for this character
  ; Character data at #[600 + (char-65)*20]
  #142 = 600 + [#141 - 65] * 20    ; Base address (A=65)
  ;
  ; Draw character strokes
  #143 = 0                        ; Stroke index
  WHILE [#143 LT 10] DO 2
    #144 = #[#142 + #143*2]         ; Stroke data 1
    #145 = #[#142 + #143*2 + 1]     ; Stroke data 2
    IF [#144 EQ 0] GOTO 400       ; End of character
    ;
    ; Decode stroke (packed format)
    #146 = FIX[#144 / 100]         ; Command (0=move, 1=line)
    #147 = #144 - #146*100          ; X offset (0-99)
    #148 = #145                    ; Y offset (0-99)
    ;
    ; Scale offsets
    #149 = #30 + #147 * #33
    #150 = #31 + #148 * #33
    ;
    IF [#146 EQ 0] GOTO 300
    ; Line to
    G01 X#149 Y#150 Z#26 F#9
    GOTO 350
    N300
    ; Move to
    G00 Z2.
    G00 X#149 Y#150
    G00 Z#26
    N350
    #143 = #143 + 1
  END 2
  ;
  N400 (NEXT CHARACTER)
  G00 Z2.
  #30 = #30 + #32               ; Advance X
  GOTO 600
  ;
  N500 (SPACE)
  #30 = #30 + #32
  ;
  N600
  #140 = #140 + 1
END 1
;
N999
G00 Z10.
M99
%
