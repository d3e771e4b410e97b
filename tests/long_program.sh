#!/usr/bin/env bash
# docs/robustness.md: a 100 000-line posted program, 2 000 blocks with a
# variable each and a chain of 2 000 IF-GOTOs run under every engine in
# bounded memory, with the same toolpath; out of memory is reported, not an
# abort. MEMORY_KB: the address-space limit (0: none, as under ASan).
#   long_program.sh MBC MEMORY_KB
source "$(dirname "$0")/script_env.sh" "$1"
memory=$2
python3 - <<'PY'
import random
r = random.Random(7)
with open("posted.nc", "w") as f:
    f.write("O1000\nG90 G17 G21 G01 F2000\n")
    for i in range(100000):
        f.write(f"X{r.uniform(-100, 100):.3f} Y{r.uniform(-100, 100):.3f}\n")
    f.write("M30\n")
with open("computed.nc", "w") as f:
    f.write("O1000\nG90 G01 F2000\n#100 = 0\n")
    for i in range(2000):
        f.write(f"X[#100 + {i % 97}.5] Y{i % 13}.\n")
    f.write("M30\n")
with open("chain.nc", "w") as f:
    f.write("O1000\nG90 G01 F2000\n#100 = 0\n")
    for i in range(1, 2001):
        f.write(f"N{i} IF [#100 GE {i}] GOTO {i + 1}\n#100 = #100 + 1\n")
        f.write(f"X#100\n")
    f.write("N2001 M30\n")
PY
[ "$memory" -gt 0 ] && ulimit -v "$memory"
for program in posted computed chain; do
  for engine in interp ir jit; do
    timeout 120 "$mbc" run --engine "$engine" "$program.nc" \
      --toolpath "$program.$engine.jsonl" 2>"$program.$engine.err" ||
      fail "$program under $engine: $(tail -3 "$program.$engine.err")"
  done
  cmp -s "$program.interp.jsonl" "$program.jit.jsonl" ||
    fail "$program: the JIT's toolpath differs"
  cmp -s "$program.interp.jsonl" "$program.ir.jsonl" ||
    fail "$program: the IR evaluator's toolpath differs"
done
grep -q "O1000: 100002 blocks, 100000 moves, 0 alarms" posted.jit.err ||
  fail "$(cat posted.jit.err)"
# Out of memory is a message and status 4, not an abort.
if [ "$memory" -gt 0 ]; then
  python3 -c "print('O1\n' + '#1 = 1\n' * 3000000 + 'M30')" >huge.nc
  (ulimit -v 400000 && "$mbc" check huge.nc 2>huge.err)
  status=$?
  [ "$status" -eq 4 ] && grep -q "^mbc: error: out of memory$" huge.err ||
    fail "3 000 000 lines in 400 MB: status $status, $(tail -2 huge.err)"
fi
echo ok
