#!/usr/bin/env python3
"""The pictures of docs/editors.md, taken from a real editor: Neovim runs
embedded with docs/editors.md's configuration and mbc lsp, a UI of this
script's attaches to it over msgpack-RPC (nvim_ui_attach), and the screen
Neovim draws (its grid of cells and their highlights) is written as an
SVG, then a PNG (rsvg-convert). Nothing in the pictures is drawn by hand.

    tools/editor_pictures.py MBC OUT_DIR
"""

import html
import os
import pathlib
import shutil
import subprocess
import sys
import tempfile
import threading
import time
import traceback

import msgpack

HERE = pathlib.Path(__file__).resolve().parent
COLUMNS, ROWS = 104, 17
CELL_W, CELL_H = 8.4, 17

# A shop program with what the pictures show: a condition written with
# '=', a call of a program the workspace does not have, arguments read.
PROGRAM = """%
O9120(BORE CYCLE)
(T12 BORING BAR D20.)
#1=#18+#26
IF[#1=0]GOTO20
G90G00X#24Y#25
G43Z[#26+5.]H12
G86Z-#1R2.F120.
G80
M98P9130(CHIP CLEAR)
M99
N20#3000=20(DEPTH ZERO)
M99
%
"""

# Lua run once the document is open: wait for the diagnostics and the
# lens, then put the cursor and open what the picture shows.
SCENES = {
    "lsp_diagnostics": """
vim.wait(20000, function() return #vim.diagnostic.get(0) > 0 end, 50)
vim.lsp.codelens.refresh()
vim.wait(3000, function()
  for _, l in ipairs(vim.lsp.codelens.get(0)) do
    if l.command then return true end
  end
end, 50)
vim.api.nvim_win_set_cursor(0, {5, 4})
-- After the CursorMoved the move gives, which would close it.
vim.defer_fn(function() vim.diagnostic.open_float({scope = "line"}) end, 300)
""",
    "lsp_hover": """
vim.wait(20000, function() return #vim.diagnostic.get(0) > 0 end, 50)
vim.api.nvim_win_set_cursor(0, {6, 8})
vim.lsp.buf.hover()
""",
}


class Screen:
    """The cells Neovim's redraw events draw on grid 1."""

    def __init__(self):
        self.cells = [[(" ", 0)] * COLUMNS for _ in range(ROWS)]
        self.attrs = {0: {}}
        self.fg, self.bg = 0xDDDDDD, 0x1E1E1E
        self.changed = time.time()

    def redraw(self, events):
        for event in events:
            name, calls = event[0], event[1:]
            for args in calls:
                getattr(self, "on_" + name, lambda *a: None)(*args)
        self.changed = time.time()

    def on_default_colors_set(self, fg, bg, *_):
        if fg >= 0:
            self.fg = fg
        if bg >= 0:
            self.bg = bg

    def on_hl_attr_define(self, ident, rgb, *_):
        self.attrs[ident] = rgb

    def on_grid_clear(self, grid):
        self.cells = [[(" ", 0)] * COLUMNS for _ in range(ROWS)]

    def on_grid_line(self, grid, row, col, cells):
        hl = 0
        for cell in cells:
            text = cell[0]
            hl = cell[1] if len(cell) > 1 else hl
            for _ in range(cell[2] if len(cell) > 2 else 1):
                if row < ROWS and col < COLUMNS:
                    self.cells[row][col] = (text, hl)
                col += 1

    def on_grid_scroll(self, grid, top, bottom, left, right, rows, cols):
        region = [row[left:right] for row in self.cells[top:bottom]]
        for r in range(top, bottom):
            source = r + rows
            if top <= source < bottom:
                self.cells[r][left:right] = region[source - top]

    def colours(self, hl):
        a = self.attrs.get(hl, {})
        fg = a.get("foreground", self.fg)
        bg = a.get("background", self.bg)
        if a.get("reverse"):
            fg, bg = bg, fg
        return fg, bg, a.get("bold", False), a.get("italic", False)

    def svg(self):
        out = [f'<svg xmlns="http://www.w3.org/2000/svg" '
               f'width="{COLUMNS * CELL_W:.0f}" height="{ROWS * CELL_H}" '
               f'font-family="DejaVu Sans Mono, monospace" font-size="14">',
               f'<rect width="100%" height="100%" fill="#{self.bg:06x}"/>']
        for r, row in enumerate(self.cells):
            c = 0
            while c < COLUMNS:
                hl = row[c][1]
                end = c
                while end < COLUMNS and row[end][1] == hl:
                    end += 1
                fg, bg, bold, italic = self.colours(hl)
                x, y = c * CELL_W, r * CELL_H
                if bg != self.bg:
                    out.append(f'<rect x="{x:.1f}" y="{y}" '
                               f'width="{(end - c) * CELL_W:.1f}" '
                               f'height="{CELL_H}" fill="#{bg:06x}"/>')
                text = "".join(cell[0] for cell in row[c:end])
                if text.strip():
                    style = (' font-weight="bold"' if bold else "") + (
                        ' font-style="italic"' if italic else "")
                    out.append(
                        f'<text x="{x:.1f}" y="{y + CELL_H - 4}" '
                        f'fill="#{fg:06x}" xml:space="preserve"{style} '
                        f'textLength="{(end - c) * CELL_W:.1f}">'
                        f'{html.escape(text)}</text>')
                c = end
        out.append("</svg>")
        return "\n".join(out) + "\n"


class Nvim:
    """An embedded Neovim and the messages it sends."""

    def __init__(self, args, env, cwd):
        self.proc = subprocess.Popen(["nvim", "--embed", *args], env=env,
                                     cwd=cwd, stdin=subprocess.PIPE,
                                     stdout=subprocess.PIPE)
        self.screen = Screen()
        self.next_id = 0
        self.results = {}
        self.cond = threading.Condition()
        threading.Thread(target=self.read, daemon=True).start()

    def read(self):
        unpacker = msgpack.Unpacker(raw=False)
        while chunk := os.read(self.proc.stdout.fileno(), 65536):
            unpacker.feed(chunk)
            for message in unpacker:
                self.take(message)

    def take(self, message):
        if message[0] == 1:
            with self.cond:
                self.results[message[1]] = (message[2], message[3])
                self.cond.notify_all()
        elif message[0] == 2 and message[1] == "redraw":
            with self.cond:
                try:
                    self.screen.redraw(message[2])
                except Exception:  # a picture must not hang on it
                    traceback.print_exc()
        elif message[0] == 0:  # a request of Neovim's: none expected
            self.send([1, message[1], None, None])

    def send(self, message):
        self.proc.stdin.write(msgpack.packb(message))
        self.proc.stdin.flush()

    def call(self, method, *params):
        with self.cond:
            ident = self.next_id
            self.next_id += 1
        self.send([0, ident, method, list(params)])
        with self.cond:
            self.cond.wait_for(lambda: ident in self.results, 60)
            error, result = self.results.pop(ident)
        if error:
            raise RuntimeError(f"{method}: {error}")
        return result

    def settled(self, quiet=1.0, most=30.0):
        """Waits until nothing was drawn for `quiet` seconds."""
        start = time.time()
        while time.time() - start < most:
            with self.cond:
                if time.time() - self.screen.changed > quiet:
                    return
            time.sleep(0.1)


def picture(mbc, name, scene, out_dir):
    with tempfile.TemporaryDirectory() as tmp:
        work = pathlib.Path(tmp)
        (work / "bin").mkdir()
        (work / "bin" / "mbc").symlink_to(pathlib.Path(mbc).resolve())
        docs = (HERE.parent / "docs" / "editors.md").read_text()
        config = docs.split("```lua\n", 1)[1].split("```", 1)[0]
        (work / "init.lua").write_text(
            config + 'vim.cmd("colorscheme desert")\nvim.cmd("syntax off")\n'
            'vim.cmd("highlight NormalFloat guibg=#404850 guifg=#e8e8e8")\n'
            'vim.o.signcolumn = "yes"\nvim.o.number = true\n')
        (work / "bore.nc").write_text(PROGRAM)
        (work / "scene.lua").write_text(scene)
        env = dict(os.environ, HOME=str(work), XDG_CONFIG_HOME=str(work),
                   XDG_DATA_HOME=str(work), XDG_STATE_HOME=str(work),
                   PATH=f"{work / 'bin'}:{os.environ['PATH']}")
        nvim = Nvim(["-n", "-i", "NONE", "-u", str(work / "init.lua"),
                     "bore.nc"], env, work)
        nvim.call("nvim_ui_attach", COLUMNS, ROWS,
                  {"rgb": True, "ext_linegrid": True})
        nvim.settled()
        nvim.call("nvim_command", f"luafile {work / 'scene.lua'}")
        nvim.settled()
        # What the scene opened asynchronously (a hover's float) is drawn
        # at the next redraw.
        nvim.call("nvim_command", "redraw")
        nvim.settled()
        svg = out_dir / f"{name}.svg"
        svg.write_text(nvim.screen.svg())
        nvim.proc.kill()
    png = out_dir / f"{name}.png"
    subprocess.run(["rsvg-convert", "-o", str(png), str(svg)], check=True)
    svg.unlink()
    print(f"wrote {png}")


def main():
    mbc, out_dir = sys.argv[1], pathlib.Path(sys.argv[2])
    if shutil.which("nvim") is None or shutil.which("rsvg-convert") is None:
        sys.exit("editor_pictures.py needs nvim and rsvg-convert")
    for name, scene in SCENES.items():
        picture(mbc, name, scene, out_dir)


if __name__ == "__main__":
    main()
