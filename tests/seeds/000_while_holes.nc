; STANDARD G-CODE (Fixed values)
G81 X10. Y10. Z-15. R2. F200.
G81 X30. Y10. Z-15. R2. F200.
G81 X50. Y10. Z-15. R2. F200.
G81 X70. Y10. Z-15. R2. F200.
G80

; MACRO B (Parametric - same result)
#1 = 10.                    ; Starting X
#2 = 4                      ; Number of holes
#3 = 0                      ; Counter
WHILE [#3 LT #2] DO 1
  G81 X#1 Y10. Z-15. R2. F200.
  #1 = #1 + 20.             ; Increment X
  #3 = #3 + 1               ; Increment counter
END 1
G80
