#!/usr/bin/env bash
# Runs one case under every engine with --trace and compares everything each
# run writes (trace on stderr, toolpath, DPRNT, variables, exit status) with
# the interpreter's: a trace is a statement-by-statement record, so this
# finds where engines part even when the final outputs agree.
#   engines_agree.sh MBC CASE.nc     (CASE.args as for run_case.sh)
set -u
mbc=$(realpath "$1")
case_path=$2
source "$(dirname "$0")/case_env.sh"
run() { # engine out-dir
  mkdir -p "$2"
  "$mbc" run "$name.nc" "${args[@]}" --engine "$1" --trace \
    --toolpath "$2/toolpath.jsonl" --dprnt "$2/dprnt" --vars-out "$2/vars.json" \
    2>"$2/stderr"
  echo $? >"$2/status"
}
run interp "$work/interp"
fail=0
for engine in ir jit; do
  run "$engine" "$work/$engine"
  for f in stderr status toolpath.jsonl dprnt vars.json; do
    [ -f "$work/interp/$f" ] || [ -f "$work/$engine/$f" ] || continue
    if ! diff -u "$work/interp/$f" "$work/$engine/$f"; then
      echo "FAIL: $name: $f under --engine $engine differs from interp"
      fail=1
    fi
  done
done
exit $fail
