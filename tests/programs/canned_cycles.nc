; Canned cycles expanded into the control's moves: positioning at the
; current level, rapid to R, the cycle's moves, back to the initial level
; (G98) or R (G99). Peck retracts use parameters 5114/5115 (0.1 mm).
G90 G00 X0 Y0 Z50.
#3001 = 0
G99 G81 X10. Y10. Z-5. R2. F100.
DPRNT[G4009*#4009[20]*G4010*#4010[20]]
X20.                     ; the same cycle at a new position
G98 Y20.                 ; back to the initial level (Z50)
Z-8.                     ; a new depth at the same place
G80
DPRNT[G4009*#4009[20]*AT*Z#5003[33]]
G00 Z10.
G91 G83 X10. Y0 Z-10. R-8. Q4. K2 F200.   ; incremental: R from the
G90 G80                                   ; initial level, Z from R
G73 X0 Y0 Z-4. R1. Q1.5
G82 X1. Z-2. P250
G84 X2. Z-3. R2. F50.
G74 X3.
G85 X4. Z-1. R1.
G86 X5.
G88 X6. P100
G89 X7. P100
G76 X8. Z-3. Q0.5 P500
G87 X9. Z-2. R-6. Q0.5
G81 X10. Y10. Z-1. R1. K0   ; K0: the data only
G00 X0 Y0                   ; a group 01 code cancels the cycle
DPRNT[G4009*#4009[20]]
G04 P1500
G04 X2.
#1 = #3001
DPRNT[CLOCK*#1[60]]
M30
