; RUN: %mbc compile -g -O0 %s -o - --emit=llvm | FileCheck %s
; RUN: %mbc compile -g -O2 %s -o %t.o --emit=obj
; RUN: llvm-dwarfdump --debug-line %t.o | FileCheck %s --check-prefix=LINES
; RUN: %mbc compile %s -o - --emit=llvm | FileCheck %s --check-prefix=NODEBUG
; -g: one compile unit, a subprogram per program named after it, and the
; code of each block at its .nc line, so that gdb shows the source.
O1000
#1 = 5
G65 P9100 A#1
M30
O9100
#100 = #1 * 2
M99
; CHECK: define internal i32 @mbc.body.O1000({{.*}}) #{{[0-9]+}} !dbg ![[O1000:[0-9]+]] {
; CHECK: call i32 @mbc.call(ptr %0, double 9.100000e+03, {{.*}}), !dbg ![[G65:[0-9]+]]
; CHECK: define internal i32 @mbc.body.O9100({{.*}}) #{{[0-9]+}} !dbg ![[O9100:[0-9]+]] {
; CHECK: fmul double %{{[0-9]+}}, 2.000000e+00, !dbg ![[MUL:[0-9]+]]
; The glue that calls bodies has artificial subprograms, as the verifier
; wants of every inlinable call in a function with debug info.
; CHECK: define internal i32 @mbc.call({{.*}}) #{{[0-9]+}} !dbg ![[CALL:[0-9]+]] {
; CHECK: call i32 @mbrt_run_call({{.*}}), !dbg
; CHECK: define i32 @mbc_O1000({{.*}}) #{{[0-9]+}} !dbg ![[ENTRY:[0-9]+]] {
; CHECK: !llvm.dbg.cu = !{![[CU:[0-9]+]]}
; CHECK-DAG: !{i32 2, !"Debug Info Version", i32 3}
; CHECK-DAG: !{i32 7, !"Dwarf Version", i32 4}
; CHECK-DAG: ![[CU]] = distinct !DICompileUnit(language: DW_LANG_C, file: ![[FILE:[0-9]+]], producer: "mbc",
; CHECK-DAG: ![[FILE]] = !DIFile(filename: "debug_info.nc", directory: "{{.+}}")
; CHECK-DAG: ![[O1000]] = distinct !DISubprogram(name: "O1000", linkageName: "mbc.body.O1000", scope: ![[FILE]], file: ![[FILE]], line: 8,
; CHECK-DAG: ![[G65]] = !DILocation(line: 9, scope: ![[O1000]])
; CHECK-DAG: ![[O9100]] = distinct !DISubprogram(name: "O9100", linkageName: "mbc.body.O9100", scope: ![[FILE]], file: ![[FILE]], line: 12,
; CHECK-DAG: ![[MUL]] = !DILocation(line: 12, scope: ![[O9100]])
; CHECK-DAG: ![[CALL]] = distinct !DISubprogram(name: "mbc.call", {{.*}}flags: DIFlagArtificial
; CHECK-DAG: ![[ENTRY]] = distinct !DISubprogram(name: "mbc_O1000", {{.*}}line: 8, {{.*}}flags: DIFlagArtificial
; LINES: file_names[{{ *}}1]:
; LINES-NEXT: name: "debug_info.nc"
; LINES: Address Line Column File
; LINES-DAG: 0x{{[0-9a-f]+}} 9 0 1
; LINES-DAG: 0x{{[0-9a-f]+}} 12 0 1
; NODEBUG-NOT: !dbg
; NODEBUG-NOT: !DICompileUnit
