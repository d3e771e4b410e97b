#!/usr/bin/env bash
# The cache of compiled code (toolchain/code_cache.h): a second run loads the
# code instead of generating it, and never loads libLLVM; a damaged or
# truncated entry is built again, never loaded; a change of source or
# options is a new entry; the cache keeps to its size; concurrent runs
# publish one whole entry; a cache that cannot be written costs a warning,
# not the run; a cache on a noexec filesystem still serves. The
# interpreter, the IR evaluator and check never load libLLVM.
#   code_cache.sh MBC
source "$(dirname "$0")/script_env.sh" "$1"
cat >slot.nc <<'NC'
%
O2001(SLOT MILL - CAM 7.2)
(T3 D10 FLAT)
#1=0
WHILE[#1LT4]DO1
G01X[#1*5.]Y[SIN[#1*30.]*10.]F400.
#1=#1+1
END1
DPRNT[END*X#5001[43]]
M30
%
NC
export MBC_CACHE_DIR=$work/cache
entries() { find cache -name '*.so' | sort; }
# Whether running "$@" (an mbc command line) loads libLLVM.
loads_llvm() { LD_DEBUG=files "$@" 2>&1 >/dev/null | grep -q 'file=libLLVM'; }

"$mbc" run slot.nc --engine interp --toolpath want.jsonl --dprnt want.txt 2>/dev/null
"$mbc" run slot.nc --time --toolpath got.jsonl --dprnt got.txt 2>err ||
  fail "first run: $(cat err)"
grep -q 'code generation' err || fail "the first run should generate: $(cat err)"
cmp -s want.jsonl got.jsonl && cmp -s want.txt got.txt ||
  fail "the compiled run differs from the interpreter's"
[ "$(entries | wc -l)" -eq 1 ] || fail "one entry expected: $(entries)"
entry=$(entries)
cp "$entry" good.so

"$mbc" run slot.nc --time --toolpath got.jsonl --dprnt got.txt 2>err
grep -q ', cache ' err || fail "the second run should hit: $(cat err)"
grep -q 'code generation' err && fail "the second run generated code"
cmp -s want.jsonl got.jsonl || fail "the cached code ran differently"
loads_llvm "$mbc" run slot.nc && fail "a cache hit loaded libLLVM"
loads_llvm "$mbc" run slot.nc --no-cache ||
  fail "LD_DEBUG shows no libLLVM where code is generated"
for engine in interp ir; do
  loads_llvm "$mbc" run slot.nc --engine $engine &&
    fail "--engine $engine loaded libLLVM"
done
loads_llvm "$mbc" check slot.nc && fail "check loaded libLLVM"

# A byte changed in the middle, then a truncated file: rebuilt, not loaded.
size=$(stat -c %s "$entry")
printf '\x5a' | dd of="$entry" bs=1 seek=$((size / 2)) conv=notrunc 2>/dev/null
"$mbc" run slot.nc --time --toolpath got.jsonl >/dev/null 2>err
grep -q 'code generation' err || fail "a damaged entry was loaded: $(cat err)"
cmp -s want.jsonl got.jsonl || fail "the run after a damaged entry differs"
cmp -s "$entry" good.so || fail "the damaged entry was not rebuilt"
truncate -s $((size / 3)) "$entry"
"$mbc" run slot.nc --time --toolpath got.jsonl >/dev/null 2>err
grep -q 'code generation' err || fail "a truncated entry was loaded: $(cat err)"
cmp -s "$entry" good.so || fail "the truncated entry was not rebuilt"

# Another source or other options: other entries; --no-cache adds none.
sed 's/CAM 7.2/CAM 7.3/' slot.nc >slot2.nc
"$mbc" run slot2.nc >/dev/null 2>/dev/null
"$mbc" run slot.nc -O0 >/dev/null 2>/dev/null
[ "$(entries | wc -l)" -eq 3 ] || fail "three entries expected: $(entries)"
"$mbc" run slot.nc -O1 --no-cache >/dev/null 2>/dev/null
[ "$(entries | wc -l)" -eq 3 ] || fail "--no-cache added an entry"

# The size limit keeps the newest; a temporary file an hour old is removed.
touch -d '2 hours ago' cache/.tmp-abandoned
touch cache/.tmp-recent
MBC_CACHE_SIZE=1 "$mbc" run slot.nc -O3 >/dev/null 2>/dev/null
[ "$(entries | wc -l)" -eq 1 ] || fail "the cache kept more than its size"
[ ! -e cache/.tmp-abandoned ] || fail "an abandoned temporary file stayed"
[ -e cache/.tmp-recent ] || fail "a temporary file being written was removed"
rm cache/.tmp-recent
MBC_CACHE_SIZE=lots "$mbc" run slot.nc >/dev/null 2>err
grep -q "MBC_CACHE_SIZE 'lots' is not a size" err || fail "$(cat err)"

# Eight runs at once on an empty cache: all right, one whole entry.
rm -rf cache
for i in 1 2 3 4 5 6 7 8; do
  "$mbc" run slot.nc --toolpath par$i.jsonl >/dev/null 2>par$i.err &
done
wait
for i in 1 2 3 4 5 6 7 8; do
  cmp -s want.jsonl par$i.jsonl || fail "concurrent run $i: $(cat par$i.err)"
done
[ "$(entries | wc -l)" -eq 1 ] || fail "concurrent runs: $(entries)"
cmp -s "$(entries)" good.so || fail "concurrent runs published another entry"
[ -z "$(find cache -name '.tmp-*')" ] || fail "concurrent runs left temporary files"

# Where the cache is: XDG_CACHE_HOME, else HOME; one that cannot be written
# is a warning.
unset MBC_CACHE_DIR
XDG_CACHE_HOME=$work/xdg "$mbc" run slot.nc >/dev/null 2>/dev/null
[ -n "$(find xdg/mbc -name '*.so')" ] || fail "nothing in XDG_CACHE_HOME/mbc"
env -u XDG_CACHE_HOME HOME=$work/home "$mbc" run slot.nc >/dev/null 2>/dev/null
[ -n "$(find home/.cache/mbc -name '*.so')" ] || fail "nothing in ~/.cache/mbc"
touch file
MBC_CACHE_DIR=$work/file "$mbc" run slot.nc --toolpath got.jsonl >/dev/null 2>err ||
  fail "an unwritable cache failed the run: $(cat err)"
grep -q "warning: cannot write in the cache $work/file" err || fail "$(cat err)"
cmp -s want.jsonl got.jsonl || fail "the uncached run differs"

# A cache and a temporary folder on a filesystem mounted noexec (hardened
# systems mount /tmp so): the code still loads. Needs root to mount.
mkdir noexec
if mount -t tmpfs -o noexec,size=64m tmpfs noexec 2>/dev/null; then
  for cold in "" --no-cache; do
    MBC_CACHE_DIR=$work/noexec/cache TMPDIR=$work/noexec \
      "$mbc" run slot.nc $cold --toolpath got.jsonl >/dev/null 2>err
    status=$?
    [ $status -eq 0 ] && cmp -s want.jsonl got.jsonl ||
      { umount noexec; fail "noexec ${cold:-cache} (status $status): $(cat err)"; }
  done
  MBC_CACHE_DIR=$work/noexec/cache "$mbc" run slot.nc --time >/dev/null 2>err
  umount noexec
  grep -q ', cache ' err || fail "no hit from a noexec cache: $(cat err)"
else
  echo "cannot mount a tmpfs (that needs root): the noexec part is left out"
fi
echo ok
