O9300 (PROBE REPORT GENERATOR)
; Exports probe data to file
;
POPEN
DPRNT[**********************************]
DPRNT[*  INSPECTION REPORT            *]
DPRNT[**********************************]
DPRNT[]
DPRNT[DATE: #3011[80]]
DPRNT[TIME: #3012[60]]
DPRNT[PROGRAM: O#4120[40]]
DPRNT[]
DPRNT[WORK OFFSET G54:]
DPRNT[  X: #5221[93]]
DPRNT[  Y: #5222[93]]
DPRNT[  Z: #5223[93]]
DPRNT[]
DPRNT[MEASURED FEATURES:]
DPRNT[FEATURE    NOMINAL    ACTUAL     DEV]
DPRNT[----------------------------------------]
;
; Output stored measurements (#500-#519)
#1 = 0
WHILE [#1 LT 10] DO 1
  #10 = #[500 + #1*2]            ; Nominal
  #11 = #[501 + #1*2]            ; Actual
  #12 = #11 - #10                ; Deviation
  DPRNT[F#1[20]     #10[83]    #11[83]   #12[83]]
  #1 = #1 + 1
END 1
;
DPRNT[]
DPRNT[END OF REPORT]
PCLOS
M99
