O1024 (FINISH PASS)
(Found by fuzz_frontend: a diagnostic inside the value of 'Z = ...')
(moved the stored ones while the error's fix-it was being added)
#101 = -10.
G01 Z = #101 + 0.0z F100.
M30
