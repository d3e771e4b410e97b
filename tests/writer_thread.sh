#!/usr/bin/env bash
# The toolpath written on its own thread (--writer-thread on) against the
# toolpath the run writes itself (--writer-thread off): the same records,
# the same DPRNT text, the same alarm at the same block and the same
# status, under output limits that fall on motions, on DPRNT lines and
# nowhere, under the block limit and under an alarm of the program's. The
# same for the SVG drawing and the HTML page, made on the thread with the
# toolpath or without it. The program makes more moves than the writer's
# ring holds, so that the run waits for room. An option that cannot apply
# is refused. auto uses the thread only with a second core the process may
# run on (taskset), and never for a toolpath on standard output.
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
# Runs the program with the thread and without, and compares what each run
# wrote (every out.* file), DPRNT, the status and the alarm. Every case
# with a limit or an alarm must stop at one: the case is what it says.
matches_inline() { # the outputs' options, the output limit (0: none), more
  local outputs=$1 limit=$2 extra=$3 mode results=()
  [ "$limit" != 0 ] && extra="$extra --max-output $limit"
  for mode in on off; do
    rm -f out.*
    # shellcheck disable=SC2086
    "$mbc" run passes.nc --engine interp $outputs --writer-thread $mode \
      --dprnt out.txt $extra 2>out.err
    echo "status $?" >>out.txt
    results+=("$(cat out.*)")
  done
  if [ "${results[0]}" != "${results[1]}" ]; then
    echo "FAIL: $outputs, limit $limit $extra: the thread's outputs differ"
    diff <(echo "${results[0]}") <(echo "${results[1]}") | head -5
    status=1
  fi
  if [ "$limit$extra" != 0 ] && ! grep -q alarm out.err; then
    echo "FAIL: $outputs, limit $limit $extra: no alarm: $(cat out.err)"
    status=1
  fi
}
for limit in 1000 4097 65536 150001 300007 1500001 0; do
  for extra in "" "--max-blocks 5000" "--set #100=2500"; do
    matches_inline "--toolpath out.jsonl" "$limit" "$extra"
  done
done
# The pictures: with the toolpath, and alone. The page needs three.js,
# which a build may lack.
pictures="--svg out.svg"
printf '%%\nO2101\nG00X1.\nM30\n%%\n' >probe.nc
if "$mbc" run probe.nc --html probe.html >/dev/null 2>&1; then
  pictures="$pictures --html out.html"
fi
for outputs in "--toolpath out.jsonl $pictures" "$pictures"; do
  for limit in 4097 150001 1500001 0; do
    for extra in "" "--set #100=2500"; do
      matches_inline "$outputs" "$limit" "$extra"
    done
  done
done
for refused in "--writer-thread on --toolpath -" "--writer-thread off" \
  "--writer-thread on --toolpath - --svg refused.svg" \
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
thread_used() { # what the thread makes ("the toolpath", no), then options
  local expected=$1
  shift
  "$mbc" run passes.nc --engine interp --time --dprnt /dev/null "$@" \
    >/dev/null 2>used.err
  used=$(sed -n 's/.* run [0-9.]* ms (\(.*\) on a writer thread)$/\1/p' \
    used.err)
  if [ "${used:-no}" != "$expected" ]; then
    echo "FAIL: $*: writer thread ${used:-no}: $(tail -1 used.err)"
    status=1
  fi
}
thread_used "the toolpath" --toolpath used.jsonl --writer-thread on
thread_used no --toolpath used.jsonl --writer-thread off
thread_used no --toolpath -
thread_used no --toolpath /dev/null --writer-thread off
thread_used "the toolpath, the SVG" --toolpath used.jsonl --svg used.svg \
  --writer-thread on
thread_used "the SVG" --svg used.svg --writer-thread on
if command -v taskset >/dev/null; then
  taskset -c 0 bash -c "$(declare -f thread_used); mbc=$mbc status=0; \
    thread_used no --toolpath used.jsonl --svg used.svg; \
    thread_used 'the toolpath' --toolpath used.jsonl --writer-thread on; \
    exit \$status" || status=1
  if [ "$(nproc --all)" -gt 1 ]; then
    taskset -c 0,1 bash -c "$(declare -f thread_used); mbc=$mbc status=0; \
      thread_used 'the toolpath' --toolpath used.jsonl; \
      thread_used 'the SVG' --toolpath - --svg used.svg; exit \$status" ||
      status=1
  fi
fi
[ "$status" = 0 ] && echo "ok: the writer thread wrote what the run writes itself"
exit $status
