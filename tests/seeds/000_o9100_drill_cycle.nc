O9100 (CUSTOM DRILLING CYCLE)
; Arguments: X, Y = position, Z = depth, R = retract, F = feed
G00 X#24 Y#25               ; Position
G00 Z#18                    ; Rapid to R plane
G01 Z#26 F#9                ; Drill to depth
G00 Z#18                    ; Retract to R
M99
