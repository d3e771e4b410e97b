O0100 (FIXED: TEST DRIVER - THE SEED CALLS O9000 AS CUSTOM M100)
(FIXED: M100 NEEDS PARAMETER 6080 - CALLED HERE WITH G65 P9000)
T01 M06
G65 P9000
M30
O9000
#1 = #4120                       ; Get current D number
(FIXED: THEN M99 IS NOT MACRO B - JUMP TO N99 M99 INSTEAD)
IF [#1 EQ 0] GOTO 99             ; No tool, exit
;
#2 = #[500 + #1]                 ; Get life count for this tool
#2 = #2 + 1                      ; Increment
#[500 + #1] = #2                 ; Store back
;
#3 = #[550 + #1]                 ; Get life limit
(FIXED: THEN M99 IS NOT MACRO B - JUMP TO N99 M99 INSTEAD)
IF [#3 EQ 0] GOTO 99             ; No limit set
;
IF [#2 GT #3] THEN #3000 = 200 (TOOL LIFE EXCEEDED - CHANGE TOOL)
(FIXED: N99 ADDED AS THE TARGET OF THE TWO GOTO 99)
N99 M99
