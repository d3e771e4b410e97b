#!/usr/bin/env bash
# The flattened program of a golden case gives the case's toolpath:
#   gcode_roundtrip.sh MBC CASE.nc
# Runs the case with its .args and --gcode, runs the flattened program on
# the same machine profile, and compares the toolpaths without "line" and
# "prog" (the flattened program is one anonymous main program).
# CASE.flat.args replaces the options of the second run: a profile whose M
# or T codes call programs would call them again from the flattened program,
# which is meant for a control without the macro option.
# A run that ends in an alarm may hold moves for cutter compensation's
# look-ahead that never ran; the flattened program ends before the alarm
# and runs them. There the case's toolpath must be the beginning of the
# flattened program's.
set -u
mbc=$(realpath "$1")
case_path=$2
source "$(dirname "$0")/case_env.sh"
machine=()
for ((i = 0; i < ${#args[@]}; i++)); do
  if [ "${args[i]}" = --machine ]; then
    machine=(--machine "${args[i + 1]}")
  fi
done
"$mbc" run --engine interp "$name.nc" "${args[@]}" --gcode "$work/flat.nc" \
  --toolpath "$work/original.jsonl" --dprnt /dev/null >/dev/null 2>&1
if [ -f "$name.flat.args" ]; then
  mapfile -t machine < <(grep -v '^[[:space:]]*$' "$name.flat.args")
fi
"$mbc" run --engine interp "$work/flat.nc" "${machine[@]}" \
  --toolpath "$work/flat.jsonl" --dprnt /dev/null >/dev/null 2>"$work/stderr"
strip() { sed -E 's/,"line":[0-9]+,"prog":"([^"\\]|\\.)*"//' "$1"; }
if [ -f "$name.status" ]; then
  head -n "$(wc -l <"$work/original.jsonl")" "$work/flat.jsonl" >"$work/begin.jsonl"
  mv "$work/begin.jsonl" "$work/flat.jsonl"
fi
if ! diff -u <(strip "$work/original.jsonl") <(strip "$work/flat.jsonl"); then
  echo "FAIL: $name: the flattened program moves differently"
  echo "--- flattened program:"
  cat "$work/flat.nc"
  cat "$work/stderr"
  exit 1
fi
