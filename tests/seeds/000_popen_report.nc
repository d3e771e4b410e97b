; Open file for output
POPEN                            ; Open output channel

; Write data
DPRNT[MEASUREMENT REPORT]
DPRNT[DATE:#3011 TIME:#3012]
DPRNT[PART NUMBER: ABC123]
DPRNT[]
DPRNT[FEATURE*X*Y*Z*DIAMETER]

; Write measurements
#1 = 1
WHILE [#1 LE 10] DO 1
  DPRNT[HOLE#1[20]*#[100+#1][73]*#[110+#1][73]*#[120+#1][73]*#[130+#1][73]]
  #1 = #1 + 1
END 1

; Close file
PCLOS                            ; Close output channel
