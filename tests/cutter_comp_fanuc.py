#!/usr/bin/env python3
"""Cutter compensation of straight contours against the FANUC figures.

An independent derivation of the tool-centre path, written from the
operator's manual's figures for cutter compensation C (start-up, offset
mode, cancel; types A and B of parameter 5003#0 SUP), not from mbc's code:

* inner corner: the intersection of the two offset lines;
* outer corner of 90 degrees or more: the intersection of the offset lines;
* sharper outer corner: the end of the first offset line extended by the
  offset, then the start of the second one moved back by it;
* start-up and cancel, type A: one vector perpendicular to the next move
  (start-up) or to the last one (cancel) at an outer corner; type B as in
  offset mode.

Each contour runs under type A and type B and under G41 and G42; every
tool-centre end point of mbc's toolpath must be within 0.001 mm.

    tests/cutter_comp_fanuc.py MBC
"""

import json
import math
import pathlib
import subprocess
import sys
import tempfile

OFFSET = 4.0

# Closed and open outlines (start point, then the programmed points): the
# first move starts compensation, the last one cancels it.
CONTOURS = [
    # A square boss with a slanted lead-in and lead-out.
    [(-20.0, -15.0), (0.0, 0.0), (0.0, 30.0), (30.0, 30.0), (30.0, 0.0),
     (0.0, 0.0), (-20.0, -15.0)],
    # A star-like outline: acute and obtuse corners both ways.
    [(-10.0, 0.0), (0.0, 0.0), (40.0, 0.0), (10.0, 10.0), (40.0, 30.0),
     (0.0, 25.0), (5.0, 12.0), (-15.0, 20.0)],
    # Sharp turns at the start and the end.
    [(30.0, -5.0), (0.0, 0.0), (20.0, 20.0), (25.0, 0.0), (45.0, 15.0),
     (20.0, 10.0)],
    # Straight on at the start-up, reversal-free zig-zag.
    [(-10.0, 0.0), (0.0, 0.0), (15.0, 0.0), (15.0, 15.0), (30.0, 15.0),
     (30.0, 0.0), (45.0, 0.0), (55.0, 0.0)],
]


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1])


def add(a, b):
    return (a[0] + b[0], a[1] + b[1])


def mul(k, a):
    return (k * a[0], k * a[1])


def direction(a, b):
    d = sub(b, a)
    n = math.hypot(*d)
    return (d[0] / n, d[1] / n)


def normal(d, side):
    """The offset vector of a move along d: left for G41 (side 1)."""
    return mul(OFFSET * side, (-d[1], d[0]))


def meet(p1, d1, p2, d2):
    det = d1[0] * d2[1] - d1[1] * d2[0]
    t = ((p2[0] - p1[0]) * d2[1] - (p2[1] - p1[1]) * d2[0]) / det
    return add(p1, mul(t, d1))


def corner(point, d1, d2, side, kind, type_b):
    """Tool-centre points at a corner; kind is startup, offset or cancel."""
    e1 = add(point, normal(d1, side))
    s2 = add(point, normal(d2, side))
    cross = d1[0] * d2[1] - d1[1] * d2[0]
    dot = d1[0] * d2[0] + d1[1] * d2[1]
    if abs(cross) < 1e-12 and dot > 0:
        return [e1]
    if cross * side > 0:  # the tool is inside the turn
        return [meet(e1, d1, s2, d2)]
    if not type_b and kind == "startup":
        return [s2]
    if not type_b and kind == "cancel":
        return [e1]
    if dot >= 0:
        return [meet(e1, d1, s2, d2)]
    return [add(e1, mul(OFFSET, d1)), sub(s2, mul(OFFSET, d2))]


def expected(points, side, type_b):
    path = []
    last = len(points) - 2  # the index of the last corner
    for i in range(1, len(points) - 1):
        d1 = direction(points[i - 1], points[i])
        d2 = direction(points[i], points[i + 1])
        kind = "startup" if i == 1 else "cancel" if i == last else "offset"
        path += corner(points[i], d1, d2, side, kind, type_b)
    return path + [points[-1]]


def program(points, side):
    code = "G41" if side > 0 else "G42"
    lines = ["%", "O2(CUTTER COMP FANUC FIGURES)", "G17G21G40G90",
             f"G10L12P3R{OFFSET:.3f}",
             f"G0X{points[0][0]:.3f}Y{points[0][1]:.3f}", "G1Z-1.F300."]
    for i, (x, y) in enumerate(points[1:], start=1):
        prefix = f"{code}D3" if i == 1 else "G40" if i == len(points) - 1 \
            else ""
        lines.append(f"{prefix}X{x:.3f}Y{y:.3f}")
    return "\n".join(lines + ["M30", "%"]) + "\n"


def mbc_points(mbc, folder, text, type_b):
    source = folder / "contour.nc"
    source.write_text(text)
    machine = folder / "machine.json"
    machine.write_text(json.dumps({"parameters": {"5003": int(type_b)}}))
    toolpath = folder / "contour.jsonl"
    subprocess.run([mbc, "run", str(source), "--machine", str(machine),
                    "--toolpath", str(toolpath)], check=True,
                   capture_output=True)
    moves = [json.loads(line) for line in toolpath.read_text().splitlines()]
    return [(m["x"], m["y"]) for m in moves[2:]]


def main():
    failed = 0
    with tempfile.TemporaryDirectory() as tmp:
        folder = pathlib.Path(tmp)
        for points in CONTOURS:
            for side in (1, -1):
                for type_b in (False, True):
                    want = expected(points, side, type_b)
                    got = mbc_points(sys.argv[1], folder,
                                     program(points, side), type_b)
                    name = (f"contour from {points[0]} "
                            f"{'G41' if side > 0 else 'G42'} "
                            f"type {'B' if type_b else 'A'}")
                    if len(got) != len(want) or any(
                            abs(a - b) > 0.0011
                            for p, q in zip(got, want) for a, b in zip(p, q)):
                        print(f"{name}:\n  mbc  {got}\n  want "
                              f"{[(round(x, 3), round(y, 3)) for x, y in want]}")
                        failed = 1
    return failed


if __name__ == "__main__":
    sys.exit(main())
