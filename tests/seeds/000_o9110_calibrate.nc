O9110 (AUTO CALIBRATE G54-G59)
; Probes reference features and sets all work offsets
; Requires reference sphere/ring at known machine position
;
; Parameters (set in permanent variables)
#510 = 300.                      ; Reference X (machine coord)
#511 = 0.                        ; Reference Y (machine coord)
#512 = -50.                      ; Reference Z (machine coord)
#513 = 25.4                      ; Reference diameter
;
; Probe the reference
G90 G53 G00 Z0                   ; Machine home Z
G53 G00 X#510 Y#511              ; Go to reference
G53 G00 Z[#512 + 25]             ; Above reference
;
; Probe Z
G31 Z[#512 - 10] F100.
#520 = #5063                     ; Reference Z result
;
; Probe X (4-point for center)
G53 G00 Z[#512 + 10]
G53 G00 X[#510 - 20]
G53 G00 Z#520
G31 X[#510 + 5] F100.
#521 = #5061                     ; -X face
G53 G00 X[#510 - 20]
G53 G00 Z[#512 + 10]
G53 G00 X[#510 + 20]
G53 G00 Z#520
G31 X[#510 - 5] F100.
#522 = #5061                     ; +X face
;
#525 = [#521 + #522] / 2         ; Measured X center
;
; Calculate drift from nominal
#530 = #525 - #510               ; X drift
#531 = #520 - #512               ; Z drift
;
; Apply correction to all work offsets
; G54
#5221 = #5221 - #530
#5223 = #5223 - #531
; G55
#5241 = #5241 - #530
#5243 = #5243 - #531
; G56
#5261 = #5261 - #530
#5263 = #5263 - #531
; G57
#5281 = #5281 - #530
#5283 = #5283 - #531
; G58
#5301 = #5301 - #530
#5303 = #5303 - #531
; G59
#5321 = #5321 - #530
#5323 = #5323 - #531
;
; Report
#100 = #530                      ; X correction applied
#101 = #531                      ; Z correction applied
;
G53 G00 Z0
M99
%
