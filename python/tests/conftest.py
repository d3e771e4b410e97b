"""Shared by the package's tests: the mbc command and the source tree (set
by ctest: MBC, MBC_SOURCE_DIR), and the writer of toolpath records that
turns a motions array back into `mbc run --toolpath` text."""
import json
import math
import os
import pathlib
import subprocess

import pytest

import mbc

SOURCE = pathlib.Path(os.environ.get("MBC_SOURCE_DIR",
                                     pathlib.Path(__file__).parents[2]))
MBC = os.environ.get("MBC", str(SOURCE / "build" / "mbc"))
# The date #3011/#3012 read, as tests/run_case.sh sets it.
os.environ["SOURCE_DATE_EPOCH"] = "1767225600"


@pytest.fixture
def source_dir():
    return SOURCE


def run_mbc(*args, cwd=None):
    return subprocess.run([MBC, *map(str, args)], cwd=cwd, capture_output=True,
                          text=True, env={**os.environ, "LC_ALL": "C"})


def trimmed(value, decimals):
    text = f"{value:.{decimals}f}"
    if "." in text:
        text = text.rstrip("0").rstrip(".")
    return "0" if text == "-0" else text


def feed_text(feed):
    if feed >= 0 and feed < 1e15 and feed == math.floor(feed):
        return str(int(feed))
    return repr(feed)


# The arc centre's two axes in the order the toolpath writes them.
PLANE_AXES = {17: "xy", 18: "zx", 19: "yz"}


def toolpath_jsonl(result, axes, decimals=3):
    """The motions as `mbc run --toolpath` writes them, record by record."""
    lines = []
    for row in result.motions:
        kind = mbc.MOTION_NAMES[row["motion"]]
        parts = [f'"motion":"{kind}"']
        parts += [f'"{a}":{trimmed(row[a], decimals)}' for a in axes]
        parts += [f'"m{a}":{trimmed(row["m" + a], decimals)}' for a in axes]
        if kind != "rapid":
            parts.append(f'"f":{feed_text(row["f"])}')
        if kind in ("cw", "ccw"):
            plane = PLANE_AXES[row["plane"]]
            parts += [f'"c{a}":{trimmed(row["c" + a], decimals)}' for a in plane]
        if row["cycle"]:
            parts.append(f'"cycle":"G{row["cycle"]}"')
        parts.append(f'"line":{row["line"]}')
        parts.append(f'"prog":{json.dumps(result.programs[row["prog"]])}')
        lines.append("{" + ",".join(parts) + "}\n")
    return "".join(lines)
