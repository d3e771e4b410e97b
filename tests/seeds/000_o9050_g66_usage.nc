G66 P9050 Z-15. R2. F200.       ; Activate modal macro
G00 X10. Y10.                   ; Macro called after this
G00 X30. Y10.                   ; Macro called after this
G00 X50. Y10.                   ; Macro called after this
G67                             ; Cancel modal macro
G00 X70. Y10.                   ; Macro NOT called
