#!/usr/bin/env bash
# Batch rows must not see each other: a program that reads the machine data
# a control keeps over power-off (#3002, #3005, the output signals, the part
# counters, commons, offsets, modal codes) and then changes all of it gives
# each row the results of `mbc run` of that row alone, whatever the rows
# before it, their order, -j, shards or --resume.
#   batch_isolation.sh MBC SOURCE_DIR
src=$(realpath "$2")/tests/batch
source "$(dirname "$0")/script_env.sh" "$1"
cp "$src/machine_data.nc" "$src/machine_data.csv" .
export SOURCE_DATE_EPOCH=1700000000 # #3011/#3012 alike in every run

# Each row alone: the reference.
mkdir alone
tail -n +2 machine_data.csv | while IFS=, read -r id a b; do
  "$mbc" run machine_data.nc --arg "A=$a" --arg "B=$b" \
    --toolpath "alone/$id.toolpath.jsonl" --dprnt "alone/$id.dprnt" \
    --vars-out "alone/$id.vars.json" 2>/dev/null || fail "mbc run of row $id"
done
# Every row starts from the same machine data: the first three lines of
# DPRNT (what the row read before changing anything) are one text.
[ "$(head -qn 3 alone/*.dprnt | sort -u | wc -l)" = 3 ] ||
  fail "rows run alone read different machine data"

same_as_alone() { # DIR WHAT
  for f in alone/*; do
    cmp -s "$f" "$1/${f#alone/}" ||
      { diff "$f" "$1/${f#alone/}"; fail "$2: ${f#alone/} differs from mbc run of the row alone"; }
  done
}
"$mbc" batch machine_data.nc --params machine_data.csv --out j1 -j 1 2>/dev/null ||
  fail "batch -j 1"
same_as_alone j1 "-j 1"
"$mbc" batch machine_data.nc --params machine_data.csv --out j2 -j 2 2>/dev/null ||
  fail "batch -j 2"
same_as_alone j2 "-j 2"
{ head -1 machine_data.csv; tail -n +2 machine_data.csv | tac; } >reversed.csv
"$mbc" batch machine_data.nc --params reversed.csv --out reversed -j 1 2>/dev/null ||
  fail "batch of the reversed table"
same_as_alone reversed "the reversed table"
for i in 0 1 2; do
  "$mbc" batch machine_data.nc --params machine_data.csv --out shards -j 1 \
    --shard "$i/3" 2>/dev/null || fail "shard $i/3"
done
same_as_alone shards "shards"
"$mbc" batch machine_data.nc --params machine_data.csv --out resumed -j 1 \
  --shard 1/2 2>/dev/null || fail "the first half"
"$mbc" batch machine_data.nc --params machine_data.csv --out resumed -j 1 \
  --resume 2>/dev/null || fail "--resume"
same_as_alone resumed "--resume"
echo ok
