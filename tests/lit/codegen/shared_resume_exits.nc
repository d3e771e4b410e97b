; RUN: %mbc compile %s -o - --emit=llvm -O0 | FileCheck %s
; After an NC block only NEXT has an edge of its own: leaving (M99, the end
; of the run, an alarm) goes to one block per function that maps mbc.resume's
; answer to the status, and an M99 P that cannot come back (no N an M98 can
; return to) to one block that raises PS0128. The M98 block's M99 P goes to
; the landing of N10 (O2000's M99 P10 makes the unit need landings at
; all). (#100 keeps N10 and M30 from being one run of
; constant blocks, codegen/constant_block_runs.nc.)
G00 X1.
M98 P2000
N10 G01 X2. F100
#100 = 1
M30
O2000
M99 P10
; CHECK-LABEL: define internal i32 @mbc.body.MAIN(
; CHECK: [[R1:%[0-9]+]] = call i32 @mbc.resume(ptr %0, ptr %flow, ptr %2)
; CHECK-NEXT: switch i32 [[R1]], label %left [
; CHECK-NEXT: i32 0, label %b1
; CHECK-NEXT: i32 -2, label %m99p
; CHECK: left:
; CHECK-NEXT: %resumed = phi i32 [ [[R1]], %{{[a-z0-9]+}} ], [ {{.*}} ], [ {{.*}} ], [ {{.*}} ]
; CHECK-NEXT: [[LEAVE:%[0-9]+]] = icmp eq i32 %resumed, -3
; CHECK-NEXT: [[STATUS:%[0-9]+]] = select i1 [[LEAVE]], i32 0, i32 %resumed
; CHECK-NEXT: br label %exit
; CHECK: m99p:
; CHECK: call i32 @mbrt_raise_sequence(
; CHECK: [[R2:%[0-9]+]] = call i32 @mbc.resume(ptr %0, ptr %flow, ptr %2)
; CHECK-NEXT: switch i32 [[R2]], label %left [
; CHECK-NEXT: i32 0, label %b2
; CHECK-NEXT: i32 -2, label %[[LANDING:m99p[0-9]+]]
; CHECK: [[LANDING]]:
; CHECK: store double %{{[0-9]+}}, ptr %retseq
; CHECK: [[R3:%[0-9]+]] = call i32 @mbc.resume(ptr %0, ptr %flow, ptr %2)
; CHECK-NEXT: switch i32 [[R3]], label %left [
; CHECK-NEXT: i32 0, label %b3
; CHECK-NEXT: i32 -2, label %m99p
