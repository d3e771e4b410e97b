; RUN: %mbc emit-ir --no-opt --no-strict %s 2>%t.err | FileCheck %s
; RUN: FileCheck --check-prefix=WARN %s < %t.err
; RUN: %mbc emit-ir --no-opt --no-strict %s 2>/dev/null > %t.mbir
; RUN: %mbc emit-ir --no-opt -x mbir %t.mbir | FileCheck %s
; A block that cannot be read keeps its place and raises its alarm when it
; runs; the blocks around it are lowered as usual.
#1 = 1
#2 = [#1 +]
M30
; CHECK-LABEL: func @MAIN
; CHECK: begin 8
; CHECK-NEXT: raise PS0114, "expected an expression, found ']'"
; CHECK: begin 9
; WARN: 8:11: warning: expected an expression, found ']'
; WARN: 8:11: note: this block raises alarm PS0114 ILLEGAL EXPRESSION FORMAT when it runs
