; RUN: %mbc compile %s -o - --emit=llvm -O0 | FileCheck %s
; RUN: %mbc compile %s -o - --emit=llvm -O0 | grep -c "call i32 @mbrt_block_limit(" | FileCheck --check-prefix=ONE %s
; RUN: %mbc compile %s -o - --emit=llvm -O0 | grep -c "call i32 @mbrt_raise(" | FileCheck --check-prefix=ONE %s
; Every check of a function that fails the same way branches to one shared
; block: the execution limit of the four blocks shares one, the three
; overflow checks another, and a runtime status goes straight to the exit.
; A block and an exit edge per check made LLVM's time grow with them.
#1 = #2 + 1
#3 = #4 + 2
#5 = #1 * #3
M30
; CHECK-LABEL: define internal i32 @mbc.body.MAIN(
; CHECK: br i1 %{{[0-9]+}}, label %[[LIMIT:fail[0-9]*]], label %cont
; CHECK: [[LIMIT]]:
; CHECK-NEXT: call i32 @mbrt_block_limit(
; CHECK: br i1 %{{[0-9]+}}, label %[[OVERFLOW:fail[0-9]*]], label %cont
; CHECK: [[OVERFLOW]]:
; CHECK-NEXT: call i32 @mbrt_raise(ptr %0, i32 11, ptr null)
; CHECK: br i1 %{{[0-9]+}}, label %[[LIMIT]], label %cont
; CHECK: br i1 %{{[0-9]+}}, label %[[OVERFLOW]], label %cont
; CHECK: call i32 @mbrt_nc_block(
; CHECK-NEXT: icmp ne i32
; CHECK-NEXT: br i1 %{{[0-9]+}}, label %exit, label %cont
; ONE: {{^1$}}
