#!/usr/bin/env python3
"""Polar coordinates against an independent oracle: LinuxCNC's rs274.

LinuxCNC writes polar points with @ (radius) and ^ (angle) about the
program origin. Where its rules are FANUC's (an absolute radius and angle,
a left-out radius or angle keeping the current one, a G91 angle adding to
the current angle) the same moves must end at the same points. A G91
radius differs (FANUC measures it from the current position) and is left
out here. Fails when rs274 is not installed (`make test`
installs it).

    tests/polar_rs274.py MBC
"""

import json
import re
import subprocess
import sys

from rs274_oracle import collect, rs274

# One move per row: the FANUC block (in G16) and LinuxCNC's.
MOVES = [
    ("G90 G00 X50. Y30.", "G90 G0 @50 ^30"),
    ("Y90.", "G0 ^90"),
    ("G91 Y120.", "G91 G0 ^120"),
    ("Y-45.", "G0 ^-45"),
    ("G90 X20.", "G90 G0 @20"),
    ("G01 X35.5 Y200. F300.", "G1 @35.5 ^200 F300"),
    ("Y-17.25", "G1 ^-17.25"),
    ("G91 Y3600.5", "G91 G1 ^3600.5"),
    ("G90 X0.001 Y10.", "G90 G1 @0.001 ^10"),
    ("X75. Y0", "G1 @75 ^0"),
]

ENDPOINT = re.compile(r"STRAIGHT_(?:TRAVERSE|FEED)\(([-0-9.]+), ([-0-9.]+),")


def mbc_points(mbc, folder):
    program = folder / "polar.nc"
    program.write_text("G17 G21 G90 G00 X0 Y0 Z10.\nG16\n" +
                       "\n".join(fanuc for fanuc, _ in MOVES) + "\nM30\n")
    toolpath = folder / "polar.jsonl"
    subprocess.run([mbc, "run", str(program), "--toolpath", str(toolpath)],
                   check=True, capture_output=True)
    moves = [json.loads(line) for line in toolpath.read_text().splitlines()]
    return [(m["x"], m["y"]) for m in moves[1:]]


def rs274_points(folder):
    program = folder / "polar.ngc"
    program.write_text("G17 G21 G90 G0 X0 Y0 Z10\n" +
                       "\n".join(linuxcnc for _, linuxcnc in MOVES) +
                       "\nM2\n")
    out = folder / "canon.txt"
    rs274(folder, "-g", program, out)
    points = [(float(x), float(y))
              for x, y in ENDPOINT.findall(out.read_text())]
    return points[1:]


def main():
    both = collect(lambda folder: mbc_points(sys.argv[1], folder),
                   rs274_points, len(MOVES))
    if isinstance(both, int):
        return both
    ours, theirs = both
    failed = 0
    for (fanuc, linuxcnc), mine, other in zip(MOVES, ours, theirs):
        # rs274 prints 4 decimals; mbc rounds to the 0.001 mm increment.
        if any(abs(a - b) > 0.0006 for a, b in zip(mine, other)):
            print(f"{fanuc!r} ends at {mine}, rs274's {linuxcnc!r} at {other}")
            failed = 1
    return failed


if __name__ == "__main__":
    sys.exit(main())
