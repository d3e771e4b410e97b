; RUN: %mbc compile %s -o - --emit=llvm -O0 | FileCheck %s
; RUN: %mbc compile %s -o - --emit=llvm -O0 | grep -c "call i32 @mbrt_block_limit(" | FileCheck --check-prefix=ONE %s
; RUN: %mbc compile %s -o - --emit=llvm -O0 | grep -c "call i32 @mbrt_raise(" | FileCheck --check-prefix=ONE %s
; The checks of a statement (the execution limit of its block, then the
; overflow of each operation) are gathered into one branch before its first
; effect; the key of the first that holds picks the alarm in the block that
; every such branch of the function shares. A block alone (M30) branches
; straight to the shared execution-limit exit, and a runtime status goes
; straight to the exit. A block and an exit edge per check made LLVM's time
; grow with them.
#1 = #2 + 1
#3 = #4 + 2
#5 = #1 * #3
M30
; CHECK-LABEL: define internal i32 @mbc.body.MAIN(
; CHECK: [[LIMIT:%[0-9]+]] = icmp ugt i64
; CHECK: [[POSITIVE:%[0-9]+]] = fcmp oeq double [[SUM:%[0-9]+]], 0x7FF0000000000000
; CHECK-NEXT: [[NEGATIVE:%[0-9]+]] = fcmp oeq double [[SUM]], 0xFFF0000000000000
; CHECK-NEXT: [[OVERFLOW:%[0-9]+]] = or i1 [[POSITIVE]], [[NEGATIVE]]
; CHECK-NEXT: [[KEY:%[0-9]+]] = select i1 [[LIMIT]], i32 -1, i32 11
; CHECK-NEXT: [[ANY:%[0-9]+]] = or i1 [[LIMIT]], [[OVERFLOW]]
; CHECK-NEXT: br i1 [[ANY]], label %[[FAIL:fail]], label %cont
; CHECK: [[FAIL]]:
; CHECK-NEXT: %alarm = phi i32 [ [[KEY]], %b ], [ %{{[0-9]+}}, %cont ], [ %{{[0-9]+}}, %cont{{[0-9]+}} ]
; CHECK-NEXT: [[ISLIMIT:%[0-9]+]] = icmp eq i32 %alarm, -1
; CHECK-NEXT: br i1 [[ISLIMIT]], label %[[LIMITEXIT:fail[0-9]+]], label %raise
; CHECK: raise:
; CHECK-NEXT: call i32 @mbrt_raise(ptr %0, i32 %alarm, ptr null)
; CHECK: [[LIMITEXIT]]:
; CHECK-NEXT: call i32 @mbrt_block_limit(
; CHECK: store i32 14, ptr
; CHECK: [[ALONE:%[0-9]+]] = icmp ugt i64
; CHECK-NEXT: br i1 [[ALONE]], label %[[LIMITEXIT]], label %cont
; CHECK: call i32 @mbrt_nc_block(
; CHECK-NEXT: icmp ne i32
; CHECK-NEXT: br i1 %{{[0-9]+}}, label %exit, label %cont
; ONE: {{^1$}}
