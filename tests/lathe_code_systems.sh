#!/usr/bin/env bash
# The same part written in G code systems A, B and C (the golden programs
# lathe_system_{a,b,c}_cycles) moves the same way: only the code numbers
# differ, and the cycle words U, W and R of G71-G73 mean the same in all
# three (in B and C, where U and W are no axes).
#   lathe_code_systems.sh MBC SOURCE_DIR
src=$(realpath "$2")/tests/programs
source "$(dirname "$0")/script_env.sh" "$1"
for s in a b c; do
  "$mbc" run "$src/lathe_system_${s}_cycles.nc" \
    --machine "$src/lathe_system_${s}_cycles.machine.json" \
    --toolpath "$s.jsonl" 2>/dev/null || fail "mbc run in system $s"
  # The cycle's name is written as the system numbers it.
  sed -e 's/"cycle":"G7[0-9]",//' -e 's/"prog":"[^"]*"//' "$s.jsonl" >"$s.path"
done
[ -s a.path ] || fail "no toolpath"
for s in b c; do
  cmp -s a.path "$s.path" || { diff a.path "$s.path"; fail "system $s moves otherwise than system A"; }
done
