; RUN: %mbc run -O0 %s | FileCheck %s
; RUN: %mbc run -O1 %s | FileCheck %s
; RUN: %mbc run -O2 %s | FileCheck %s
; RUN: %mbc run -O3 %s | FileCheck %s
; RUN: %mbc compile -O3 -g %s -o %t.o
; Every optimisation level compiles and runs the same program (a call, a
; loop over a promoted local, an indirect store, DPRNT).
O0001
G65 P0002 A4
POPEN
DPRNT[SUM*#100[30]*LAST*#104[11]]
PCLOS
M30
O0002
#100 = 0
#2 = 1
WHILE [#2 LE #1] DO1
#100 = #100 + #2 * #2
#[100 + #2] = #2 / 4
#2 = #2 + 1
END1
M99
; CHECK: SUM   30 LAST  1.0
