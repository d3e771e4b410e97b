O9000
#1 = #4120                       ; Get current D number
IF [#1 EQ 0] THEN M99            ; No tool, exit
;
#2 = #[500 + #1]                 ; Get life count for this tool
#2 = #2 + 1                      ; Increment
#[500 + #1] = #2                 ; Store back
;
#3 = #[550 + #1]                 ; Get life limit
IF [#3 EQ 0] THEN M99            ; No limit set
;
IF [#2 GT #3] THEN #3000 = 200 (TOOL LIFE EXCEEDED - CHANGE TOOL)
M99
