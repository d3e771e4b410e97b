#!/usr/bin/env bash
# SIGINT or SIGTERM stops a run before its next block with alarm MBC0004:
# the exit status is the shell's 128+signal, every toolpath record and DPRNT
# line written is whole and on disk (the toolpath's on the writer thread
# too), and the state file is saved. Under each
# engine and in an executable of `mbc build`; the loop that calls nothing
# must stop too (compiled code cannot keep the block limit in a register).
#   interrupt.sh MBC
source "$(dirname "$0")/script_env.sh" "$1"
# Each program first shows a message, so that the signal comes once the run
# has started, however long the machine takes to start mbc and compile. Its
# loop never ends by itself (no axis word grows past its digits): an
# executable of `mbc build` writes a million passes in less than the time
# the signal takes to come.
cat >writes.nc <<'NC'
O1000
#3006 = 1 (STARTED)
G90 G01 F1000
#1 = 0
WHILE [1 GT 0] DO1
#1 = #1 + 1
X[#1 MOD 100] Y[#1 MOD 1000]
DPRNT[PASS*#1[90]]
#500 = #1
END1
M30
NC
cat >spins.nc <<'NC'
O1000
#3006 = 1 (STARTED)
#1 = 0
WHILE [1 GT 0] DO1
#1 = #1 + 1
END1
M30
NC
"$mbc" build writes.nc -o writes.exe || fail "mbc build"

# interrupt NAME SIGNAL COMMAND...: runs COMMAND, sends SIGNAL a moment
# after the run has started, and checks how it ended (at most 10 s later).
interrupt() {
  local name=$1 sig=$2
  shift 2
  "$@" --max-blocks 1e15 2>"$name.err" &
  local pid=$!
  local started=0
  until grep -q "message: STARTED" "$name.err" 2>/dev/null; do
    ((started++ < 600)) || { kill -9 "$pid"; fail "$name: did not start"; }
    sleep 0.1
  done
  sleep 0.2
  kill "-$sig" "$pid"
  local waited=0
  while kill -0 "$pid" 2>/dev/null; do
    ((waited++ < 100)) || { kill -9 "$pid"; fail "$name: did not stop"; }
    sleep 0.1
  done
  wait "$pid"
  status=$?
  local expected=$((128 + $(kill -l "$sig")))
  [ "$status" -eq "$expected" ] ||
    fail "$name: status $status, not $expected: $(cat "$name.err")"
  grep -q "alarm MBC0004: INTERRUPTED: the run was stopped before this block" \
    "$name.err" || fail "$name: $(cat "$name.err")"
}

whole() { # name: the outputs end with whole records, the state is saved
  local name=$1
  [ -s "$name.dprnt" ] || fail "$name: no DPRNT output"
  [ "$(tail -c1 "$name.dprnt" | od -An -c | tr -d ' ')" = '\n' ] ||
    fail "$name: the DPRNT output ends in a partial line"
  # Each pass moves, then prints: every move before the stop is written.
  python3 -c '
import json, sys
lines = open(sys.argv[1]).read().split("\n")
assert lines[-1] == "", "partial last record"
for line in lines[:-1]:
    json.loads(line)
last = int(open(sys.argv[2]).read().split()[-1])
assert len(lines) - 1 in (last, last + 1), (len(lines) - 1, last)
' "$name.jsonl" "$name.dprnt" ||
    fail "$name: the toolpath has a partial record or lacks some"
  grep -q '"500": [1-9]' "$name.state" || fail "$name: state $(cat "$name.state")"
}

# SIGINT with the toolpath written on a thread of its own, SIGTERM without.
for engine in interp ir jit; do
  for sig in INT TERM; do
    name=$engine-$sig
    writer=on
    [ "$sig" = TERM ] && writer=off
    interrupt "$name" "$sig" "$mbc" run --engine "$engine" writes.nc \
      --toolpath "$name.jsonl" --writer-thread $writer --dprnt "$name.dprnt" \
      --state "$name.state"
    whole "$name"
  done
  interrupt "$engine-spin" INT "$mbc" run --engine "$engine" -O2 spins.nc
done
interrupt aot INT ./writes.exe --toolpath aot.jsonl --dprnt aot.dprnt \
  --state aot.state
whole aot

# A batch: the rows running stop, no other row starts, results.csv keeps
# the rows that ran. Rows 1 and 2 end at once, rows 3 on spin.
cat >rows.nc <<'NC'
O1000
IF [#500 LT 3] GOTO 10
WHILE [1 GT 0] DO1
#1 = #1 + 1
END1
N10 DPRNT[ROW*#500[20]]
M30
NC
printf '#500\n1\n2\n3\n4\n5\n6\n' >rows.csv
"$mbc" batch rows.nc --params rows.csv --out rows -j 2 --max-blocks 1e15 2>rows.err &
pid=$!
waited=0
until [ "$(cat rows/results.csv 2>/dev/null | wc -l)" = 3 ]; do
  ((waited++ < 600)) || { kill -9 "$pid"; fail "batch: rows 1 and 2 did not end"; }
  sleep 0.1
done
sleep 0.2
kill -INT "$pid"
wait "$pid"
status=$?
[ "$status" = 130 ] || fail "batch: status $status: $(cat rows.err)"
[ "$(cut -d, -f1,3 rows/results.csv | tr '\n' ' ')" = \
  "id,status 1,ended 2,ended 3,interrupted 4,interrupted " ] ||
  fail "batch: $(cat rows/results.csv)"
grep -q "2 ended, 0 alarms, 2 interrupted;" rows.err &&
  grep -q "interrupted; 2 of the rows did not run" rows.err || fail "batch: $(cat rows.err)"
grep -qx "ROW *2" rows/2.dprnt || fail "batch: row 2's DPRNT"
echo ok
