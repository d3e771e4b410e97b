; RUN: %mbc compile %s -o - --emit=llvm -O0 | %llc -O0 -filetype=null -pass-remarks-missed=sdagisel 2>&1 | FileCheck %s
; At -O0 (and in optnone bodies) LLVM selects instructions with FastISel,
; which hands the rest of a basic block to SelectionDAG at the first
; instruction it cannot select: every block's execution-limit load (atomic)
; and every overflow check (fabs) were such instructions, and -O0 compiled
; a fifth slower. What is left is the switch on the flow after an NC
; block (mbc.resume's answer).
; CHECK-NOT: FastISel missed{{.*}} load atomic
; CHECK-NOT: FastISel missed{{.*}} @llvm.fabs
; CHECK: FastISel missed terminator: switch
; CHECK-NOT: FastISel missed{{.*}} load atomic
; CHECK-NOT: FastISel missed{{.*}} @llvm.fabs
%
O0100(FASTISEL PROBE)
#1=#2+1.5
#3=0
WHILE[#3LT4]DO1
G01X[#1*#3]Y-#3F250.
#3=#3+1
END1
M30
%
