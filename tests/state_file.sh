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

# A run that ends in G20 on a metric machine saves millimetres: three such
# runs leave G54 where the profile put it, to the last digit.
echo '{"work_offsets": {"G54": [-250, -123.457, 0.001]}}' >metric.json
cat >inch.nc <<'NC'
G21
#101=#5221
G20
G91G01X0.1F10.
M30
NC
for run in 1 2 3; do
  "$mbc" run inch.nc --machine metric.json --state inch.json \
    --vars-out inch.vars 2>/dev/null || fail "inch run $run"
done
grep -q '"101":-250[,}]' inch.vars || fail "G54 X after three inch runs: $(cat inch.vars)"
tr -d ' \n' <inch.json | grep -q '"unit":"mm"' || fail "unit: $(cat inch.json)"
tr -d ' \n' <inch.json | grep -q '"G54":\[-250.0,-123.457,0.001\]' ||
  fail "G54 after inch runs: $(cat inch.json)"
# A lathe saves its own offsets (geometry through G10 P10000+n) by the
# profile's names, and gets them back.
echo '{"series": "T"}' >lathe.json
cat >lathe.nc <<'NC'
IF[#500EQ#0]GOTO10
#501=#15003
#502=#10003
M30
N10G10P10003X-10.25Z5.5R0.4Q3
G10P3X0.12
#500=1
M30
NC
for run in 1 2; do
  "$mbc" run lathe.nc --machine lathe.json --state lathe-state.json \
    --vars-out lathe.vars 2>/dev/null || fail "lathe run $run"
done
grep -q '"501":-10.25,"502":0.12' lathe.vars || fail "lathe offsets: $(cat lathe.vars)"
tr -d ' \n' <lathe-state.json |
  grep -q '"3":{"r_geometry":0.4,"tip":3.0,"x_geometry":-10.25,"x_wear":0.12,"z_geometry":5.5}' ||
  fail "lathe state: $(cat lathe-state.json)"
! grep -q 'G54.1' lathe-state.json || fail "a lathe's offsets as work offsets: $(cat lathe-state.json)"
# A file of another machine stops the run.
"$mbc" run count.nc --state lathe-state.json 2>err
[ $? -eq 2 ] && grep -q '"series": "T": the file is for another machine' err ||
  fail "a lathe's file on a mill: $(cat err)"
echo '{"unit": "inch"}' >other-unit.json
"$mbc" run count.nc --state other-unit.json 2>err
[ $? -eq 2 ] && grep -q '"unit": "inch": the file is for another machine (this one.s is "mm")' err ||
  fail "an inch file on a metric machine: $(cat err)"
echo ok
