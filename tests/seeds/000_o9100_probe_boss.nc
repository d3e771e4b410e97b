O9100 (PROBE RECTANGULAR BOSS)
; G65 P9100 X_ Y_ I_ J_ Z_ F_
; X, Y = Approximate center
; I = Approximate X size
; J = Approximate Y size
; Z = Probe depth
; F = Feed
;
IF [#4 EQ #0] THEN #3000 = 200 (PROBE BOSS - I SIZE REQUIRED)
IF [#5 EQ #0] THEN #5 = #4       ; Square if J not given
IF [#26 EQ #0] THEN #26 = -5.
IF [#9 EQ #0] THEN #9 = 100.
IF [#24 EQ #0] THEN #24 = 0
IF [#25 EQ #0] THEN #25 = 0
;
#30 = #4 / 2 + 10                ; X search distance
#31 = #5 / 2 + 10                ; Y search distance
;
; Position above boss
G00 X#24 Y#25
G00 Z10.
;
; Move to -X side, outside boss
G00 X[#24 - #30]
G00 Z#26
;
; Probe +X (find -X face)
G31 X[#24 + 5] F#9
#100 = #5061                     ; -X face
G00 X[#24 - #30]
;
; Move to +X side
G00 Z10.
G00 X[#24 + #30]
G00 Z#26
;
; Probe -X (find +X face)
G31 X[#24 - 5] F#9
#101 = #5061                     ; +X face
G00 X[#24 + #30]
;
; Calculate X center and size
#110 = [#100 + #101] / 2         ; X center
#111 = #101 - #100               ; X size
;
; Move to -Y side
G00 Z10.
G00 X#110                        ; Go to found X center
G00 Y[#25 - #31]
G00 Z#26
;
; Probe +Y (find -Y face)
G31 Y[#25 + 5] F#9
#102 = #5062                     ; -Y face
G00 Y[#25 - #31]
;
; Move to +Y side
G00 Z10.
G00 Y[#25 + #31]
G00 Z#26
;
; Probe -Y (find +Y face)
G31 Y[#25 - 5] F#9
#103 = #5062                     ; +Y face
G00 Y[#25 + #31]
;
; Calculate Y center and size
#112 = [#102 + #103] / 2         ; Y center
#113 = #103 - #102               ; Y size
;
; Store results
#500 = #110                      ; Center X
#501 = #112                      ; Center Y
#502 = #111                      ; Size X
#503 = #113                      ; Size Y
;
; Retract and move to found center
G00 Z10.
G00 X#110 Y#112
;
M99
%
