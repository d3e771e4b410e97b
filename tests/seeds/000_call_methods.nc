; G65 - Non-modal macro call
G65 P9100 A50. B25. C-10.   ; Call O9100 with arguments
G00 X100.                    ; This does NOT call macro again

; G66 - Modal macro call
G66 P9100 A50. B25. C-10.   ; Activate modal macro
G00 X100. Y50.              ; Macro called after this move
G00 X150. Y100.             ; Macro called after this move
G67                         ; Cancel modal macro

; M98 - Subprogram call
M98 P1000                   ; Call O1000
M98 P1000 L5                ; Call O1000, repeat 5 times
M98 P10001000               ; Call O1000, repeat 1000 times (old format)
