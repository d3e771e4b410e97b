O9060 (UNIVERSAL THREAD MILL)
(FIXED: #40-#47 ARE NOT VARIABLES - LOCALS END AT #33 - NOW #140-#147)
; G65 P9060 X_ Y_ Z_ R_ I_ K_ Q_ H_ D_ F_
; X, Y = Center position
; Z = Thread start (top)
; R = Thread end (bottom) - depth
; I = Thread pitch
; K = Major diameter (positive=OD, negative=ID)
; Q = Number of spring passes
; H = Helix direction: 1=climb, 2=conventional
; D = Tool diameter (or use D offset)
; F = Feed
;
; Validate
IF [#24 EQ #0] THEN #24 = 0
IF [#25 EQ #0] THEN #25 = 0
IF [#26 EQ #0] THEN #3000 = 160 (THREAD - Z START REQUIRED)
IF [#18 EQ #0] THEN #3000 = 160 (THREAD - R END REQUIRED)
IF [#4 EQ #0] THEN #3000 = 160 (THREAD - I PITCH REQUIRED)
IF [#6 EQ #0] THEN #3000 = 160 (THREAD - K DIAMETER REQUIRED)
;
; Defaults
IF [#17 EQ #0] THEN #17 = 1      ; 1 spring pass
IF [#8 EQ #0] THEN #8 = 1        ; Climb cut
IF [#9 EQ #0] THEN #9 = #4113 * #4 / 25.4  ; Calculate feed
;
; Get tool diameter
IF [#7 NE #0] GOTO 10
#7 = #[2400 + #4120] * 2         ; From D offset
IF [#7 EQ 0] THEN #3000 = 160 (THREAD - NO TOOL DIAMETER)
N10
;
; Determine ID or OD
#140 = 1                          ; ID flag
IF [#6 GT 0] THEN #140 = 0        ; OD
#6 = ABS[#6]                     ; Make positive
;
; Calculate helix radius (tool center)
IF [#140 EQ 1] GOTO 20
; OD thread
#141 = [#6 / 2] + [#7 / 2]        ; OD: major + tool radius
GOTO 30
N20
; ID thread
#141 = [#6 / 2] - [#7 / 2]        ; ID: major - tool radius
N30
;
; Position
G00 X#24 Y#25
G00 Z[#26 + 5]                   ; Above start
;
; Entry move
G00 Z#26                         ; To start depth
#142 = #24 + #141                  ; Entry X
G01 X#142 F[#9 * 3]               ; Linear approach
;
; Calculate passes
#143 = FUP[ABS[#18 - #26] / #4] + #17
;
; Select direction based on ID/OD and climb/conv
; ID Climb = G02, ID Conv = G03
; OD Climb = G03, OD Conv = G02
#144 = 2                          ; Default G02
IF [[#140 EQ 1] AND [#8 EQ 1]] THEN #144 = 2    ; ID Climb = G02
IF [[#140 EQ 1] AND [#8 EQ 2]] THEN #144 = 3    ; ID Conv = G03
IF [[#140 EQ 0] AND [#8 EQ 1]] THEN #144 = 3    ; OD Climb = G03
IF [[#140 EQ 0] AND [#8 EQ 2]] THEN #144 = 2    ; OD Conv = G02
;
; Generate helix
#145 = #26                        ; Current Z
#146 = 0                          ; Pass counter
;
WHILE [#146 LT #143] DO 1
  #147 = #145 - #4                 ; Next Z
  IF [#147 LT #18] THEN #147 = #18
  ;
  IF [#144 EQ 2] GOTO 50
  ; G03
  G03 X#142 Y#25 Z#147 I[-#141] J0 F#9
  GOTO 60
  N50
  ; G02
  G02 X#142 Y#25 Z#147 I[-#141] J0 F#9
  N60
  ;
  #145 = #147
  #146 = #146 + 1
END 1
;
; Exit
G01 X#24 F[#9 * 3]
G00 Z[#26 + 10]
;
M99
%
