; RUN: %mbc emit-ir %s | FileCheck %s
; RUN: %mbc emit-ir --disable-pass loadelim %s | FileCheck %s --check-prefix=OFF
; Within a block a common variable is read once: #102 * #102 loads it once,
; and #100 takes the value just stored (then 5 * 5 folds). An indirect store
; may write any variable, so #102 is read again after it.
#100 = 5
#101 = [#100 * #100] + [#102 * #102]
#[#101] = 1
#103 = #102
M30
; CHECK-LABEL: func @MAIN
; CHECK-NOT: ldvar #100
; CHECK: [[B:%[0-9]+]] = ldvar #102
; CHECK-NEXT: [[N:%[0-9]+]] = tonum [[B]]{{$}}
; CHECK-NEXT: [[BB:%[0-9]+]] = mul [[N]], [[N]]{{$}}
; CHECK: stind
; CHECK: [[C:%[0-9]+]] = ldvar #102
; CHECK-NEXT: stvar #103, [[C]]{{$}}
; OFF-LABEL: func @MAIN
; OFF: ldvar #100
; OFF: ldvar #102
; OFF: ldvar #102
