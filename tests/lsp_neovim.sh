#!/usr/bin/env bash
# A real editor's client: Debian's Neovim, headless, with the configuration
# docs/editors.md gives, opens a shop program and checks that mbc lsp's
# diagnostics appear, that the hover names the G code, that go to
# definition lands on the label, and that O1000's code lens shows its run.
#   tests/lsp_neovim.sh MBC
set -u
mbc=$(realpath "$1")
here=$(cd "$(dirname "$0")" && pwd)
command -v nvim >/dev/null || { echo "nvim not found (make test installs neovim)"; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/bin" "$work/home"
ln -s "$mbc" "$work/bin/mbc"
# The configuration of docs/editors.md, taken from it, not written again.
sed -n '/^```lua$/,/^```$/p' "$here/../docs/editors.md" | sed '1d;$d' >"$work/init.lua"
# Without the library: its calls are missing programs.
cp "$here/lsp/part.nc" "$work"/
cd "$work" || exit 1
HOME=$work/home XDG_CONFIG_HOME=$work/home XDG_DATA_HOME=$work/home \
  XDG_STATE_HOME=$work/home PATH=$work/bin:$PATH MBC_NVIM_REPORT=$work/report \
  timeout 120 nvim --headless -n -i NONE -u "$work/init.lua" part.nc \
  -c "luafile $here/lsp_neovim.lua" >/dev/null 2>&1
cat >"$work/expected" <<'TXT'
attached true
diagnostic 15 missing-program
diagnostic 16 missing-program
hover **G01**: linear interpolation (modal group 01, read back in #4001)
definition part.nc 17
lens 2 6 moves · 0:06.5 · ends
TXT
if ! diff -u "$work/expected" "$work/report"; then
  echo "FAIL: Neovim's client and mbc lsp"
  exit 1
fi
echo "ok: Neovim's client got the diagnostics, the hover, the definition and the lens"
