#!/usr/bin/env bash
# --state: the nonvolatile variables and offsets last from run to run, are
# written after an alarm too, and a bad state file stops the run without
# touching the file.
#   state_file.sh MBC
source "$(dirname "$0")/script_env.sh" "$1"
cat >count.nc <<'NC'
IF [#500 EQ #0] THEN #500 = 0
#500 = #500 + 1
#5221 = #5221 - 1.
#11001 = #11001 + 10.
G10 L20 P2 X#500
IF [#500 EQ 3] THEN #3000 = 1 (THIRD RUN)
M30
NC
for run in 1 2 3; do
  "$mbc" run count.nc --state state.json 2>/dev/null
done
[ $? -eq 3 ] || fail "the third run should alarm"
grep -q '"500": 3.0' state.json || fail "#500 after three runs: $(cat state.json)"
grep -q '"h_geometry": 30.0' state.json || fail "H1 geometry: $(cat state.json)"
tr -d ' \n' <state.json | grep -q '"G54":\[-3.0,0.0,0.0\]' ||
  fail "G54: $(cat state.json)"
tr -d ' \n' <state.json | grep -q '"G54.1P2":\[3.0,0.0,0.0\]' ||
  fail "G54.1 P2: $(cat state.json)"
[ ! -e state.json.tmp ] || fail "a temporary file was left"
# A bad file: exit 2, nothing run, the file as it was.
echo '{"variables": {"100": 1}}' >bad.json
cp bad.json before.json
"$mbc" run count.nc --state bad.json 2>err
[ $? -eq 2 ] || fail "a bad state file should stop the run"
grep -q "state file 'bad.json'" err || fail "message: $(cat err)"
cmp -s bad.json before.json || fail "the bad file was changed"
echo '{"tool_offsets": {"1": {"h_geom": 1}}}' >bad.json
"$mbc" run count.nc --state bad.json 2>err
grep -q 'unknown key "tool_offsets.1.h_geom"' err || fail "message: $(cat err)"
echo ok
