# Sourced by the test scripts that take MBC as their first argument: $mbc
# (absolute), a $work folder they run in, removed at exit, and fail().
set -u
mbc=$(realpath "$1")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 2
fail() { echo "FAIL: $*"; exit 1; }
