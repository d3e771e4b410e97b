"""What the rs274 oracle tests share: both sides run in a scratch folder,
and a side that loses or gains a move fails before any comparison."""

import os
import pathlib
import shutil
import subprocess
import tempfile


def collect(mbc_side, rs274_side, expected):
    """(mbc's moves, rs274's moves) from `side(folder)`, or the exit status:
    1 when rs274 is not installed (`make test` installs it, so that the
    oracle runs everywhere) or when a side has not `expected`."""
    if shutil.which("rs274") is None:
        print("rs274 is not installed (make test installs linuxcnc-uspace)")
        return 1
    with tempfile.TemporaryDirectory() as tmp:
        folder = pathlib.Path(tmp)
        ours = mbc_side(folder)
        theirs = rs274_side(folder)
    if len(ours) != expected or len(theirs) != expected:
        print(f"moves: mbc {len(ours)}, rs274 {len(theirs)}, "
              f"expected {expected}")
        return 1
    return ours, theirs


def rs274(folder, *args):
    """Runs LinuxCNC's rs274 in `folder`. It keeps its tool table in
    $HOME/.tool.mmap, which it truncates as it starts: runs that share a
    HOME (the oracle tests side by side under ctest -j) spoil each other's
    tools, so each gets `folder` as its HOME."""
    subprocess.run(["rs274", *map(str, args)], check=True,
                   capture_output=True, stdin=subprocess.DEVNULL,
                   env={**os.environ, "HOME": str(folder)})
