; RUN: %mbc compile %s -o - --emit=llvm -O0 | FileCheck %s
; NC blocks whose words are all constants, one after the other, are one run:
; a table of steps (line, words, first word), the words' letters and kinds,
; their values, executed by one mbrt_nc_steps call in a loop that hands a
; step's call or end to mbc.resume. No code per block, so that a posted
; program of a million blocks compiles in seconds. A block that a GOTO or an
; M99 P can land on starts a new run; a block with a variable is not in one.
G90 G01 F100
X1. Y-2.5
X3
N20 X4.
X5. Y6.
X#100
IF [#101 EQ 1] GOTO 20
M30
; CHECK: @.steps = private unnamed_addr constant [9 x i32] [i32 8, i32 3, i32 0, i32 9, i32 2, i32 3, i32 10, i32 1, i32 5]
; CHECK: @.codes = private unnamed_addr constant [12 x i8] c"G\00G\00F\00X\01Y\01X\00"
; CHECK: @.values = private unnamed_addr constant [6 x double] [double 9.000000e+01, double 1.000000e+00, double 1.000000e+02, double 1.000000e+00, double -2.500000e+00, double 3.000000e+00]
; CHECK: @.run = private unnamed_addr constant %mbrt_nc_run { ptr @.str{{.*}}, ptr @.steps, ptr @.codes, ptr @.values, i64 3 }
; CHECK: @.steps.{{[0-9]+}} = private unnamed_addr constant [6 x i32] [i32 11, i32 2, i32 0, i32 12, i32 2, i32 2]
; CHECK: @.codes.{{[0-9]+}} = private unnamed_addr constant [8 x i8] c"N\00X\01X\01Y\01"
; CHECK-LABEL: define internal i32 @mbc.body.MAIN(
; CHECK-NOT: @mbrt_nc_block(ptr %0, ptr @
; CHECK: steps:
; CHECK-NEXT: %step = phi i64 [ 0, %b ], [ %after, %stepped ]
; CHECK-NEXT: [[ST:%[0-9]+]] = call i32 @mbrt_nc_steps(ptr %0, ptr @.run, i64 %step, ptr %flow, ptr [[NEXT:%[0-9]+]])
; CHECK: %after = load i64, ptr [[NEXT]]
; CHECK-NEXT: [[R:%[0-9]+]] = call i32 @mbc.resume(ptr %0, ptr %flow, ptr %2)
; CHECK-NEXT: switch i32 [[R]], label %left [
; CHECK-NEXT: i32 0, label %stepped
; CHECK-NEXT: i32 -2, label %m99p
; CHECK: stepped:
; CHECK-NEXT: [[ALL:%[0-9]+]] = icmp eq i64 %after, 3
; CHECK-NEXT: br i1 [[ALL]], label %b{{[0-9]+}}, label %steps
; CHECK: call i32 @mbrt_nc_steps(ptr %0, ptr @.run.{{[0-9]+}},
