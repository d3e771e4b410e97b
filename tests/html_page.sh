#!/usr/bin/env bash
# --html in a real browser: headless Chromium (Debian's) opens the page of
# the demo from disk without network, and the page must load without an
# error (its own count and the browser's console), hold a segment per move
# (the demo has no arcs: 20 moves, 20 segments; a program with arcs more),
# and look as docs/images/bolt_circle_html.png does within a tolerance
# (software WebGL, SwiftShader, draws alike from run to run).
#   html_page.sh MBC SOURCE_DIR PYTHON [--update]
source_dir=$(realpath "$2")
python=$3
update=${4:-}
source "$(dirname "$0")/script_env.sh" "$1"
command -v chromium >/dev/null || fail "chromium is not installed (make test installs it)"
browse() { # PAGE ARGS...: Chromium on the page, headless, offline
  local page=$1; shift
  timeout 120 chromium --headless --no-sandbox --disable-gpu --use-angle=swiftshader \
    --enable-unsafe-swiftshader --hide-scrollbars --no-first-run --disable-extensions \
    --proxy-server=127.0.0.1:9 --user-data-dir="$work/profile" \
    --enable-logging=stderr --v=0 "$@" "file://$work/$page"
}
if ! "$mbc" run "$source_dir/examples/bolt_circle.nc" --html demo.html --dprnt /dev/null 2>err.txt; then
  # Built where npm could not reach its registry: said, and skipped.
  grep -q "mbc: error: --html is not available: this mbc was built without its page" err.txt ||
    { cat err.txt; fail "mbc run --html"; }
  echo "SKIPPED: $(cat err.txt)"
  exit 77
fi
grep -q '<title>O1000 · machine built-in 3-axis mill · 20 moves · cycle 0:22.1</title>' demo.html ||
  fail "the page's title"
! grep -qE '(src|href)="https?:' demo.html || fail "the page loads something from the network"
browse demo.html --dump-dom >dom.html 2>console.txt || { tail -5 console.txt; fail "chromium --dump-dom"; }
grep -q 'data-ready="1"' dom.html || { grep -i console console.txt; fail "the page did not draw"; }
! grep -q 'data-errors=' dom.html || fail "the page had errors: $(grep -o 'data-errors="[0-9]*"' dom.html)"
! grep -E 'CONSOLE.*(Uncaught|Error)' console.txt || fail "errors on the browser's console"
grep -q 'data-segments="20" data-moves="20"' dom.html ||
  fail "segments: $(grep -o 'data-segments="[0-9]*" data-moves="[0-9]*"' dom.html)"

# The move under the pointer names its source line and end point: the
# rapid of move 2 (the first hole of 30 radius about X50 Y30, at 18 degrees).
browse 'demo.html#probe=2' --dump-dom 2>/dev/null | tr '\n' ' ' >probe.html
grep -q 'data-probe="[^"]*bolt_circle.nc:18  O9001  rapid 2  X78.978 Y47.765 Z10. G00 X#28 Y#29"' probe.html ||
  fail "the tip at move 2: $(grep -o 'data-probe="[^"]*"' probe.html)"

# View presets as backplotters have them, axis labels, the iso view first:
# where the machine's axes point on the screen.
grep -q 'data-view="iso" data-screen="X:right Y:up Z:up"' dom.html &&
  grep -q 'data-labels="X,Y,Z"' dom.html || fail "the iso view: $(grep -o '<html[^>]*>' dom.html)"
for view in "top X:right Y:up Z:depth" "front X:right Y:depth Z:up" "side X:depth Y:right Z:up"; do
  browse "demo.html#view=${view%% *}" --dump-dom 2>/dev/null >view.html
  grep -q "data-view=\"${view%% *}\" data-screen=\"${view#* }\"" view.html ||
    fail "view ${view%% *}: $(grep -o '<html[^>]*>' view.html)"
done

# A lathe: Z to the right and X up, its X and Z labelled, the tip's X a
# diameter as the control shows it (the drawing's is a radius); under tool
# nose radius compensation the programmed contour beside the tip's path.
printf '{"series": "T", "tool_offsets": {"1": {"r_geometry": 0.8, "tip": 3}}}\n' >lathe.json
printf '%%\nO2(SHAFT)\nG18G21G40G99\nT0101S500M3\nG00X40.Z2.\nG42G01Z0F.2\nX50.Z-5.\nZ-20.\nG40G00X80.Z50.\nM30\n%%\n' >shaft.nc
"$mbc" run shaft.nc --machine lathe.json --html lathe.html 2>/dev/null || fail "mbc run --html on a lathe"
browse 'lathe.html#probe=1' --dump-dom 2>/dev/null | tr '\n' ' ' >lathe-dom.html
grep -q 'data-view="front" data-screen="X:up Z:right"' lathe-dom.html &&
  grep -q 'data-labels="X,Z"' lathe-dom.html ||
  fail "the lathe's view: $(grep -o '<html[^>]*>' lathe-dom.html)"
grep -q 'data-probe="[^"]*shaft.nc:5  O0002  rapid 1  X40. Z2. G00X40.Z2."' lathe-dom.html ||
  fail "the lathe's tip: $(grep -o 'data-probe="[^"]*"' lathe-dom.html)"
browse 'lathe.html#view=top' --dump-dom 2>/dev/null >lathe-top.html
grep -q 'data-view="top" data-screen="X:depth Z:right"' lathe-top.html ||
  fail "the lathe's top view: $(grep -o '<html[^>]*>' lathe-top.html)"
grep -q 'data-programmed="[1-9]' lathe-dom.html && ! grep -q 'data-programmed="[1-9]' dom.html ||
  fail "the programmed contour: $(grep -o 'data-programmed="[0-9]*"' lathe-dom.html dom.html)"

# Arcs are segments of their own: a full circle and a quarter.
printf '%%\nO1(ARCS)\nG90G54G17G0X10.Y0Z5.\nG1Z-1.F100\nG3I-10.\nG2X0Y10.R10.\nG0Z5.\nM30\n%%\n' >arcs.nc
"$mbc" run arcs.nc --html arcs.html 2>/dev/null || fail "mbc run --html arcs"
browse arcs.html --dump-dom >arcs-dom.html 2>/dev/null
# 48 segments a turn, 12 for the quarter circle, 3 lines.
grep -q 'data-segments="63" data-moves="5"' arcs-dom.html ||
  fail "arc segments: $(grep -o 'data-segments="[0-9]*" data-moves="[0-9]*"' arcs-dom.html)"

# No moves: an empty scene, no error.
printf 'O2(NOTHING)\n#100=1\nM30\n' >none.nc
"$mbc" run none.nc --html none.html 2>/dev/null || fail "mbc run --html without moves"
browse none.html --dump-dom >none-dom.html 2>/dev/null
grep -q 'data-segments="0" data-moves="0" data-ready="1"' none-dom.html && ! grep -q data-errors none-dom.html ||
  fail "the page of a run without moves"

browse demo.html --window-size=900,600 --screenshot="$work/demo.png" 2>/dev/null ||
  fail "chromium --screenshot"
expected="$source_dir/docs/images/bolt_circle_html.png"
[ "$update" = --update ] && cp demo.png "$expected"
"$python" "$source_dir/tests/compare_pictures.py" demo.png "$expected" --max-changed 0.002 ||
  { cp demo.png demo.diff.png /tmp/ 2>/dev/null; fail "the page looks different (/tmp/demo.png, /tmp/demo.diff.png)"; }
echo "html_page: the demo page in Chromium checks"
