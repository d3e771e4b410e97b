O0001 (COMPLETE PART FRAMEWORK)
;
; ═══════════════════════════════════════════════════════════════
; PROGRAM HEADER
; ═══════════════════════════════════════════════════════════════
; Part: Example Framework
; Material: 6061-T6 Aluminum
; Machine: 3-Axis VMC
; Programmer: [Name]
; Date: [Date]
;
; Revision History:
; v1.0 - Initial release
;
; ═══════════════════════════════════════════════════════════════
; INITIALIZATION
; ═══════════════════════════════════════════════════════════════
;
N10 G90 G21 G17 G40 G49 G80      ; Safety line
N20 G54                          ; Work offset
;
; Store parameters
#500 = 1                         ; Part counter
#501 = 0                         ; Error flag
;
; ═══════════════════════════════════════════════════════════════
; TOOL 1 - FACE MILL
; ═══════════════════════════════════════════════════════════════
;
N100 T01 M06 (50MM FACE MILL)
G43 H01 Z50.
G65 P9040 T1 A1                  ; Tool life increment
;
S3000 M03
M08
;
; Face mill operation
G00 X-30. Y0
G00 Z2.
G01 Z0 F1000.
G01 X130. F500.
G00 Z50.
;
M09
;
; ═══════════════════════════════════════════════════════════════
; TOOL 2 - DRILL
; ═══════════════════════════════════════════════════════════════
;
N200 T02 M06 (10MM DRILL)
G43 H02 Z50.
G65 P9040 T2 A1                  ; Tool life increment
;
S2500 M03
M08
;
; Bolt circle
G65 P9001 X0 Y0 R30. H6 Z-15. Q3. F200.
;
M09
;
; Tool break check
G65 P9130 T2
IF [#100 EQ 1] GOTO 8000         ; Tool broken
;
; ═══════════════════════════════════════════════════════════════
; TOOL 3 - END MILL
; ═══════════════════════════════════════════════════════════════
;
N300 T03 M06 (12MM END MILL)
G43 H03 Z50.
G65 P9040 T3 A1                  ; Tool life increment
;
S4000 M03
M08
;
; Pocket operation
G65 P9004 X50. Y50. Z-10. R3. D40. Q2. F300.
;
M09
;
; ═══════════════════════════════════════════════════════════════
; PROGRAM END
; ═══════════════════════════════════════════════════════════════
;
N9000 (NORMAL END)
#500 = #500 + 1                  ; Increment part count
G91 G28 Z0 M09
G28 X0 Y0
M30
;
; ═══════════════════════════════════════════════════════════════
; ERROR HANDLING
; ═══════════════════════════════════════════════════════════════
;
N8000 (TOOL BROKEN)
#501 = 1
G91 G28 Z0 M09
M05
M00 (TOOL BROKEN - REPLACE AND RESTART)
GOTO 200                         ; Return to operation
;
%
