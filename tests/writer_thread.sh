#!/usr/bin/env bash
# The toolpath written on its own thread (--writer-thread on) against the
# toolpath the run writes itself (--writer-thread off): the same records,
# the same DPRNT text, the same alarm at the same block and the same
# status, under output limits that fall on motions, on DPRNT lines and
# nowhere, under the block limit and under an alarm of the program's. The
# program makes more moves than the writer's ring holds, so that the run
# waits for room. An option that cannot apply is refused. auto uses the
# thread only with a second core the process may run on (taskset).
#   writer_thread.sh MBC
source "$(dirname "$0")/script_env.sh" "$1"
cat >passes.nc <<'NC'
%
O2100(PASSES WITH A REPORT)
G21G90G17G54
G00X0Y0Z5.
#1=0
WHILE[#1LT12000]DO1
G01X[#1MOD97]Y[#1MOD89]F1200.
IF[[#1MOD7]EQ0]THEN#2=1
IF[#1EQ#100]THEN#3000=7(STOPPED AT PASS)
DPRNT[PASS*#1[40]*X*#5041[43]]
G02X[#1MOD97+2.]Y[#1MOD89]R1.
#1=#1+1
END1
M30
%
NC
status=0
for limit in 1000 4097 65536 150001 300007 1500001 0; do
  for extra in "" "--max-blocks 5000" "--set #100=2500"; do
    [ "$limit" != 0 ] && extra="$extra --max-output $limit"
    # shellcheck disable=SC2086
    "$mbc" run passes.nc --engine interp --toolpath thread.jsonl \
      --writer-thread on --dprnt thread.txt $extra 2>thread.err
    threaded=$?
    # shellcheck disable=SC2086
    "$mbc" run passes.nc --engine interp --toolpath inline.jsonl \
      --writer-thread off --dprnt inline.txt $extra 2>inline.err
    inline=$?
    if [ "$threaded" != "$inline" ] || ! cmp -s thread.jsonl inline.jsonl ||
      ! cmp -s thread.txt inline.txt ||
      ! diff -q <(grep alarm thread.err) <(grep alarm inline.err) >/dev/null; then
      echo "FAIL: limit $limit $extra: status $threaded/$inline"
      diff <(grep alarm thread.err) <(grep alarm inline.err)
      status=1
    fi
    # Every case but the first stops at an alarm: the case is what it says.
    if [ "$limit$extra" != 0 ] && ! grep -q alarm thread.err; then
      echo "FAIL: limit $limit $extra: no alarm: $(cat thread.err)"
      status=1
    fi
  done
done
for refused in "--writer-thread on --toolpath -" "--writer-thread off" \
  "--writer-thread always --toolpath refused.jsonl"; do
  # shellcheck disable=SC2086
  if "$mbc" run passes.nc $refused >/dev/null 2>refused.err ||
    ! grep -q "writer-thread" refused.err; then
    echo "FAIL: $refused: $(cat refused.err)"
    status=1
  fi
done
# When it is used: --time says so. auto takes a second core the process
# may run on, and never standard output.
thread_used() { # expected, then mbc run's options
  local expected=$1
  shift
  "$mbc" run passes.nc --engine interp --time --dprnt /dev/null "$@" \
    >/dev/null 2>used.err
  if grep -q "run [0-9.]* ms (the toolpath on a writer thread)" used.err; then
    used=yes
  else
    used=no
  fi
  if [ "$used" != "$expected" ]; then
    echo "FAIL: $*: writer thread $used: $(tail -1 used.err)"
    status=1
  fi
}
thread_used yes --toolpath used.jsonl --writer-thread on
thread_used no --toolpath used.jsonl --writer-thread off
thread_used no --toolpath -
thread_used no --toolpath /dev/null --writer-thread off
if command -v taskset >/dev/null; then
  taskset -c 0 bash -c "$(declare -f thread_used); mbc=$mbc status=0; \
    thread_used no --toolpath used.jsonl; \
    thread_used yes --toolpath used.jsonl --writer-thread on; exit \$status" ||
    status=1
  if [ "$(nproc --all)" -gt 1 ]; then
    taskset -c 0,1 bash -c "$(declare -f thread_used); mbc=$mbc status=0; \
      thread_used yes --toolpath used.jsonl; exit \$status" || status=1
  fi
fi
[ "$status" = 0 ] && echo "ok: the writer thread wrote what the run writes itself"
exit $status
