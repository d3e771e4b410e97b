; RUN: %mbc compile -c %s -o %t.o --header %t.h
; RUN: sed -e 's/^ \* //' %t.h | tr '\n' ' ' | FileCheck %s
; The header says which G65 arguments each entry point's program reads:
; its own reads of #1-#33 and those of the M98 subprograms it calls (they
; share its locals), not those of a G65 macro (locals of its own), and a
; computed variable number makes the list uncertain.
O4640(FACE MILL - X Y W WIDTH F)
G90G00X#24Y#25
M98P4641
G65P4642A1.
M30
O4641(PASSES)
#30=#23/2
G01X[#24+#30]F#9
M99
O4642(SPOT - ITS OWN A)
#100=#1+#[#100]
M99
O4643(NOTHING)
G00Z50.
M99
; CHECK: O4640 ({{[^)]*}}header_arguments.nc): runs it as the main program,
; CHECK-SAME: The arguments it reads: F (#9), W (#23), X (#24), Y (#25). */ mbrt_status mbc_O4640(
; CHECK-SAME: O4641 ({{[^*]*}}The arguments it reads: F (#9), W (#23), X (#24). */ mbrt_status mbc_O4641(
; CHECK-SAME: O4642 ({{[^*]*}}The arguments it reads: A (#1), and maybe others by a computed number. */
; CHECK-SAME: O4643 ({{[^*]*}}It reads no argument. */
