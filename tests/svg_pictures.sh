#!/usr/bin/env bash
# --svg as people see it: the demo's drawing in the XY and the isometric
# view, rendered by librsvg (rsvg-convert), holds what it must (six holes
# with their depth, the origin's axes, the legend, the title) and looks as
# the expected pictures in docs/images do, within a tolerance for
# anti-aliasing. A new expected picture after a deliberate change:
#   tests/svg_pictures.sh build/mbc . /usr/bin/python3 --update
#   svg_pictures.sh MBC SOURCE_DIR PYTHON [--update]
source_dir=$(realpath "$2")
python=$3
update=${4:-}
source "$(dirname "$0")/script_env.sh" "$1"
for view in xy iso; do
  "$mbc" run "$source_dir/examples/bolt_circle.nc" --svg "$view.svg" --view "$view" \
    --dprnt /dev/null 2>/dev/null || fail "mbc run --svg --view $view"
  [ "$(grep -c 'class="hole"' "$view.svg")" = 6 ] || fail "$view: not six holes"
  [ "$(grep -c '>Z-5</text>' "$view.svg")" = 6 ] || fail "$view: the holes' depth"
  grep -q 'class="title"[^>]*>O1000 · machine built-in 3-axis mill · 20 moves · cycle 0:22.1<' "$view.svg" ||
    fail "$view: title"
  for item in rapid feed arc 'plunge, depth'; do
    grep -q ">$item</text>" "$view.svg" || fail "$view: no '$item' in the legend"
  done
  rsvg-convert --background-color=white "$view.svg" -o "$view.png" || fail "rsvg-convert $view.svg"
  expected="$source_dir/docs/images/bolt_circle_$view.png"
  if [ "$update" = --update ]; then
    cp "$view.png" "$expected"
  fi
  "$python" "$source_dir/tests/compare_pictures.py" "$view.png" "$expected" ||
    { cp "$view.png" "$view.diff.png" /tmp/ 2>/dev/null; fail "$view: the picture differs (/tmp/$view.png, /tmp/$view.diff.png)"; }
done
grep -q '>Y</text>' xy.svg && ! grep -q '>Z</text>' xy.svg || fail "xy: the axes X and Y only"

# A spot drill and a drill in the same holes: both depths at each. The
# hole at the right edge has its label on its left, inside the picture.
# Every retract runs back down its plunge: drawn once, or the dashes of
# the two fill each other's gaps and the rapid looks like a feed.
printf '%%\nO3(SPOT AND DRILL)\nG90G17G80G00X0Y0Z10.\nG99G81X10.Y10.Z-1.R2.F100.\nX80.\nG80G00Z10.\nG81X10.Y10.Z-10.R2.F80.\nX80.\nG80G00Z10.\nM30\n%%\n' >spot.nc
"$mbc" run spot.nc --svg spot.svg 2>/dev/null || fail "mbc run --svg spot.nc"
[ "$(grep -c '>Z-1 / Z-10</text>' spot.svg)" = 2 ] || fail "spot: two depths at each hole: $(grep -o '>Z[^<]*<' spot.svg)"
grep -q 'text-anchor="end">Z-1 / Z-10<' spot.svg || fail "spot: the label at the right edge"
"$mbc" run spot.nc --svg spot-xz.svg --view xz 2>/dev/null || fail "mbc run --svg --view xz spot.nc"
rapids=$(grep -o 'class="rapid"[^>]*d="[^"]*"' spot-xz.svg | grep -o 'M[^M]*')
[ "$(printf '%s\n' "$rapids" | sort | uniq -d)" = "" ] || fail "spot: a rapid drawn twice"
[ "$(printf '%s\n' "$rapids" | grep -c 'M10 -2L10 -10$')" = 1 ] || fail "spot: the retract over X10: $rapids"
grep -q '>Z</text>' iso.svg || fail "iso: the Z axis"
"$mbc" run "$source_dir/examples/bolt_circle.nc" --view xz 2>err.txt && fail "--view without --svg"
grep -q "mbc: error: --view chooses the view of --svg, which is not given" err.txt || { cat err.txt; fail "--view alone"; }
echo "svg_pictures: the demo drawing in two views checks"
