#!/usr/bin/env bash
# mbc batch: every row's outputs equal those of `mbc run` with the row's
# arguments and presets, under every engine; alarms are reported and do not
# stop the other rows; a 10 000-row table gives each row its own result
# (checked against what the program computes); results do not depend on -j;
# shards run by GNU parallel together equal the unsharded batch; bad tables
# and options get clear errors.
#   batch.sh MBC SOURCE_DIR
src=$(realpath "$2")/tests/batch
source "$(dirname "$0")/script_env.sh" "$1"
cp "$src/holes.nc" "$src/small.csv" .

# The small table: files per row, the same as mbc run's.
"$mbc" batch holes.nc --params small.csv --out small -j 2 2>small.err
[ $? = 3 ] || { cat small.err; fail "a batch with alarms must exit 3"; }
grep -q '^mbc: batch: row no-h (small.csv:6): holes.nc:21: alarm 3001: HOLES H MISSING$' small.err ||
  { cat small.err; fail "the alarm of row no-h is not reported"; }
grep -q '6 rows .*: 4 ended, 2 alarms; small/results.csv$' small.err ||
  { cat small.err; fail "summary"; }
[ "$(cut -d, -f1,3 small/results.csv | tr '\n' ' ')" = \
  "id,status a1,ended a2,ended a3,ended no-h,alarm neg-h,alarm a7,ended " ] ||
  { cat small/results.csv; fail "results.csv rows"; }
run_row() { # ID ARGS...: the row as mbc run runs it
  local id=$1; shift
  "$mbc" run holes.nc "$@" --toolpath "single/$id.toolpath.jsonl" \
    --dprnt "single/$id.dprnt" --vars-out "single/$id.vars.json" 2>"single/$id.log"
}
mkdir single
run_row a1 --arg R=10 --arg H=4 --arg Z=-3 --arg F=200 --set '#500=1'
run_row a2 --arg R=12.5 --arg H=6 --arg Z=-2.5 --arg F=150 --set '#500=2'
run_row a3 --arg H=3 --arg Z=-1 --arg F=100 --set '#500=3'
run_row no-h --arg R=10 --arg Z=-1 --arg F=100 --set '#500=4'
run_row neg-h --arg R=10 --arg H=-2 --arg Z=-1 --arg F=100 --set '#500=5'
run_row a7 --arg R=20 --arg H=8 --arg Z=-4 --arg F=300 --set '#500=7'
for f in single/*; do
  # An output a row did not write is no file in the batch.
  if [ ! -s "$f" ]; then
    [ ! -e "small/${f#single/}" ] || fail "small/${f#single/} is an empty file"
    continue
  fi
  cmp -s "$f" "small/${f#single/}" || { diff "$f" "small/${f#single/}"; fail "$f differs from the batch's"; }
done
for engine in interp ir; do
  "$mbc" batch holes.nc --params small.csv --out "small-$engine" --engine "$engine" 2>/dev/null
  diff -r small "small-$engine" || fail "--engine $engine differs from the JIT"
done
# --arg and --set apply to every row; the row's own cells win.
"$mbc" batch holes.nc --params small.csv --out defaults --arg H=5 --set '#500=9' 2>/dev/null
[ "$(cut -d, -f1,3,5 defaults/results.csv | tr '\n' ' ')" = \
  "id,status,moves a1,ended,12 a2,ended,18 a3,ended,9 no-h,ended,15 neg-h,alarm,0 a7,ended,24 " ] ||
  { cat defaults/results.csv; fail "--arg defaults"; }

# 10 000 rows, one combined JSONL; rows 2500, 5000, ... have no holes.
python3 - <<'PY'
with open("big.csv", "w") as f:
    f.write("R,H,Z,F,#500\n")
    for i in range(1, 10001):
        holes = 0 if i % 2500 == 0 else 1 + i % 12
        f.write(f"{10 + i % 17},{holes},{-1 - i % 5}.5,{100 + i % 3 * 50},{i}\n")
PY
"$mbc" batch holes.nc --params big.csv --out big --combined -j 2 2>big.err
[ $? = 3 ] || { cat big.err; fail "the 10 000-row batch"; }
grep -q '10000 rows .*: 9996 ended, 4 alarms; big/batch.jsonl$' big.err || { cat big.err; fail "big summary"; }
python3 - <<'PY' || fail "the 10 000 rows' results"
import json, math
rows = [json.loads(line) for line in open("big/batch.jsonl")]
assert [r["id"] for r in rows] == [f"{i:05}" for i in range(1, 10001)], "row ids"
for i, r in enumerate(rows, 1):
    holes = 0 if i % 2500 == 0 else 1 + i % 12
    if holes == 0:
        assert r["status"] == "alarm" and "alarm 3002" in r["alarm"], r
        continue
    radius, depth = 10 + i % 17, -1 - i % 5 - 0.5
    assert r["status"] == "ended" and r["alarm"] is None, r
    assert r["variables"] == {"100": holes, "101": i * 1000 + holes, "500": i}, r["variables"]
    assert r["dprnt"] == f"PART{i:6} HOLES{holes:5}\n", r["dprnt"]
    assert r["moves"] == 3 * holes and len(r["toolpath"]) == 3 * holes, r
    for k in range(holes):
        angle = math.radians(k * 360 / holes)
        hole = r["toolpath"][3 * k]
        assert abs(hole["x"] - radius * math.cos(angle)) < 6e-4, (i, hole)
        assert abs(hole["y"] - radius * math.sin(angle)) < 6e-4, (i, hole)
        assert r["toolpath"][3 * k + 1]["z"] == depth, (i, r["toolpath"][3 * k + 1])
PY
"$mbc" batch holes.nc --params big.csv --out big-j1 --combined -j 1 2>/dev/null
cmp -s big/batch.jsonl big-j1/batch.jsonl || fail "-j 1 and -j 2 give different results"

# A progress line on a terminal only, drawn in place.
! grep -q $'\r' big.err || fail "a progress line in a file"
script -qec "'$mbc' batch holes.nc --params big.csv --out tty --combined" /dev/null >tty.out
grep -qa $'\r\033\\[K\\[#\\{30\\}\\] 10000/10000 rows, 4 alarms, [0-9]* rows/s' tty.out ||
  { od -c tty.out | tail -5; fail "no progress line on a terminal"; }

# Shards through GNU parallel: together they are the unsharded batch.
head -1001 big.csv >part.csv
"$mbc" batch holes.nc --params part.csv --out whole 2>/dev/null
parallel --will-cite -j 2 "$mbc" batch holes.nc --params part.csv --out shards \
  --shard {}/3 ::: 0 1 2 2>shards.err
[ $? = 0 ] || { cat shards.err; fail "sharded batch"; }
grep -q 'shard 2/3 of 1000 rows' shards.err || { cat shards.err; fail "shard summary"; }
[ ! -e shards/results.csv ] && [ -e shards/results.shard-1-of-3.csv ] || fail "shard results names"
diff <(tail -n +2 whole/results.csv) \
  <(tail -q -n +2 shards/results.shard-*-of-3.csv | sort) || fail "shard results"
rm whole/results.csv shards/results.shard-*
diff -r whole shards || fail "the shards' row files differ from the whole batch's"
parallel --will-cite -j 2 "$mbc" batch holes.nc --params big.csv --out bigshards --combined \
  --shard {}/4 ::: 0 1 2 3 2>/dev/null
diff big/batch.jsonl <(cat bigshards/batch.shard-*-of-4.jsonl | sort) ||
  fail "the combined shards differ from the combined batch"

# Errors.
expect_error() { # STATUS MESSAGE ARGS...
  local status=$1 message=$2; shift 2
  "$mbc" "$@" >err.out 2>&1
  local got=$?
  [ "$got" = "$status" ] && grep -qF -- "$message" err.out ||
    { cat err.out; fail "mbc $* (exit $got)"; }
}
printf 'R,P\n1,2\n' >bad-column.csv
expect_error 2 "bad-column.csv:1:3: 'P' is not a G65 argument" batch holes.nc --params bad-column.csv --out e
printf 'R,H\n1,2\n3,x4\n' >bad-cell.csv
expect_error 2 "bad-cell.csv:3:3: 'x4' is not a number" batch holes.nc --params bad-cell.csv --out e
printf 'id,R\na/b,1\n' >bad-id.csv
expect_error 2 "bad-id.csv:2:1: id 'a/b' is not usable in file names" batch holes.nc --params bad-id.csv --out e
printf 'R,H\n1,2,3\n' >bad-width.csv
expect_error 2 "bad-width.csv:2:1: 3 cells, but the header names 2 columns" batch holes.nc --params bad-width.csv --out e
expect_error 2 "cannot read 'missing.csv'" batch holes.nc --params missing.csv --out e
expect_error 2 "'--toolpath' is not an option of mbc batch (it is one of mbc run): mbc batch writes each row" batch holes.nc --params small.csv --out e --toolpath t.jsonl
expect_error 2 "mbc batch needs --params TABLE.csv and --out DIR" batch holes.nc --params small.csv
expect_error 2 "--shard expects I/N with 0 <= I < N, got '3/3'" batch holes.nc --params small.csv --out e --shard 3/3
expect_error 2 "-j expects a number of threads from 1 to 256" batch holes.nc --params small.csv --out e -j 0
expect_error 2 "'--params' is not an option of mbc run (it is one of mbc batch)" run holes.nc --params small.csv

# Tables as spreadsheets save them: Excel's UTF-8 byte order mark, the
# semicolons and decimal commas of European locales, columns named for
# people and mapped with --column, columns to ignore.
printf '\xef\xbb\xbfid,R,H,Z,F,#500\r\na1,10,4,-3,200,1\r\n' >bom.csv
"$mbc" batch holes.nc --params bom.csv --out bom 2>/dev/null || fail "a table with a BOM"
cmp -s small/a1.toolpath.jsonl bom/a1.toolpath.jsonl || fail "BOM table row a1"
printf 'id;R;H;Z;F;#500\na2;12,5;6;-2,5;150;2\n' >semicolon.csv
"$mbc" batch holes.nc --params semicolon.csv --out semicolon 2>/dev/null || fail "a ; table"
cmp -s small/a2.toolpath.jsonl semicolon/a2.toolpath.jsonl || fail "; table row a2"
printf 'part,radius,holes,depth,feed,#500,note\na7,20,8,-4,300,7,"deburr, check"\n' >named.csv
"$mbc" batch holes.nc --params named.csv --out named --column part=id --column radius=R \
  --column HOLES=H --column depth=Z --column feed=F --column note= 2>/dev/null || fail "--column"
cmp -s small/a7.toolpath.jsonl named/a7.toolpath.jsonl || fail "--column row a7"
expect_error 2 "named.csv:1:1: unknown column 'part' (a G65 argument letter such as R, a variable such as #100, or id; --column 'part=R' maps it, --column 'part=' ignores it)" \
  batch holes.nc --params named.csv --out e
expect_error 2 "named.csv:1:1: --column width: the header has no column 'width'" \
  batch holes.nc --params named.csv --out e --column part=id --column radius=R --column holes=H \
  --column depth=Z --column feed=F --column note= --column width=W
expect_error 2 "--column expects NAME=TARGET (such as depth=Z), got 'depth'" \
  batch holes.nc --params named.csv --out e --column depth

# --resume: the rows an interrupted batch finished are kept, the others
# run; an interrupted row runs again.
mkdir resumed && cp small/* resumed/
{ head -3 small/results.csv; sed -n 4p small/results.csv | sed 's/,ended,/,interrupted,/'
  sed -n 5p small/results.csv | head -c 12; } >resumed/results.csv
echo "kept" >resumed/a1.dprnt
"$mbc" batch holes.nc --params small.csv --out resumed --resume 2>resume.err
[ $? = 3 ] || { cat resume.err; fail "a resumed batch with alarms must exit 3"; }
grep -q '6 rows, 2 kept from the earlier batch in .*: 4 ended, 2 alarms; resumed/results.csv$' resume.err ||
  { cat resume.err; fail "resumed summary"; }
cmp -s small/results.csv resumed/results.csv || fail "resumed results.csv"
[ "$(cat resumed/a1.dprnt)" = kept ] || fail "--resume ran a finished row again"
cmp -s small/a3.toolpath.jsonl resumed/a3.toolpath.jsonl || fail "the interrupted row a3"
"$mbc" batch holes.nc --params small.csv --out resumed --resume 2>resume.err
grep -q '6 rows, 6 kept from the earlier batch in .*: 4 ended, 2 alarms;' resume.err ||
  { cat resume.err; fail "a finished batch resumed"; }
"$mbc" batch holes.nc --params small.csv --out fresh --resume 2>/dev/null
cmp -s small/results.csv fresh/results.csv || fail "--resume of nothing"
# A combined batch that an earlier mbc began named the id "row".
"$mbc" batch holes.nc --params small.csv --out combined --combined 2>/dev/null
mkdir old && head -2 combined/batch.jsonl | sed 's/^{"id":/{"row":/' >old/batch.jsonl
head -3 combined/results.csv | sed '1s/^id,/row,/' >old/results.csv
"$mbc" batch holes.nc --params small.csv --out old --combined --resume 2>resume.err
grep -q '6 rows, 2 kept from the earlier batch' resume.err ||
  { cat resume.err; fail "a batch.jsonl with row ids resumed"; }
cmp -s <(tail -n +3 combined/batch.jsonl) <(tail -n +3 old/batch.jsonl) ||
  fail "the rows after the kept ones"

# The files of an earlier batch's rows that this one has not never mix in;
# files that no batch listed stay.
mkdir stale && cp -r small/* stale/ && cp big/batch.jsonl stale/ && echo mine >stale/notes.log
printf 'id,R,H,Z,F,#500\na1,10,4,-3,200,1\n' >one.csv
"$mbc" batch holes.nc --params one.csv --out stale 2>/dev/null
[ "$(ls stale | tr '\n' ' ')" = "a1.dprnt a1.log a1.toolpath.jsonl a1.vars.json notes.log results.csv " ] ||
  { ls stale; fail "stale files of the earlier batch"; }
"$mbc" batch holes.nc --params one.csv --out stale --combined 2>/dev/null
[ "$(ls stale | tr '\n' ' ')" = "batch.jsonl notes.log results.csv " ] ||
  { ls stale; fail "row files left beside a combined batch"; }
echo "batch: per-row results, engines, 10 000 rows, -j, shards and errors check"
