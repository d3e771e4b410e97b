#!/usr/bin/env python3
"""The stored stroke check (parameters 1320/1321) on random mill programs,
against a geometry of this script's own.

Each program moves a tool under a work offset and a tool length offset
with lines (G90 and G91), arcs in G17, G18 and G19 and helices. The script
knows every move it wrote: it follows the control point in machine
coordinates, samples each move, and finds the first that passes an end
of the strokes it then sets. mbc must alarm at that move's block with the
end's alarm (OT0500 +, OT0501 -), after the moves before it, which are the
same as in a run without strokes; a run whose strokes the path stays
within must not differ at all from one without.

    stroke_random.py MBC [SEED...]
"""

import json
import math
import pathlib
import random
import re
import subprocess
import sys
import tempfile

AXES = "XYZ"
# A plane's two axes in their order (G03 turns from the first towards the
# second) and the centre letters of each.
PLANES = {17: ((0, 1), "IJ"), 18: ((2, 0), "KI"), 19: ((1, 2), "JK")}
SAMPLES = 2000
# Reaches this close to an end are left out: rounding may go either way.
MARGIN = 1e-3


def fmt(v):
    text = f"{v:.3f}".rstrip("0")
    return text if text != "-0." else "0."


class Writer:
    """A random program and, per block, the moves of the control point in
    machine coordinates as functions of s in [0, 1]."""

    def __init__(self, rng, offset, length):
        self.rng = rng
        self.offset = offset
        self.length = length
        self.work = [-v for v in offset]  # machine zero, no length yet
        self.lines = ["%", "O3001(STROKE ORACLE)",
                      "(POST: RANDOM  T1 D10.0 ENDMILL H1)",
                      "N10G21G17G40G49G80G90"]
        self.moves = []  # (line, f(s) -> machine point)
        self.absolute = True

    def machine(self, work, with_length=True):
        return [work[i] + self.offset[i] +
                (self.length if i == 2 and with_length else 0.0)
                for i in range(3)]

    def block(self, text, move=None):
        self.lines.append(f"N{10 * (len(self.lines) - 2)}{text}")
        if move is not None:
            self.moves.append((len(self.lines), move))

    def start(self):
        rng = self.rng
        x, y = round(rng.uniform(-60, 60), 3), round(rng.uniform(-60, 60), 3)
        a = self.machine(self.work, False)
        self.work = [x, y, self.work[2]]
        b = self.machine(self.work, False)
        self.block(f"G90G54G00X{fmt(x)}Y{fmt(y)}S3000M03", line(a, b))
        z = round(rng.uniform(5, 60), 3)
        a = b
        self.work[2] = z
        self.block(f"G43Z{fmt(z)}H01M08", line(a, self.machine(self.work)))

    def straight(self):
        rng = self.rng
        target = [round(v + rng.uniform(-50, 50), 3) for v in self.work]
        if rng.random() < 0.5:
            target[rng.randrange(3)] = self.work[rng.randrange(3)]
        if target == self.work:
            target[0] += 1.0
        a = self.machine(self.work)
        words = ""
        incremental = rng.random() < 0.3
        mode = ""
        if incremental != (not self.absolute):
            mode = "G91" if incremental else "G90"
            self.absolute = not incremental
        for i, letter in enumerate(AXES):
            if target[i] != self.work[i]:
                v = target[i] - self.work[i] if incremental else target[i]
                words += letter + fmt(round(v, 3))
        code = rng.choice(["G00", "G01"])
        feed = f"F{rng.randint(200, 1500)}." if code == "G01" else ""
        self.work = target
        self.block(f"{mode}{code}{words}{feed}", line(a, self.machine(target)))

    def arc(self):
        rng = self.rng
        plane = rng.choice([17, 18, 19])
        (p, q), letters = PLANES[plane]
        r = rng.uniform(5, 40)
        alpha = rng.uniform(0, 2 * math.pi)
        offset = (round(r * math.cos(alpha), 3), round(r * math.sin(alpha), 3))
        center = (self.work[p] + offset[0], self.work[q] + offset[1])
        begin = math.atan2(-offset[1], -offset[0])
        turn = rng.uniform(math.radians(10), math.radians(350))
        ccw = rng.random() < 0.5
        end_angle = begin + (turn if ccw else -turn)
        radius = math.hypot(*offset)
        target = list(self.work)
        target[p] = round(center[0] + radius * math.cos(end_angle), 3)
        target[q] = round(center[1] + radius * math.sin(end_angle), 3)
        helix = plane == 17 and rng.random() < 0.4
        if helix:
            target[2] = round(self.work[2] + rng.uniform(-20, 20), 3)
        # The sweep from the rounded end, as the control measures it.
        end = math.atan2(target[q] - center[1], target[p] - center[0])
        sweep = (end - begin) % (2 * math.pi) if ccw else \
            (begin - end) % (2 * math.pi)
        mode = "" if self.absolute else "G90"
        self.absolute = True
        words = "".join(AXES[i] + fmt(target[i]) for i in range(3)
                        if target[i] != self.work[i])
        words += letters[0] + fmt(offset[0]) + letters[1] + fmt(offset[1])
        start = list(self.work)
        shift = [self.machine(start)[i] - start[i] for i in range(3)]

        def move(s):
            angle = begin + (sweep if ccw else -sweep) * s
            point = [start[i] + (target[i] - start[i]) * s for i in range(3)]
            point[p] = center[0] + radius * math.cos(angle)
            point[q] = center[1] + radius * math.sin(angle)
            return [point[i] + shift[i] for i in range(3)]

        self.work = target
        code = "G03" if ccw else "G02"
        self.block(f"{mode}G{plane}{code}{words}F{rng.randint(200, 1500)}.",
                   move)

    def text(self):
        return "\n".join(self.lines + ["N9990M30", "%", ""])


def line(a, b):
    return lambda s: [a[i] + (b[i] - a[i]) * s for i in range(3)]


def points(move):
    return [move(i / SAMPLES) for i in range(SAMPLES + 1)]


def expectation(moves, low, high):
    """The first move past an end: (line, alarms) with the alarms its first
    crossing may give, or None when none passes; "ambiguous" when some
    move comes within MARGIN of an end before that."""
    for line_no, move in moves:
        crossing = None
        for s, point in enumerate(points(move)):
            for i in range(3):
                if low[i] - MARGIN <= point[i] <= low[i] + MARGIN or \
                        high[i] - MARGIN <= point[i] <= high[i] + MARGIN:
                    return "ambiguous"
                if point[i] > high[i] or point[i] < low[i]:
                    found = (s, i, point[i] > high[i])
                    crossing = crossing or found
        if crossing:
            s0 = crossing[0]
            # Axes crossing within a sample of the first may be named.
            alarms = set()
            for s, point in enumerate(points(move)):
                if s > s0 + 1:
                    break
                for i in range(3):
                    if point[i] > high[i]:
                        alarms.add(("OT0500", AXES[i]))
                    if point[i] < low[i]:
                        alarms.add(("OT0501", AXES[i]))
            return line_no, alarms
    return None


def run(mbc, work, engine, machine):
    (work / "m.json").write_text(json.dumps(machine))
    path = work / "p.jsonl"
    result = subprocess.run([mbc, "run", str(work / "p.nc"), "--machine",
                             str(work / "m.json"), "--engine", engine,
                             "--toolpath", str(path)],
                            capture_output=True, text=True, timeout=60)
    return result, path.read_text().splitlines()


def trial(mbc, work, rng, name):
    offset = [round(rng.uniform(-500, -100), 3),
              round(rng.uniform(-300, -50), 3),
              round(rng.uniform(-450, -250), 3)]
    length = round(rng.uniform(60, 160), 3)
    w = Writer(rng, offset, length)
    w.start()
    for _ in range(rng.randint(6, 14)):
        (w.arc if rng.random() < 0.45 else w.straight)()
    (work / "p.nc").write_text(w.text())
    machine = {"work_offsets": {"G54": offset},
               "tool_offsets": {"1": {"h_geometry": length}}}
    engine = rng.choice(["interp", "ir", "jit"])
    free, free_path = run(mbc, work, engine, machine)
    if free.returncode != 0:
        return "free", f"{name}: the run without strokes failed\n{free.stderr}"
    every = [p for _, move in w.moves for p in points(move)]
    box_low = [min(min(p[i] for p in every), 0.0) for i in range(3)]
    box_high = [max(max(p[i] for p in every), 0.0) for i in range(3)]
    low, high = [], []
    # An end inside the path's box, on the far side of machine zero (where
    # the tool starts), or outside it.
    for i in range(3):
        inside = rng.random() < 0.3 and box_high[i] > 1.0
        high.append(round(rng.uniform(0.5, box_high[i])
                          if inside else box_high[i] + rng.uniform(1, 20), 3))
        inside = rng.random() < 0.3 and box_low[i] < -1.0
        low.append(round(rng.uniform(box_low[i], -0.5)
                         if inside else box_low[i] - rng.uniform(1, 20), 3))
    expected = expectation(w.moves, low, high)
    if expected == "ambiguous":
        return "ambiguous", None
    machine["parameters"] = {"1320": high, "1321": low}
    limited, limited_path = run(mbc, work, engine, machine)
    program = (work / "p.nc").read_text()
    context = f"{name} ({engine}), strokes {low} .. {high}\n{program}"
    if expected is None:
        if limited.returncode != 0 or limited_path != free_path:
            return "within", f"{context}\nexpected no alarm\n{limited.stderr}"
        return "within", None
    line_no, alarms = expected
    said = re.search(r"p\.nc:(\d+): alarm (OT050[01]): .*: ([XYZ]) would",
                     limited.stderr)
    if not said or int(said.group(1)) != line_no or \
            (said.group(2), said.group(3)) not in alarms:
        return "alarm", (f"{context}\nexpected line {line_no} {alarms}\n"
                         f"{limited.stderr}")
    before = [r for r in free_path if json.loads(r)["line"] < line_no]
    if limited_path != before:
        return "alarm", f"{context}\nthe moves before line {line_no} differ"
    return "alarm", None


def main():
    mbc = sys.argv[1]
    seeds = [int(s) for s in sys.argv[2:]] or [1, 2, 3]
    failures = 0
    tried = 0
    kinds = {"free": 0, "ambiguous": 0, "within": 0, "alarm": 0}
    with tempfile.TemporaryDirectory() as tmp:
        work = pathlib.Path(tmp)
        for seed in seeds:
            rng = random.Random(seed)
            for n in range(50):
                kind, failure = trial(mbc, work, rng,
                                      f"seed {seed} program {n}")
                tried += 1
                kinds[kind] += 1
                if failure:
                    print(failure)
                    failures += 1
    print(f"{tried} programs: {kinds['alarm']} pass an end, "
          f"{kinds['within']} stay within, {kinds['ambiguous']} come within "
          f"{MARGIN} of an end (left out); {failures} failing")
    # The oracle must have had something to check.
    if kinds["alarm"] < tried // 4 or kinds["within"] < tried // 10:
        print("too few programs of each kind")
        return 1
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
