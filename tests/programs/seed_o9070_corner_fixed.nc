O9070 (CORNER CHAMFER/ROUND)
(FIXED: #34-#38 ARE NOT VARIABLES - LOCALS END AT #33 - NOW #134-#138)
; G65 P9070 X_ Y_ Z_ R_ C_ I_ J_ F_
; X, Y = Corner position
; Z = Depth
; R = Retract
; C = Chamfer/radius size
; I = Direction to X: 1=positive, -1=negative
; J = Direction to Y: 1=positive, -1=negative
; F = Feed
;
; Defaults
IF [#3 EQ #0] THEN #3 = 2.       ; 2mm chamfer default
IF [#4 EQ #0] THEN #4 = 1        ; +X direction
IF [#5 EQ #0] THEN #5 = 1        ; +Y direction
IF [#18 EQ #0] THEN #18 = 3.
IF [#9 EQ #0] THEN #9 = 300.
;
; Calculate start and end points
#30 = #24 - [#3 * #4]            ; Start X
#31 = #25                        ; Start Y
#32 = #24                        ; End X
#33 = #25 - [#3 * #5]            ; End Y
;
; Arc center (for radius)
#134 = #24 - [#3 * #4]            ; Center X
#135 = #25 - [#3 * #5]            ; Center Y
#136 = #134 - #30                  ; I
#137 = #135 - #31                  ; J
;
; Move to start
G00 X#30 Y#31
G00 Z#18
G01 Z#26 F[#9 / 2]
;
; Cut corner (G02 or G03 based on direction)
#138 = #4 * #5                    ; Direction product
IF [#138 GT 0] GOTO 100
G02 X#32 Y#33 I#136 J#137 F#9      ; CW for opposite signs
GOTO 200
N100
G03 X#32 Y#33 I#136 J#137 F#9      ; CCW for same signs
;
N200
G00 Z#18
M99
%
