#!/usr/bin/env python3
"""mbc check's range analysis held against brute force: each program of
tests/range_grid runs (interp) on a grid of argument values inside the
ranges of its .ranges file, and every alarm a run raises must be one that
`mbc check --arg ...` predicted at that line. Check may say "may" where no
run alarmed; it must never be silent where a run did.

A program with a .machine.json runs on that machine, and check is given it
too: then an overtravel (OT0500/OT0501) must be one check predicted at
its line (or check said it could not follow the tool), and every point of
every run's toolpath, arcs sampled, must be inside the box check says the
tool may reach.
    tests/range_grid.py MBC"""
import itertools
import json
import math
import pathlib
import re
import subprocess
import sys
import tempfile

MAX_RUNS = 400
# The alarms the analysis decides (docs/check.md); a run may raise others
# (the machine model's), which are counted apart.
DECIDED = {"PS0112", "PS0119", "PS0115", "PS0076", "PS0011", "MC",
           "OT0500", "OT0501"}
# The toolpath has three decimals; the box is computed from the program's.
BOX_SLACK = 0.002
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


def predictions(stderr):
    """The (line, alarm) pairs check predicts, whether it could follow the
    tool, and the box it says the tool may reach (letter: (lo, hi))."""
    predicted = set()
    followed = "-Wstroke-undecided" not in stderr
    box = {}
    for line in stderr.splitlines():
        m = re.match(r".*?:(\d+):\d+: warning: (.*) may be raised here: ", line)
        if m:
            predicted.add((int(m.group(1)), alarm_key(m.group(2))))
        m = re.match(r".*?:(\d+):\d+: warning: \w may (?:reach|go) .* past the "
                     r"([+-]) end of its stroke", line)
        if m:
            predicted.add((int(m.group(1)),
                           "OT0500" if m.group(2) == "+" else "OT0501"))
        m = re.match(r"mbc: the tool may reach, in machine coordinates: (.*)",
                     line)
        if m:
            for axis in m.group(1).split(", "):
                letter, span = axis.split(" ")
                lo, hi = span.split("..")
                box[letter] = (float(lo), float(hi))
    return predicted, followed, box


def path_points(path):
    """Every machine position of a toolpath, arcs sampled: from where the
    tool stands at power on (machine zero)."""
    here = None
    for line in path.read_text().splitlines():
        move = json.loads(line)
        axes = [k[1:] for k in move if re.fullmatch(r"m[a-z]", k)]
        end = {a: move["m" + a] for a in axes}
        if here is None:
            here = {a: 0.0 for a in axes}
        yield end
        centre = [k[1:] for k in move if re.fullmatch(r"c[a-z]", k)]
        if move["motion"] in ("cw", "ccw") and len(centre) == 2:
            p, q = centre
            shift = {a: move["m" + a] - move[a] for a in (p, q)}
            c = (move["c" + p] + shift[p], move["c" + q] + shift[q])
            a0 = math.atan2(here[q] - c[1], here[p] - c[0])
            a1 = math.atan2(end[q] - c[1], end[p] - c[0])
            r = math.hypot(here[p] - c[0], here[q] - c[1])
            turn = (a1 - a0) % (2 * math.pi) if move["motion"] == "ccw" \
                else -((a0 - a1) % (2 * math.pi))
            if turn == 0:
                turn = 2 * math.pi if move["motion"] == "ccw" else -2 * math.pi
            for k in range(65):
                a = a0 + turn * k / 64
                yield {p: c[0] + r * math.cos(a), q: c[1] + r * math.sin(a)}
        here = end


failures = 0
for program in sorted(root.glob("*.nc")):
    ranges = []
    for line in program.with_suffix(".ranges").read_text().split():
        letter, span = line.split("=")
        lo, _, hi = span.partition("..")
        ranges.append((letter, float(lo), float(hi or lo)))
    arg_options = [f"--arg={l}={lo:g}..{hi:g}" for l, lo, hi in ranges]
    profile = program.with_suffix(".machine.json")
    machine = ["--machine", profile.name] if profile.exists() else []
    check = subprocess.run([mbc, "check", program.name, *arg_options,
                            *machine],
                           cwd=root, capture_output=True, text=True)
    predicted, followed, box = predictions(check.stderr)
    if machine and followed and not box:
        print(f"{program.name}: check gave no box\n{check.stderr}")
        failures += 1
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
    outside = 0
    scratch = tempfile.TemporaryDirectory()
    toolpath = pathlib.Path(scratch.name) / "toolpath.jsonl"
    for values in itertools.product(*grids):
        args = [f"--arg={l}={v:g}" for (l, _, _), v in zip(ranges, values)]
        toolpath.unlink(missing_ok=True)  # not the last run's
        run = subprocess.run(
            [mbc, "run", program.name, "--engine", "interp",
             "--max-blocks", "100000", "--toolpath", str(toolpath), *args,
             *machine],
            cwd=root, capture_output=True, text=True)
        for line in run.stderr.splitlines():
            m = re.match(r".*?:(\d+): alarm (\w+)", line)
            if not m:
                continue
            key = (int(m.group(1)), alarm_key(m.group(2)))
            if key[1].startswith("OT") and not followed:
                undecided.add(key)
            elif key[1] in DECIDED:
                observed.setdefault(key, " ".join(args))
            else:
                undecided.add(key)
        if machine and followed and toolpath.exists():
            for point in path_points(toolpath):
                for letter, v in point.items():
                    lo, hi = box.get(letter.upper(), (0.0, 0.0))
                    if not lo - BOX_SLACK <= v <= hi + BOX_SLACK:
                        if outside == 0:
                            print(f"{program.name}: {letter.upper()} {v} "
                                  f"outside the box {lo}..{hi} with "
                                  f"{' '.join(args)}")
                        outside += 1
    scratch.cleanup()
    failures += 1 if outside else 0
    missed = sorted(set(observed) - predicted)
    for line, alarm in missed:
        print(f"{program.name}:{line}: {alarm} raised with "
              f"{observed[(line, alarm)]}, and check did not predict it")
    failures += len(missed)
    print(f"{program.name}: {len(predicted)} predicted, "
          f"{len(observed)} raised on the grid, {len(missed)} missed "
          f"({len(undecided)} alarms the analysis does not decide)"
          + (f"; box {box}, {outside} points outside" if machine else ""))
    if check.returncode != 0:
        print(f"{program.name}: mbc check failed:\n{check.stderr}")
        failures += 1
sys.exit(1 if failures else 0)
