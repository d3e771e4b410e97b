O9130 (TOOL BREAK DETECTION)
(FIXED: #34 #35 ARE NOT VARIABLES - LOCALS END AT #33 - NOW #134 #135)
(FIXED: A SHORT OR BROKEN TOOL TOUCHES LOWER, NOT HIGHER - LT/GT SWAPPED)
; Uses laser or touch probe to verify tool
; G65 P9130 T_ L_ D_
; T = Tool number to check
; L = Expected length (optional, uses offset if omitted)  
; D = Diameter to check (optional)
;
IF [#20 EQ #0] THEN #20 = #4120  ; Current tool
;
; CUSTOMIZE FOR YOUR MACHINE:
#30 = 200.                       ; Laser X position
#31 = 0.                         ; Laser Y position
#32 = 100.                       ; Laser Z start (above)
#33 = -100.                      ; Laser Z search limit
#134 = 0.5                        ; Tolerance
;
; Get expected length
IF [#12 NE #0] GOTO 10
#12 = #[2000 + #20]              ; From H offset
IF [#12 EQ 0] THEN #3000 = 230 (BREAK DET - NO LENGTH DATA)
N10
;
; Expected Z at break position
#135 = #32 - #12
;
; Position over detector
G90 G53 G00 Z0
G53 G00 X#30 Y#31
G53 G00 Z#32
;
; Probe down
G31 Z#33 F500.
;
; Check if tool found
IF [#5063 LT #135 - #134] GOTO 100  ; Tool shorter than expected or broken
IF [#5063 GT #135 + #134] GOTO 100  ; Tool longer (wrong tool?)
;
; Tool OK
#100 = 0                         ; Status: OK
GOTO 900
;
N100 (TOOL PROBLEM)
#100 = 1                         ; Status: Problem
#101 = #5063                     ; Measured position
#102 = #135                       ; Expected position
#103 = #5063 - #135               ; Difference
;
IF [#103 LT 0] THEN #3000 = 231 (TOOL BROKEN OR SHORT)
IF [#103 GT 0] THEN #3000 = 232 (WRONG TOOL LENGTH)
;
N900
G53 G00 Z0
M99
%
