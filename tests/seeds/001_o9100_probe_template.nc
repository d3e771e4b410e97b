O9100 (CUSTOM PROBING MACRO)
(INPUT: A=X POSITION, B=Y POSITION, C=DEPTH)
(OUTPUT: #500=MEASURED X, #501=MEASURED Y)
(-------------------------------)
(ARGUMENT VALIDATION)
IF [#1 EQ #0] THEN #3000=1(MISSING A - X POSITION)
IF [#2 EQ #0] THEN #3000=2(MISSING B - Y POSITION)
IF [#3 EQ #0] THEN #3000=3(MISSING C - DEPTH)
(-------------------------------)
(SAVE MODAL STATE)
#3003=1 (DISABLE SINGLE BLOCK)
#3004=1 (DISABLE FEED HOLD)
(-------------------------------)
(MACRO BODY)
G90 G00 X#1 Y#2
G43 Z5.0 H#11
G01 Z#3 F200.
... (probing logic) ...
(-------------------------------)
(STORE RESULTS)
#500=#5061
#501=#5062
(-------------------------------)
(RESTORE AND RETURN)
G90 G00 Z50.0
#3003=0
#3004=0
M99
