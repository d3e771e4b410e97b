#!/usr/bin/env bash
# Every file in a golden-case folder belongs to a case: NAME.nc and the
# expected files named after it (run_case.sh, gcode_roundtrip.sh). A stray
# file, such as a fuzzer's hash-named input, fails here rather than lying
# in the tree unused.
#   tests/case_files.sh
set -u
tests=$(cd "$(dirname "$0")" && pwd)
status=0
for suite in programs diag seeds; do
  for path in "$tests/$suite"/*; do
    file=${path##*/}
    [ -d "$path" ] && continue
    [ "$suite/$file" = seeds/README.md ] && continue
    case=${file%%.*}
    extension=${file#"$case"}
    case $extension in
      .nc | .check | .check-args | .status | .stderr | .args | .dprnt | .toolpath.jsonl | \
        .vars.json | .machine.json | .flat.args | .flat.machine.json) ;;
      *)
        echo "tests/$suite/$file: not a file of a golden case (NAME.nc, NAME.check, ...)"
        status=1
        continue
        ;;
    esac
    if [[ ! $case =~ ^[a-z0-9_]+$ ]] || [ ! -f "$tests/$suite/$case.nc" ]; then
      echo "tests/$suite/$file: no case $case.nc beside it"
      status=1
    fi
  done
done
exit $status
