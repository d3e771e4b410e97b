#!/usr/bin/env python3
"""Cutter compensation against an independent oracle: LinuxCNC's rs274.

Both controls offset straight moves and arcs by the tool radius and meet
at inner corners at the intersection of the offset paths; they differ at
outer corners (LinuxCNC inserts an arc), at the start-up and at the cancel
move. So the contours here have inner corners and tangent joins only, and
the comparison leaves out the start-up move, the last contour move and the
cancel move: every other tool-centre end point (and arc centre) must agree.
Skips (exit 77) when rs274 is not installed (`make bench` installs it).

    tests/cutter_comp_rs274.py MBC
"""

import json
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile

from rs274_oracle import rs274

RADIUS = 5.0  # D1 in mbc's offset memory; a 10 mm tool in rs274's table

# Contours: (side, start point, moves); a move is ("G1", x, y) or
# ("G2"/"G3", x, y, i, j) with the centre incremental from the move's start.
CONTOURS = [
    # A pocket: G41 counter-clockwise, every corner inner, one arc.
    ("G41", (20.0, 10.0), [
        ("G1", 40.0, 0.0), ("G1", 80.0, 0.0), ("G1", 80.0, 40.0),
        ("G3", 60.0, 60.0, -20.0, 0.0), ("G1", 0.0, 60.0),
        ("G1", 0.0, 0.0), ("G1", 40.0, 0.0)]),
    # A pocket with a slanted wall and a clockwise arc: G42.
    ("G42", (30.0, 20.0), [
        ("G1", 30.0, 0.0), ("G1", 0.0, 0.0), ("G1", 10.0, 45.0),
        ("G1", 50.0, 45.0), ("G2", 70.0, 25.0, 0.0, -20.0),
        ("G1", 65.0, 0.0), ("G1", 30.0, 0.0)]),
    # A slot: lines and half circles joined tangentially; the tool centre
    # runs on radius 15.
    ("G41", (40.0, 20.0), [
        ("G1", 40.0, 0.0), ("G1", 60.0, 0.0), ("G3", 60.0, 40.0, 0.0, 20.0),
        ("G1", 20.0, 40.0), ("G3", 20.0, 0.0, 0.0, -20.0),
        ("G1", 40.0, 0.0)]),
]

CANON = re.compile(r"(STRAIGHT_FEED|ARC_FEED)\(([^)]*)\)")


def contour_blocks(side, start, moves, fanuc):
    """The contour's blocks from the start-up to the cancel: packed words
    with 3 decimals for FANUC, spaced words for LinuxCNC (whose D is the
    loaded tool's)."""
    sep, number, offset = ("", "{:.3f}", "D1") if fanuc else (" ", "{}", "")
    blocks = []
    for index, (code, x, y, *center) in enumerate(moves):
        words = [code, "X" + number.format(x), "Y" + number.format(y)]
        if center:
            words += ["I" + number.format(center[0]),
                      "J" + number.format(center[1])]
        if index == 0:
            words.insert(0, side + offset)
        blocks.append(sep.join(words))
    blocks.append(sep.join(["G40", "G1", "X" + number.format(start[0]),
                            "Y" + number.format(start[1])]))
    return blocks


def fanuc_program(side, start, moves):
    lines = ["%", "O1(CUTTER COMP ORACLE)", "G17G21G40G90",
             f"G10L12P1R{RADIUS:.3f}", f"G0X{start[0]:.3f}Y{start[1]:.3f}",
             "G1Z-2.F200."] + contour_blocks(side, start, moves, True)
    return "\n".join(lines + ["M30", "%"]) + "\n"


def linuxcnc_program(side, start, moves):
    lines = [f"G17 G21 G90 G0 X{start[0]} Y{start[1]} Z10", "T1 M6",
             "G1 Z-2 F200"] + contour_blocks(side, start, moves, False)
    return "\n".join(lines + ["M2"]) + "\n"


def mbc_moves(mbc, folder, program):
    path = folder / "contour.nc"
    path.write_text(program)
    toolpath = folder / "contour.jsonl"
    subprocess.run([mbc, "run", str(path), "--toolpath", str(toolpath)],
                   check=True, capture_output=True)
    moves = [json.loads(line) for line in toolpath.read_text().splitlines()]
    # After the rapid and the plunge: the contour's moves.
    return [((m["x"], m["y"]), (m["cx"], m["cy"]) if "cx" in m else None)
            for m in moves[2:]]


def rs274_moves(folder, program):
    path = folder / "contour.ngc"
    path.write_text(program)
    table = folder / "tools.tbl"
    # rs274 reads its tool table in inches.
    table.write_text(f"T1 P1 D{2 * RADIUS / 25.4:.9f} Z0 ;\n")
    out = folder / "canon.txt"
    rs274(folder, "-t", table, "-g", path, out)
    moves = []
    for kind, args in CANON.findall(out.read_text()):
        values = [float(v) for v in args.split(",")]
        centre = (values[2], values[3]) if kind == "ARC_FEED" else None
        moves.append(((values[0], values[1]), centre))
    return moves[1:]  # after the plunge


def close(a, b):
    # rs274 prints 4 decimals; mbc rounds to the 0.001 mm increment.
    return a is None and b is None or (
        a is not None and b is not None and
        all(abs(x - y) <= 0.0006 for x, y in zip(a, b)))


def main():
    if shutil.which("rs274") is None:
        print("rs274 is not installed (make test installs linuxcnc-uspace)")
        return 1
    failed = 0
    with tempfile.TemporaryDirectory() as tmp:
        folder = pathlib.Path(tmp)
        for side, start, moves in CONTOURS:
            ours = mbc_moves(sys.argv[1], folder,
                             fanuc_program(side, start, moves))
            theirs = rs274_moves(folder, linuxcnc_program(side, start, moves))
            if len(ours) != len(moves) + 1 or len(theirs) != len(moves) + 1:
                print(f"{side} contour from {start}: mbc {len(ours)} moves, "
                      f"rs274 {len(theirs)}, expected {len(moves) + 1}")
                failed = 1
                continue
            # Leave out the start-up, the last contour move and the cancel.
            for index in range(1, len(moves) - 1):
                (end, centre), (other_end, other_centre) = (ours[index],
                                                            theirs[index])
                if not close(end, other_end) or not close(centre,
                                                          other_centre):
                    print(f"{side} contour from {start}, move {index + 1} "
                          f"{moves[index]}: mbc ends at {end} centre {centre},"
                          f" rs274 at {other_end} centre {other_centre}")
                    failed = 1
    return failed


if __name__ == "__main__":
    sys.exit(main())
