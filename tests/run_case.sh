#!/usr/bin/env bash
# Runs one golden case and compares every expected file that exists beside it.
#   run_case.sh MBC CASE.nc [--bless]
# CASE.args       extra `mbc run` arguments, one per line (optional)
# CASE.status     expected exit status (default 0)
# CASE.toolpath.jsonl / CASE.dprnt / CASE.vars.json / CASE.stderr
#                 expected outputs of `mbc run`
# CASE.check      expected standard error of `mbc check` (its exit status is
#                 CASE.status) -- for programs that must be diagnosed
# CASE.check-args extra `mbc check` arguments, one per line (optional)
# MBC_ENGINE=interp|ir|jit|aot picks the engine (default: mbc's, jit; aot:
# an executable made by `mbc build`, run with the same options): the
# expected outputs are the same files, since every engine must give
# byte-identical output. Under ir the IR is verified after every pass
# (--verify-each).
# MBC_EXTRA_ARGS: more `mbc run` arguments, split at spaces (for instance
# "--disable-pass dce").
# Paths are printed relative to the case's folder, so the case runs from there.
set -u
mbc=$(realpath "$1")
case_path=$2
bless=${3:-}
# Parameter expansion rather than dirname/basename: a process less each,
# and ctest runs this script hundreds of times.
dir=${case_path%/*}
[ "$dir" = "$case_path" ] && dir=.
[ -z "$dir" ] && dir=/
name=${case_path##*/}
name=${name%.nc}
cd "$dir" || exit 2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export LC_ALL=${MBC_TEST_LOCALE:-C} SOURCE_DATE_EPOCH=1767225600
expected_status=0
[ -f "$name.status" ] && expected_status=$(<"$name.status")
fail=0

compare() { # expected actual label
  if [ -n "$bless" ]; then
    cp "$2" "$1"
  elif ! diff -u "$1" "$2"; then
    echo "FAIL: $name: $3 differs"
    fail=1
  fi
}

if [ -f "$name.check" ]; then
  check_args=()
  if [ -f "$name.check-args" ]; then
    mapfile -t check_args < <(grep -v '^[[:space:]]*$' "$name.check-args")
  fi
  "$mbc" check "$name.nc" "${check_args[@]}" 2>"$work/check" >/dev/null
  status=$?
  compare "$name.check" "$work/check" "check diagnostics"
else
  args=()
  if [ -f "$name.args" ]; then
    mapfile -t args < <(grep -v '^[[:space:]]*$' "$name.args")
  fi
  read -r -a extra <<<"${MBC_EXTRA_ARGS:-}"
  outputs=(--toolpath "$work/toolpath.jsonl" --dprnt "$work/dprnt" --vars-out "$work/vars.json")
  if [ "${MBC_ENGINE:-}" = aot ]; then
    # An executable of `mbc build`: the .nc arguments are compiled in, the
    # others are its run options.
    # The build reads the input as `mbc run` does: errors make their blocks
    # alarm, unless the case asks for --strict; it finds called programs in
    # the -I folders.
    inputs=()
    run_args=()
    strict=(--no-strict)
    include=()
    for ((i = 0; i < ${#args[@]}; ++i)); do
      a=${args[i]}
      case $a in
        *.nc) inputs+=("$a") ;;
        --strict) strict=() ;;
        -I) include+=(-I "${args[i + 1]}"); ((++i)) ;;
        *) run_args+=("$a") ;;
      esac
    done
    "$mbc" build "$name.nc" "${inputs[@]}" "${strict[@]}" "${include[@]}" "${extra[@]}" -o "$work/program" 2>"$work/stderr" &&
      "$work/program" "${run_args[@]}" "${outputs[@]}" 2>>"$work/stderr"
    status=$?
  else
    engine=()
    [ -n "${MBC_ENGINE:-}" ] && engine=(--engine "$MBC_ENGINE")
    [ "${MBC_ENGINE:-}" = ir ] && engine+=(--verify-each)
    "$mbc" run "$name.nc" "${args[@]}" "${engine[@]}" "${extra[@]}" "${outputs[@]}" 2>"$work/stderr"
    status=$?
  fi
  for f in toolpath.jsonl dprnt vars.json stderr; do
    if [ -f "$name.$f" ] || { [ -n "$bless" ] && [ -s "$work/$f" ]; }; then
      [ -f "$work/$f" ] || : >"$work/$f"
      compare "$name.$f" "$work/$f" "$f"
    fi
  done
fi
if [ -n "$bless" ]; then
  if [ "$status" != 0 ]; then echo "$status" >"$name.status"; else rm -f "$name.status"; fi
  echo "blessed $name (status $status)"
  exit 0
fi
if [ "$status" != "$expected_status" ]; then
  echo "FAIL: $name: exit status $status, expected $expected_status"
  cat "$work"/stderr 2>/dev/null
  fail=1
fi
exit $fail
