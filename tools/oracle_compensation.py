"""The geometry of cutter compensation as properties, checked on random
contours by geometry of the oracle's own (oracle_geometry.py), not mbc's.

A case is a closed contour of lines and arcs around a random centre, with
,C and ,R corners between lines (the last one too, before G40), Z moves
that the look-ahead tolerates, a random D, G41 or G42, start-up and cancel
of type A or B, under no frame or under G68, G51.1, G51 or G52. The tool
centre must:

* keep at least the offset from the programmed contour: from the block's
  own elements everywhere, and from those of the blocks before and after
  it about the corners it shares with them (a random contour may narrow
  elsewhere to less than the tool, which no compensation can help): no
  gouge. The one overcut FANUC documents, after more blocks without plane
  motion than parameter 19625 allows, is never generated;
* run on the offset path of its element at the start of each block: the
  first move of a block lies exactly the offset away on the side of G41 or
  G42 (swapped by a mirror image), in the workpiece frame (scaling does
  not scale the offset);
* turn every arc about its centre: its start and end at one radius.

The start-up and the cancel move themselves are left out (they run from or
to a point without offset).

One case in four is a lathe's tool nose radius compensation in G18: the
contour in Z and X (a diameter), the nose radius and the imaginary tip of
offset 1. The toolpath is the imaginary tip's; the nose centre is the tip
less the tip vector of the operator's manual's figure (tip 3: the tip one
radius below and to the left of the centre, X down, Z towards the chuck;
tip 2 a boring bar's, above it; tips 0 and 9: the centre itself), and it
must keep the nose radius as a mill's tool centre keeps D."""

import json
import math
import random
import subprocess

from oracle_geometry import (Frame, add, beside, corner, cross, distance,
                             fmt, mul, norm, points, sub, tangent, unit)

TOLERANCE = 0.003  # rounding to 0.001 mm of ends, centres and frames
# The imaginary tip from the nose centre by tip direction, in nose radii
# along (Z, X), from the operator's manual's figure (X up, Z right): 3 an
# outside turning tool's (below the centre, towards the chuck), 2 a boring
# bar's (above it), 0 and 9 the centre itself.
TIP_FROM_CENTRE = {0: (0, 0), 9: (0, 0), 3: (-1, -1), 2: (-1, 1)}
# An arc's start is the end of the move before, found where a line meets
# the arc's offset circle: at a tangent corner R that meeting is
# ill-conditioned, and the start may lie a few increments off the circle.
ARC_TOLERANCE = 0.005
# How far from a corner, in offsets, the elements that meet there count:
# the farthest corner vectors (two extended ones) lie within 1 + sqrt 2.
# Farther off, two elements may close in on each other (a spike between
# arcs that bend towards each other) to less than the tool: the contour's
# fault, which no compensation can help.
CORNER_REACH = 2.5


class Case:
    """A random contour and how it is compensated; render() writes it."""

    def __init__(self, seed):
        rng = random.Random(seed)
        self.seed = seed
        self.lathe = rng.random() < 0.25
        self.tip = rng.choice(sorted(TIP_FROM_CENTRE)) if self.lathe else 0
        self.offset = round(rng.uniform(0.5, 5.0), 3)
        self.side = rng.choice((1, -1))  # G41: left
        self.type_b = rng.random() < 0.5
        # A lathe's contour in (Z, X radius), well off the spindle axis.
        self.center = ((rng.uniform(-60, -20), rng.uniform(55, 70))
                       if self.lathe else
                       (rng.uniform(-20, 20), rng.uniform(-20, 20)))
        count = rng.randint(3, 7)
        angles = []
        while len(angles) < count:
            angle = rng.uniform(0, 2 * math.pi)
            if all(abs((angle - a + math.pi) % (2 * math.pi) - math.pi) >
                   math.radians(25) for a in angles):
                angles.append(angle)
        angles.sort(reverse=rng.random() < 0.5)
        self.vertices = [
            tuple(round(v, 3) for v in add(
                self.center, mul(rng.uniform(25, 45), (math.cos(a),
                                                       math.sin(a)))))
            for a in angles]
        # Per element: None for a line, or (ccw, radius factor).
        self.arcs = [(rng.random() < 0.5, rng.uniform(1.1, 2.5))
                     if rng.random() < 0.35 else None for _ in angles]
        # Per element: the comma word at its end, ("C" or "R", fraction of
        # the most that fits), or None; the last one meets the cancel move.
        self.corners = [(rng.choice("CR"), rng.uniform(0.2, 0.9))
                        if rng.random() < 0.35 else None for _ in angles]
        self.still = [rng.random() < 0.1 for _ in angles]
        self.frame = None if self.lathe else rng.choice(
            (None, None, "G68", "G51.1", "G51", "G52"))
        self.frame_words = {
            "G68": (rng.uniform(-30, 30), rng.uniform(-30, 30),
                    rng.uniform(-180, 180)),
            "G51.1": (rng.choice(("X", "Y", "XY")), rng.uniform(-20, 20),
                      rng.uniform(-20, 20)),
            "G51": (rng.uniform(-20, 20), rng.uniform(-20, 20),
                    rng.choice((0.5, 0.75, 1.5, 2.0))),
            "G52": (rng.uniform(-50, 50), rng.uniform(-50, 50)),
        }.get(self.frame)
        lead = unit(sub(self.vertices[0], self.center))
        self.start = tuple(round(v, 3) for v in
                           add(self.vertices[0], mul(15, lead)))
        self.end = tuple(round(v, 3) for v in add(
            self.vertices[0], mul(15, unit(add(lead, (0.3, -0.4))))))

    # The frame as a program sets it and as the oracle maps points.
    def frame_lines(self):
        if self.frame is None:
            return [], [], Frame()
        w = self.frame_words
        if self.frame == "G68":
            return ([f"G68X{fmt(w[0])}Y{fmt(w[1])}R{fmt(w[2])}"], ["G69"],
                    Frame(angle=round(w[2], 3),
                          rotation_center=(round(w[0], 3), round(w[1], 3))))
        if self.frame == "G51.1":
            axes, mx, my = w
            words = "".join(f"{a}{fmt(v)}" for a, v in (("X", mx), ("Y", my))
                            if a in axes)
            return ([f"G51.1{words}"], ["G50.1X0Y0"],
                    Frame(mirror=(round(mx, 3) if "X" in axes else None,
                                  round(my, 3) if "Y" in axes else None)))
        if self.frame == "G51":
            return ([f"G51X{fmt(w[0])}Y{fmt(w[1])}P{w[2]}"], ["G50"],
                    Frame(scale=w[2],
                          scale_center=(round(w[0], 3), round(w[1], 3))))
        return ([f"G52X{fmt(w[0])}Y{fmt(w[1])}"], ["G52X0Y0"],
                Frame(shift=(round(w[0], 3), round(w[1], 3))))

    def elements(self):
        """The programmed elements in program coordinates, the arcs valid
        for the offset (the tool outside, or inside with room). An arc that
        would meet its neighbour almost head on (a turn of more than 140
        degrees) is a line: two arcs bending towards each other at such a
        corner leave a spike thinner than the tool."""
        elements = self._elements()
        count = len(elements)
        for i in range(count):
            after = (i + 1) % count
            turn = math.degrees(math.acos(max(-1.0, min(1.0, sum(
                p * q for p, q in zip(tangent(elements[i][:5], True),
                                      tangent(elements[after][:5],
                                              False)))))))
            if turn > 140 and (self.arcs[i] or self.arcs[after]):
                self.arcs[i] = self.arcs[after] = None
                return self.elements()
        return elements

    def _elements(self):
        count = len(self.vertices)
        result = []
        for i in range(count):
            a, b = self.vertices[i], self.vertices[(i + 1) % count]
            arc = self.arcs[i]
            if arc is None:
                result.append(("line", a, b))
                continue
            ccw, factor = arc
            chord = norm(sub(b, a))
            radius = round(chord / 2 * factor, 3)
            inside = (self.side > 0) == ccw
            if inside and radius < self.offset + 1:
                radius = round(self.offset + 1 + chord / 2, 3)
            height = math.sqrt(max(radius * radius - chord * chord / 4, 0))
            middle = mul(0.5, add(a, b))
            normal = unit((-(b[1] - a[1]), b[0] - a[0]))
            # A short arc (R > 0) has its centre left of the chord for G03.
            c = add(middle, mul(height if ccw else -height, normal))
            result.append(("arc", a, b, c, ccw, radius))
        return result

    def contour(self):
        """(program lines, the segments of each element block in program
        coordinates, the line of each element block, the start-up line and
        the cancel line)."""
        elements = self.elements()
        count = len(elements)
        opening, closing, _ = self.frame_lines()
        code = "G41" if self.side > 0 else "G42"
        if self.lathe:
            lines = ["%", "O5000(NOSE RADIUS ORACLE)", "G18G21G40G80G97S800M03",
                     f"G00{self.words(self.start)}T0101",
                     f"{code}G01{self.words(self.vertices[0])}F0.2"]
        else:
            lines = ["%", "O5000(CUTTER COMP ORACLE)", "G90G17G21G40G49G80G94",
                     f"G10L12P1R{fmt(self.offset)}",
                     f"G00{self.words(self.start)}Z5.",
                     "G01Z-2.F500.", *opening,
                     f"{code}D1G01{self.words(self.vertices[0])}F400."]
        startup = len(lines)
        segments = [[e[:5]] for e in elements]
        cancel_segment = ("line", self.vertices[0], self.end)
        words = [""] * count
        for i in range(count):
            if self.corners[i] is None or elements[i][0] != "line":
                continue
            after = (segments[i + 1][0] if i + 1 < count else cancel_segment)
            if after[0] != "line":
                continue
            kind, fraction = self.corners[i]
            before = segments[i][-1]
            most = 0.3 * min(norm(sub(before[2], before[1])),
                             norm(sub(after[2], after[1])))
            amount = most * fraction
            if kind == "R":
                turn = math.atan2(abs(cross(unit(sub(before[2], before[1])),
                                            unit(sub(after[2], after[1])))),
                                  sum(p * q for p, q in zip(
                                      unit(sub(before[2], before[1])),
                                      unit(sub(after[2], after[1])))))
                if turn < math.radians(5) or turn > math.radians(150):
                    continue
                amount = most * fraction / math.tan(turn / 2)
                left_turn = cross(sub(before[2], before[1]),
                                  sub(after[2], after[1])) > 0
                if left_turn == (self.side > 0) and \
                        amount < self.offset + 1:
                    continue  # the tool inside a corner R too small for it
            amount = round(amount, 3)
            if amount < 0.01:
                continue
            cut = corner(before, after, kind, amount)
            if cut is None:
                continue
            segments[i][-1] = cut[0]
            segments[i].append(cut[1])
            if i + 1 < count:
                segments[i + 1][0] = cut[2]
            else:
                cancel_segment = cut[2]
            words[i] = f",{kind}{fmt(amount)}"
        element_lines = []
        for i, element in enumerate(elements):
            to = self.words(element[2])
            if element[0] == "line":
                lines.append(f"G01{to}{words[i]}")
            else:
                lines.append(f"G0{3 if element[4] else 2}{to}"
                             f"R{fmt(element[5])}")
            element_lines.append(len(lines))
            if self.still[i] and i + 1 < count and not words[i] and \
                    not self.lathe:
                lines.append("Z-2.5" if i % 2 == 0 else "Z-2.")
        lines.append(f"G40G01{self.words(self.end)}")
        cancel = len(lines)
        lines += ["M30" if self.lathe else "G00Z5.", *closing, "M30", "%"]
        return lines, segments, element_lines, startup, cancel

    def words(self, point):
        """The plane words of a point: X Y, or a lathe's X (a diameter) and
        Z of a point in (Z, X radius)."""
        if self.lathe:
            return f"X{fmt(2 * point[1])}Z{fmt(point[0])}"
        return f"X{fmt(point[0])}Y{fmt(point[1])}"

    def plane_point(self, record):
        """Where a record puts the tool centre (a lathe's nose centre) in
        the plane of the contour."""
        if not self.lathe:
            return (record["x"], record["y"])
        along, across = TIP_FROM_CENTRE[self.tip]
        return (record["z"] - along * self.offset,
                record["x"] / 2 - across * self.offset)

    def arc_centre(self, record):
        if not self.lathe:
            return (record["cx"], record["cy"])
        point = self.plane_point({"z": record["cz"], "x": record["cx"]})
        return point

    def profile(self):
        if self.lathe:
            return json.dumps({"series": "T", "parameters": {
                "5003": 1 if self.type_b else 0}, "tool_offsets": {
                    "1": {"r_geometry": self.offset, "tip": self.tip}}})
        return json.dumps({"parameters": {"5003": 1 if self.type_b else 0}})

    def describe(self):
        machine = f"lathe, tip {self.tip}, nose radius" if self.lathe else "D"
        return (f"seed {self.seed}: {machine} {self.offset}, "
                f"{'G41' if self.side > 0 else 'G42'}, type "
                f"{'B' if self.type_b else 'A'}, frame {self.frame}")


def run(mbc, case, folder):
    """The program, and mbc's toolpath records or an alarm's text."""
    lines = case.contour()[0]
    source = folder / "case.nc"
    source.write_text("\n".join(lines) + "\n")
    profile = folder / "machine.json"
    profile.write_text(case.profile())
    toolpath = folder / "toolpath.jsonl"
    result = subprocess.run(
        [mbc, "run", str(source), "--engine", "interp", "--machine",
         str(profile), "--toolpath", str(toolpath)],
        capture_output=True, text=True, timeout=60)
    if result.returncode != 0:
        return None, result.stderr.strip()
    records = [json.loads(line) for line in toolpath.read_text().splitlines()]
    return records, None


def tool_segments(case, records):
    """(line, segment) of every move of the tool centre, in order."""
    moves = []
    at = None
    for record in records:
        end = case.plane_point(record)
        if at is not None and record["motion"] in ("cw", "ccw"):
            moves.append((record["line"], ("arc", at, end,
                                           case.arc_centre(record),
                                           record["motion"] == "ccw")))
        elif at is not None and end != at:
            moves.append((record["line"], ("line", at, end)))
        at = end
    return moves


def violations(case, records):
    """What the tool-centre path breaks of the properties, as text."""
    _, segments, element_lines, startup, cancel = case.contour()
    frame = case.frame_lines()[2]
    work = [[frame.segment(s) for s in block] for block in segments]
    index_of = {line: i for i, line in enumerate(element_lines)}
    side = case.side * (-1 if frame.reverses() else 1)
    count = len(work)
    found = []
    seen = set()
    for line, move in tool_segments(case, records):
        if move[0] == "arc":
            start = norm(sub(move[1], move[3]))
            end = norm(sub(move[2], move[3]))
            if abs(start - end) > ARC_TOLERANCE:
                found.append(f"line {line}: an arc from radius {start:.4f} to "
                             f"{end:.4f} about ({move[3][0]}, {move[3][1]})")
        if line in (startup, cancel) or line not in index_of:
            continue
        i = index_of[line]
        corners = [(k, work[k][-1][2] if k < i else work[k][0][1])
                   for k in (i - 1, i + 1) if 0 <= k < count]
        for p in points(move):
            near = list(work[i])
            for k, vertex in corners:
                if norm(sub(p, vertex)) <= CORNER_REACH * case.offset:
                    near += work[k]
            gap = min(distance(p, s) for s in near)
            if gap < case.offset - TOLERANCE:
                found.append(f"line {line}: the tool centre at ({p[0]:.4f}, "
                             f"{p[1]:.4f}) is {gap:.4f} from the contour, "
                             f"less than the offset {case.offset}")
                break
        if line not in seen:  # the block's first move: on its offset path
            seen.add(line)
            own = work[i][0]
            for p in points(move):
                across = beside(p, own)
                if abs(across - side * case.offset) > TOLERANCE:
                    found.append(
                        f"line {line}: its first move at ({p[0]:.4f}, "
                        f"{p[1]:.4f}) is {across:+.4f} across its element, "
                        f"not {side * case.offset:+.4f}")
                    break
    return found


def shrink(case, still_fails):
    """A smaller case that still fails: without the frame, corners, Z
    moves, arcs and vertices where the failure stays."""
    changed = True
    while changed:
        changed = False
        trials = []
        if case.frame is not None:
            trials.append(lambda c: setattr(c, "frame", None))
        for i in range(len(case.vertices)):
            if case.corners[i] is not None:
                trials.append(lambda c, i=i: c.corners.__setitem__(i, None))
            if case.still[i]:
                trials.append(lambda c, i=i: c.still.__setitem__(i, False))
            if case.arcs[i] is not None:
                trials.append(lambda c, i=i: c.arcs.__setitem__(i, None))
            if len(case.vertices) > 3:
                trials.append(lambda c, i=i: [lst.pop(i) for lst in (
                    c.vertices, c.arcs, c.corners, c.still)])
        for trial in trials:
            smaller = copy_case(case)
            trial(smaller)
            if still_fails(smaller):
                case, changed = smaller, True
                break
    return case


def copy_case(case):
    other = Case.__new__(Case)
    other.__dict__ = {k: (list(v) if isinstance(v, list) else v)
                      for k, v in case.__dict__.items()}
    return other
