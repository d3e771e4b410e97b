#!/usr/bin/env python3
"""G71 type II on random shapes, against an outline of this script's own.

Each shape runs along Z from Z2 towards -Z with pockets, shoulders and
rises at random diameters; mbc roughs it from X46 (G71 type II: the first
block gives Z too). Every move of the cycle, sampled, must stay outside
the finished shape: on or above its outline, which this script evaluates
by itself from the corners it wrote.

    lathe_pockets_random.py MBC [SEED...]
"""

import json
import pathlib
import random
import subprocess
import sys
import tempfile

START_X = 46.0


def shape(rng):
    """The corners (z, x) of a shape after its start at Z2."""
    z = 0.0
    corners = [(2.0, rng.choice([20.0, 24.0, 30.0]))]
    for _ in range(rng.randint(3, 8)):
        z -= rng.choice([3, 4, 5, 6, 8])
        x = rng.choice([16.0, 20.0, 24.0, 28.0, 32.0, 36.0, 40.0])
        if rng.random() < 0.3:  # a shoulder: X alone
            corners.append((corners[-1][0], x))
        corners.append((z, x))
    return corners


def program(corners, depth):
    lines = ["O1", f"G98G00X{START_X:.1f}Z2.", f"G71U{depth:.1f}R0.5",
             "G71P10Q20F100.", f"N10G00X{corners[0][1]:.1f}Z2."]
    moves = [f"G01X{x:.1f}Z{z:.1f}" for z, x in corners[1:]]
    moves[-1] = "N20" + moves[-1]
    return "\n".join(lines + moves + ["M30", ""])


def outline_at(corners, z):
    """The lowest diameter of the outline at z (a shoulder counts its
    lower end), or None outside it."""
    found = None
    for (z0, x0), (z1, x1) in zip(corners, corners[1:]):
        if z1 <= z <= z0:
            x = min(x0, x1) if z0 == z1 else x0 + (z - z0) * (x1 - x0) / (z1 - z0)
            found = x if found is None else min(found, x)
    return found


def check(mbc, work, seed):
    rng = random.Random(seed)
    failures = 0
    for trial in range(60):
        corners = shape(rng)
        source = work / "p.nc"
        source.write_text(program(corners, rng.choice([1.0, 1.5, 2.0])))
        path = work / "p.jsonl"
        run = subprocess.run([mbc, "run", "--machine", str(work / "t.json"),
                              str(source), "--toolpath", str(path)],
                             capture_output=True, text=True, timeout=60)
        if run.returncode != 0 or ": alarm " in run.stderr:
            print(f"seed {seed} shape {trial}: mbc failed\n{run.stderr}")
            failures += 1
            continue
        start = None
        for line in path.read_text().splitlines():
            move = json.loads(line)
            end = (move["x"], move["z"])
            if start is not None and move.get("cycle"):
                for i in range(41):
                    s = i / 40
                    x = start[0] + s * (end[0] - start[0])
                    z = start[1] + s * (end[1] - start[1])
                    floor = outline_at(corners, z)
                    if floor is not None and x < floor - 0.01:
                        print(f"seed {seed} shape {trial}: {start} -> {end} "
                              f"enters the shape at X{x:.3f} Z{z:.3f}\n"
                              f"{source.read_text()}")
                        failures += 1
                        break
            start = end
    return failures


def main():
    mbc = sys.argv[1]
    seeds = [int(s) for s in sys.argv[2:]] or [1, 2, 3]
    with tempfile.TemporaryDirectory() as tmp:
        work = pathlib.Path(tmp)
        (work / "t.json").write_text('{"series": "T"}')
        failures = sum(check(mbc, work, seed) for seed in seeds)
    print(f"{len(seeds) * 60} shapes, {failures} failing")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
