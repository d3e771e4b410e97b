#!/usr/bin/env bash
# The --state file is the old complete file or the new one whenever a run is
# killed (SIGKILL, no chance to clean up), at random moments of the run
# including the save.
#   state_kill.sh MBC [KILLS]
source "$(dirname "$0")/script_env.sh" "$1"
kills=${2:-40}
# Every run writes its pass number into all of #500-#999 (F is #9) and the work
# offsets, so a file mixing two runs shows.
cat >pass.nc <<'NC'
O1000
#1 = 500
WHILE [#1 LE 999] DO1
#[#1] = #9
#1 = #1 + 1
END1
G10 L2 P1 X#9 Y#9 Z#9
M30
NC
"$mbc" build pass.nc -o pass.exe || fail "mbc build"
./pass.exe --arg F=0 --state state.json 2>/dev/null || fail "first run"
start=$(date +%s%N)
./pass.exe --arg F=0 --state timing.json 2>/dev/null
run_us=$((($(date +%s%N) - start) / 1000))
for ((k = 1; k <= kills; k++)); do
  cp state.json old.json
  ./pass.exe --arg F=$k --state new.json 2>/dev/null || fail "run $k"
  ./pass.exe --arg F=$k --state state.json 2>/dev/null &
  pid=$!
  # a moment anywhere in the run, up to 20% past its usual end
  delay=$((RANDOM * RANDOM % (run_us * 12 / 10 + 1)))
  sleep "$(printf '0.%06d' "$delay")"
  kill -9 "$pid" 2>/dev/null
  wait "$pid" 2>/dev/null
  cmp -s state.json old.json || cmp -s state.json new.json ||
    fail "kill $k after ${delay} us: the state file is neither the old nor the new one"
  [ "$(cat new.json)" != "$(cat old.json)" ] || fail "run $k changed nothing"
  rm -f new.json
done
echo "ok: $kills kills, a run takes ${run_us} us"
