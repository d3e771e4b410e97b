#!/usr/bin/env bash
# Runs the libFuzzer targets of tests/fuzz for SECONDS each (make fuzz).
#   tools/fuzz.sh BUILD_DIR SECONDS
# Each target's corpus grows in BUILD_DIR/fuzz-corpus/TARGET, seeded from
# the golden programs and diagnostics cases (Macro B), the machine profiles
# beside them (JSON) or the editor sessions of tests/fuzz/lsp and
# tests/fuzz/lsp_server. A crash, a leak, a sanitizer report or an input
# slower than 10 s stops the run with status 1 and leaves the input in
# BUILD_DIR/fuzz-crashes: turn it into a regression test (tests/diag or
# tests/programs) before fixing it.
set -u
build=$1
seconds=$2
root=$(cd "$(dirname "$0")/.." && pwd)
crashes=$build/fuzz-crashes
mkdir -p "$crashes"
status=0
for target in frontend pipeline profile lsp lsp_server; do
  corpus=$build/fuzz-corpus/$target
  mkdir -p "$corpus"
  # The seeds are copied: libFuzzer writes into the corpus folders it is
  # given, and the source tree must never receive its inputs.
  if [ "$target" = profile ]; then
    cp -n "$root"/tests/programs/*.machine.json "$root"/tests/fuzz/profiles/* \
      "$corpus"/ 2>/dev/null
    dict=()
  elif [ "$target" = lsp ]; then
    cp -n "$root"/tests/fuzz/lsp/* "$corpus"/ 2>/dev/null
    dict=()
  elif [ "$target" = lsp_server ]; then
    cp -n "$root"/tests/fuzz/lsp_server/* "$corpus"/ 2>/dev/null
    dict=(-dict="$root/tests/fuzz/lsp_server.dict")
  else
    cp -n "$root"/tests/programs/*.nc "$root"/tests/diag/*.nc \
      "$root"/tests/seeds/*.nc "$corpus"/ 2>/dev/null
    dict=(-dict="$root/tests/fuzz/macro_b.dict")
  fi
  echo "== fuzz_$target: $seconds s =="
  if ! "$build/tests/fuzz/fuzz_$target" -max_total_time="$seconds" \
      -timeout=10 -rss_limit_mb=4096 -max_len=8192 -print_final_stats=1 \
      -artifact_prefix="$crashes/$target-" "${dict[@]}" "$corpus" \
      2>"$build/fuzz-$target.log"; then
    tail -40 "$build/fuzz-$target.log"
    echo "fuzz_$target: FAILED, inputs in $crashes"
    status=1
  else
    grep -E "stat::number_of_executed_units|cov: " "$build/fuzz-$target.log" |
      tail -2
  fi
done
exit $status
