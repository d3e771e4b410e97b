#!/usr/bin/env python3
"""A lathe's diameter programming against an independent oracle: rs274.

LinuxCNC's rs274 in lathe mode (G18, G7 diameter mode) prints its moves
with X as a radius. The same turned profile, written for a FANUC lathe
(diameter X, incremental U/W in G code system A, I and K as radii) and for
LinuxCNC (G91 for the incremental blocks), must end every move at the same
point and turn every arc about the same centre: mbc's X and arc centre X
are diameters, so half of them is compared. Fails when rs274 is
not installed (`make test` installs it).

    tests/lathe_rs274.py MBC
"""

import json
import re
import subprocess
import sys

from rs274_oracle import collect, rs274

# One block per row: the FANUC lathe's and LinuxCNC's.
MOVES = [
    ("G00X30.Z2.", "G90 G0 X30 Z2"),
    ("G01Z0.F.1", "G1 Z0 F100"),
    ("X35.Z-2.5", "X35 Z-2.5"),
    ("Z-20.", "Z-20"),
    ("G02X45.Z-25.R5.", "G2 X45 Z-25 R5"),
    ("G01U5.", "G91 G1 X5"),
    ("G03X65.Z-32.5I0K-7.5", "G90 G3 X65 Z-32.5 I0 K-7.5"),
    ("G01W-10.", "G91 G1 Z-10"),
    ("G02U10.W-5.I5.K0", "G2 X10 Z-5 I5 K0"),
    ("G01X84.987Z-52.5", "G90 G1 X84.987 Z-52.5"),
    ("G03X100.Z-70.R-12.", "G3 X100 Z-70 R-12"),
    ("G00U2.001W1.", "G91 G0 X2.001 Z1"),
    ("X120.Z10.", "G90 G0 X120 Z10"),
]

# rs274's canonical calls: X first (a radius), then Y and Z; an arc's first
# end and centre are Z's, its second X's (G18).
STRAIGHT = re.compile(r"STRAIGHT_(?:TRAVERSE|FEED)\(([-0-9.]+), [-0-9.]+, "
                      r"([-0-9.]+),")
ARC = re.compile(r"ARC_FEED\(([-0-9.]+), ([-0-9.]+), ([-0-9.]+), "
                 r"([-0-9.]+), (-?1),")


def run_mbc(mbc, folder, text, cycle=None):
    """Each move's end (radius, z) and, for arcs, centre (radius, z), of
    the FANUC lathe program `text`; with `cycle` ("G70"), its moves only."""
    (folder / "lathe.json").write_text('{"series": "T"}')
    program = folder / "lathe.nc"
    program.write_text(text)
    toolpath = folder / "lathe.jsonl"
    subprocess.run([mbc, "run", str(program), "--machine",
                    str(folder / "lathe.json"), "--toolpath", str(toolpath)],
                   check=True, capture_output=True)
    moves = []
    for line in toolpath.read_text().splitlines():
        m = json.loads(line)
        if cycle is not None and m.get("cycle") != cycle:
            continue
        centre = (m["cx"] / 2, m["cz"]) if "cx" in m else None
        moves.append(((m["x"] / 2, m["z"]), centre))
    return moves


def run_rs274(folder, text):
    """The moves of the LinuxCNC program `text`, as run_mbc gives them; a
    move that goes nowhere is left out."""
    program = folder / "lathe.ngc"
    program.write_text(text)
    out = folder / "canon.txt"
    rs274(folder, "-g", program, out)
    moves = []
    for line in out.read_text().splitlines():
        if arc := ARC.search(line):
            z, x, cz, cx, _ = (float(v) for v in arc.groups())
            moves.append(((x, z), (cx, cz)))
        elif straight := STRAIGHT.search(line):
            x, z = (float(v) for v in straight.groups())
            if not moves or moves[-1][0] != (x, z):
                moves.append(((x, z), None))
    return moves


def mbc_moves(mbc, folder):
    return run_mbc(mbc, folder,
                   "%\nO3001(PROFILE)\nG18G21G40G97G99S1000M03\n" +
                   "\n".join(fanuc for fanuc, _ in MOVES) + "\nM30\n%\n")


def rs274_moves(folder):
    return run_rs274(folder, "G18 G21 G7 G90\n" +
                     "\n".join(linuxcnc for _, linuxcnc in MOVES) + "\nM2\n")


def close(a, b):
    # rs274 prints 4 decimals, mbc's toolpath rounds to the 0.001 increment.
    return all(abs(p - q) <= 0.0006 for p, q in zip(a, b))


def compare(rows, ours, theirs):
    """0 when every move of mbc's ends (and turns) where rs274's does; 1
    after printing those that do not."""
    failed = 0
    for row, (end, centre), (oend, ocentre) in zip(rows, ours, theirs):
        if not close(end, oend) or (centre is None) != (ocentre is None) or (
                centre is not None and not close(centre, ocentre)):
            print(f"{row}: mbc end {end} centre {centre}; rs274's end {oend} "
                  f"centre {ocentre}")
            failed = 1
    return failed


def main():
    both = collect(lambda folder: mbc_moves(sys.argv[1], folder),
                   rs274_moves, len(MOVES))
    if isinstance(both, int):
        return both
    return compare(MOVES, *both)


if __name__ == "__main__":
    sys.exit(main())
