#!/usr/bin/env bash
# A program big enough to be compiled in two parts at once (object_file.cpp)
# still makes one object whose bodies are hidden symbols named after its
# table, and an executable of `mbc build` that runs as the IR evaluator does.
#   object_in_parts.sh MBC GEN_LARGE_PY
gen=$(realpath "$2") # before script_env.sh enters its work folder
source "$(dirname "$0")/script_env.sh" "$1"
python3 "$gen" 5000 big.nc || exit 2
"$mbc" compile -c -O1 big.nc -o big.o || fail "compile -c"
readelf -sW big.o >symbols.txt || exit 2
grep -q ' HIDDEN .* mbc_programs_big\.body\.O2000$' symbols.txt ||
  fail "no hidden body symbol: not compiled in parts?"
grep -q ' GLOBAL DEFAULT .* mbc_programs_big$' symbols.txt ||
  fail "no program table"
"$mbc" build -O1 big.nc -o big || fail "build"
./big --toolpath aot.jsonl --vars-out aot.json 2>aot.err
aot=$?
"$mbc" run --engine ir big.nc --toolpath ir.jsonl --vars-out ir.json 2>ir.err
[ $? -eq "$aot" ] || fail "exit status $aot, the IR evaluator's differs"
for f in jsonl json err; do
  cmp -s "aot.$f" "ir.$f" || fail "$f differs: $(diff "ir.$f" "aot.$f" | head)"
done
