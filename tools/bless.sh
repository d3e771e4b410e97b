#!/usr/bin/env bash
# Regenerates the expected outputs of golden cases from the current build
# (the interpreter, the oracle):
#   tools/bless.sh tests/programs/foo.nc ...
# Read the diff before committing: blessing accepts whatever mbc does now.
set -eu
top=$(cd "$(dirname "$0")/.." && pwd)
for c in "$@"; do
  MBC_ENGINE=interp "$top/tests/run_case.sh" "$top/build/mbc" "$c" --bless
done
