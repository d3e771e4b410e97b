#!/usr/bin/env python3
"""mbc check's range analysis held against brute force: each program of
tests/range_grid runs (interp) on a grid of argument values inside the
ranges of its .ranges file, and every alarm a run raises must be one that
`mbc check --arg ...` predicted at that line. Check may say "may" where no
run alarmed; it must never be silent where a run did.
    tests/range_grid.py MBC"""
import itertools
import pathlib
import re
import subprocess
import sys

MAX_RUNS = 400
# The alarms the analysis decides (docs/check.md); a run may raise others
# (the machine model's), which are counted apart.
DECIDED = {"PS0112", "PS0119", "PS0115", "PS0076", "PS0011", "MC"}
root = pathlib.Path(__file__).resolve().parent / "range_grid"
mbc = str(pathlib.Path(sys.argv[1]).resolve())


def alarm_key(text):
    """The alarm as both sides name it: PS0112, or MC for #3000's."""
    code = text.split()[0]
    return "MC" if code in ("the", "3000") or code.isdigit() else code


def grid_values(lo, hi, points):
    if lo == hi:
        return [lo]
    values = {lo, hi, 0.0 if lo <= 0 <= hi else lo}
    values.update(lo + (hi - lo) * k / (points - 1) for k in range(points))
    if hi - lo <= 12:
        values.update(float(n) for n in range(int(lo), int(hi) + 1)
                      if lo <= n <= hi)
    return sorted(values)


failures = 0
for program in sorted(root.glob("*.nc")):
    ranges = []
    for line in program.with_suffix(".ranges").read_text().split():
        letter, span = line.split("=")
        lo, _, hi = span.partition("..")
        ranges.append((letter, float(lo), float(hi or lo)))
    arg_options = [f"--arg={l}={lo:g}..{hi:g}" for l, lo, hi in ranges]
    check = subprocess.run([mbc, "check", program.name, *arg_options],
                           cwd=root, capture_output=True, text=True)
    predicted = set()
    for line in check.stderr.splitlines():
        m = re.match(r".*?:(\d+):\d+: warning: (.*) may be raised here: ", line)
        if m:
            predicted.add((int(m.group(1)), alarm_key(m.group(2))))
    points = 8
    while True:
        grids = [grid_values(lo, hi, points) for _, lo, hi in ranges]
        runs = 1
        for g in grids:
            runs *= len(g)
        if runs <= MAX_RUNS or points == 2:
            break
        points -= 1
    observed = {}
    undecided = set()
    for values in itertools.product(*grids):
        args = [f"--arg={l}={v:g}" for (l, _, _), v in zip(ranges, values)]
        run = subprocess.run(
            [mbc, "run", program.name, "--engine", "interp",
             "--max-blocks", "100000", "--toolpath", "/dev/null", *args],
            cwd=root, capture_output=True, text=True)
        for line in run.stderr.splitlines():
            m = re.match(r".*?:(\d+): alarm (\w+)", line)
            if not m:
                continue
            key = (int(m.group(1)), alarm_key(m.group(2)))
            if key[1] in DECIDED:
                observed.setdefault(key, " ".join(args))
            else:
                undecided.add(key)
    missed = sorted(set(observed) - predicted)
    for line, alarm in missed:
        print(f"{program.name}:{line}: {alarm} raised with "
              f"{observed[(line, alarm)]}, and check did not predict it")
    failures += len(missed)
    print(f"{program.name}: {len(predicted)} predicted, "
          f"{len(observed)} raised on the grid, {len(missed)} missed "
          f"({len(undecided)} alarms the analysis does not decide)")
    if check.returncode != 0:
        print(f"{program.name}: mbc check failed:\n{check.stderr}")
        failures += 1
sys.exit(1 if failures else 0)
