#!/bin/sh
# The man pages and the bash completion the build writes from mbc's help
# (tools/command_docs.py): a page per command with its options, and
# completion of commands, options and their values.
# Usage: command_docs.sh BUILD_DIR
build=$1
fail() { echo "command_docs: $*" >&2; exit 1; }
for page in mbc mbc-run mbc-batch mbc-check mbc-emit-ir mbc-compile mbc-build; do
  [ -s "$build/man/$page.1" ] || fail "no man page $page.1"
done
grep -q '^\.TH MBC-RUN "1"' "$build/man/mbc-run.1" || fail "mbc-run.1 has no title"
grep -q -- '\\-\\-toolpath' "$build/man/mbc-run.1" || fail "mbc-run.1 lacks --toolpath"
grep -q -- '\\-\\-params' "$build/man/mbc-batch.1" || fail "mbc-batch.1 lacks --params"
grep -q 'mbc-run(1)' "$build/man/mbc.1" || fail "mbc.1 does not point at mbc-run(1)"

complete() { # WORDS...: what completing the last word offers
  bash -c '. "$0"; COMP_WORDS=("$@"); COMP_CWORD=$(($# - 1)); _mbc; echo "${COMPREPLY[*]}"' \
    "$build/completion/mbc" "$@"
}
[ "$(complete mbc b)" = "batch build" ] || fail "commands: $(complete mbc b)"
[ "$(complete mbc run --tool)" = "--toolpath" ] || fail "run options: $(complete mbc run --tool)"
[ "$(complete mbc run --par)" = "" ] || fail "run offers --params"
[ "$(complete mbc batch --par)" = "--params" ] || fail "batch options"
[ "$(complete mbc run --engine i)" = "interp ir" ] || fail "engines: $(complete mbc run --engine i)"
[ "$(complete mbc help com)" = "compile" ] || fail "help topics"
echo "command_docs: man pages and completion check"
