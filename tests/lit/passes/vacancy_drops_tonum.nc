; RUN: %mbc emit-ir %s | FileCheck %s
; RUN: %mbc emit-ir --disable-pass vacancy %s | FileCheck %s --check-prefix=OFF
; [#1] in an assignment reads vacant as 0 (tonum). Once #1 is promoted its
; value is an addition, which is never vacant, so the tonum goes; #2 was
; never set here and may be vacant, so its tonum stays.
#1 = #100 + 1
#101 = [#1]
#102 = [#2]
M30
; CHECK-LABEL: func @MAIN
; CHECK: [[V2:%[0-9]+]] = ldvar #2
; CHECK: [[SUM:%[0-9]+]] = add
; CHECK-NOT: tonum [[SUM]]{{$}}
; CHECK: stvar #101, [[SUM]]{{$}}
; CHECK: [[N2:%[0-9]+]] = tonum [[V2]]{{$}}
; CHECK-NEXT: stvar #102, [[N2]]{{$}}
; OFF-LABEL: func @MAIN
; OFF: [[SUM:%[0-9]+]] = add
; OFF: tonum [[SUM]]{{$}}
