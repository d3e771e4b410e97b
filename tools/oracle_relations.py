"""Metamorphic relations of the machine model: two programs that must make
the same path, or one path and its image under a frame, checked on random
motion programs without reading mbc's geometry:

* frames: the program under G52 or G92 (a shift), G68 (a rotation), G51.1
  (a mirror, which turns arcs and swaps G41/G42) or G51 (scaling, without
  compensation: the offset is not scaled) makes the plain program's path
  moved by the oracle's own transform (oracle_geometry.Frame);
* G91: the same path written with incremental words;
* calls: part of the program in a subprogram (M98) or a macro (G65) makes
  the path of the program that has it inline;
* G16: points written as a radius and an angle make the path of their
  Cartesian twins, to the rounding of the conversion;
* a tool length offset given in a later block (G43 H, preferably in the
  block after a chamfer or corner R, whose moves that block makes): the
  plain path, the machine Z higher by the offset from that block's own
  moves on, and not for the moves of the blocks before it.

A motion program is a list of blocks: rapids and feeds (with ,C and ,R
corners between lines), arcs with R or I J, a drilling cycle, and
contours under cutter compensation."""

import json
import math
import random
import subprocess

from oracle_geometry import Frame, fmt

TOLERANCE = 0.0025  # each side rounds its points to 0.001 mm
LENGTH = 25.0  # H1, which the length relation's G43 takes
FORMS = ("absolute", "incremental", "polar")


def point(rng, reach=40.0):
    return (round(rng.uniform(-reach, reach), 3),
            round(rng.uniform(-reach, reach), 3))


def on_circle(centre, radius, near):
    """The point of a circle nearest `near`, rounded to the increment."""
    angle = math.atan2(near[1] - centre[1], near[0] - centre[0])
    return (round(centre[0] + radius * math.cos(angle), 3),
            round(centre[1] + radius * math.sin(angle), 3))


def contour_points(rng, at):
    """The corners of a contour from `at` out to its lead-out (3, -2) past
    the last: no turn sharper than 150 degrees, where an inner corner's
    intersection moves far for a rounding of the points (ill-conditioned:
    a frame's rounding would show as a difference); None when none found."""
    for _ in range(20):
        points = [point(rng, 30) for _ in range(rng.randint(2, 4))]
        path = [at, *points, (points[-1][0] + 3.0, points[-1][1] - 2.0)]
        legs = [(b[0] - a[0], b[1] - a[1]) for a, b in zip(path, path[1:])]
        if all(math.hypot(*leg) > 2.0 for leg in legs) and all(
                math.cos(math.radians(150)) * math.hypot(*u) * math.hypot(*v)
                < u[0] * v[0] + u[1] * v[1] for u, v in zip(legs, legs[1:])):
            return points
    return None


def polar_words(p):
    """A point as G16's radius and angle, each rounded to 0.001."""
    return (round(math.hypot(*p), 3),
            round(math.degrees(math.atan2(p[1], p[0])), 3))


def polar_point(p):
    """The point G16's rounded radius and angle of `p` name."""
    radius, angle = polar_words(p)
    return (round(radius * math.cos(math.radians(angle)), 3),
            round(radius * math.sin(math.radians(angle)), 3))


class Motion:
    """A random motion program: blocks as data, written out in each form
    that a relation compares."""

    def __init__(self, seed):
        rng = random.Random(seed)
        self.seed = seed
        self.blocks = []  # (kind, data)
        at = (0.0, 0.0)
        for _ in range(rng.randint(4, 10)):
            roll = rng.random()
            if roll < 0.3:
                at = point(rng)
                self.blocks.append(("rapid", (at, rng.choice((5.0, 2.0,
                                                              -1.5)))))
            elif roll < 0.6:
                at = point(rng)
                corner = None
                if rng.random() < 0.5:
                    corner = f",{rng.choice('CR')}" \
                             f"{fmt(round(rng.uniform(0.2, 1.5), 3))}"
                self.blocks.append(("line", (at, corner)))
                if corner:  # the corner needs a line after it
                    at = point(rng)
                    self.blocks.append(("line", (at, None)))
            elif roll < 0.8:
                to = point(rng)
                chord = math.dist(at, to)
                if chord < 1.0:
                    continue
                ccw = rng.random() < 0.5
                if rng.random() < 0.5:
                    radius = round(chord / 2 * rng.uniform(1.05, 3), 3)
                    self.blocks.append(("arc", (to, ccw, "R", radius)))
                else:
                    # A centre on the perpendicular bisector; the end point
                    # moved onto its circle.
                    middle = ((at[0] + to[0]) / 2, (at[1] + to[1]) / 2)
                    normal = (-(to[1] - at[1]) / chord,
                              (to[0] - at[0]) / chord)
                    k = rng.uniform(-1.5, 1.5) * chord
                    centre = (round(middle[0] + k * normal[0], 3),
                              round(middle[1] + k * normal[1], 3))
                    to = on_circle(centre, math.dist(at, centre), to)
                    self.blocks.append(("arc", (to, ccw, "IJ", centre)))
                at = to
            elif roll < 0.9:
                holes = [point(rng) for _ in range(rng.randint(1, 3))]
                self.blocks.append(("drill", (holes, rng.random() < 0.5)))
                at = holes[-1]
            else:
                points = contour_points(rng, at)
                if points is None:
                    continue
                self.blocks.append(("contour", (points, rng.choice(
                    ("G41", "G42")), round(rng.uniform(0.2, 1.0), 3))))
                at = (points[-1][0] + 3.0, points[-1][1] - 2.0)
        # The blocks a call takes: never a line with its corner apart from
        # the line after it.
        bounds = [b for b in range(len(self.blocks) + 1)
                  if b == 0 or self.blocks[b - 1][0] != "line" or
                  self.blocks[b - 1][1][1] is None]
        self.call_span = sorted(rng.sample(bounds, 2)) if len(bounds) > 1 \
            else (0, 0)

    def polar_twin(self):
        """The program whose Cartesian points are those the polar form's
        radius and angle (each rounded to 0.001) name, rounded to the
        increment as the control converts them: what text(form="polar")
        must make."""
        twin = Motion.__new__(Motion)
        twin.__dict__ = dict(self.__dict__)
        snap = polar_point
        twin.blocks = []
        for kind, data in self.blocks:
            if kind == "rapid":
                data = (snap(data[0]), data[1])
            elif kind == "line":
                data = (snap(data[0]), data[1])
            elif kind == "drill":
                data = ([snap(hole) for hole in data[0]], data[1])
            twin.blocks.append((kind, data))
        return twin

    def compensates(self):
        return any(kind == "contour" for kind, _ in self.blocks)

    def length_block(self):
        """The block the length relation gives G43 H1: a line after a
        line with a corner when there is one, else any line or rapid;
        None when the program has neither."""
        moves = [i for i, (kind, _) in enumerate(self.blocks)
                 if kind in ("line", "rapid")]
        after_corner = [i for i in moves if i > 0 and
                        self.blocks[i - 1][0] == "line" and
                        self.blocks[i - 1][1][1]]
        return (after_corner or moves or [None])[0]

    def text(self, form="absolute", frame_lines=(), caller=None,
             length_at=None):
        """The program: `form` one of FORMS (polar: the lines, rapids and
        holes as G16 radius and angle); `frame_lines` after the opening;
        `caller` "M98" or "G65" moves call_span's blocks into O2000;
        `length_at` a block that gets G43 H1. self.line_of holds the line
        each block starts at."""
        state = {"at": (0.0, 0.0), "z": 5.0, "polar": False}
        head = ["%", "O4000(MOTION ORACLE)", "G90G17G21G40G49G80G94G98",
                f"G10L10P1R{fmt(LENGTH)}", "G00X0Y0Z5.", *frame_lines,
                "G00G90X0Y0Z5."]
        body, called = [], []
        first, last = self.call_span
        self.line_of = {}
        for i, (kind, data) in enumerate(self.blocks):
            lines = self._block(kind, data, form, state)
            if i == length_at:
                lines[0] = "G43H1" + lines[0]
            self.line_of[i] = len(head) + len(body) + 1
            (called if caller and first <= i < last else body).extend(lines)
            if caller and i + 1 == last:
                body.append(f"{caller}P2000")
        # The frame, then the program's first point in its coordinates: a
        # frame set under a standing tool moves the program position.
        program = [*head, *body, "G15G80G40G90G00Z5.", "M30"]
        if caller:
            program += ["O2000", *called, "M99"]
        return "\n".join(program + ["%"]) + "\n"

    def _xy(self, to, state, form, polar=True):
        """The X Y words of a move to `to` in the form asked for."""
        x, y = to
        start = state["at"]
        state["at"] = to
        if form == "incremental":
            return f"G91X{fmt(round(x - start[0], 3))}" \
                   f"Y{fmt(round(y - start[1], 3))}"
        if form == "polar" and polar:
            state["polar"] = True
            state["at"] = polar_point(to)
            radius, angle = polar_words(to)
            return f"G90G16X{fmt(radius)}Y{fmt(angle)}"
        return f"{self._cartesian(state)}G90X{fmt(x)}Y{fmt(y)}"

    @staticmethod
    def _cartesian(state):
        """G15 when G16 is in force."""
        if state["polar"]:
            state["polar"] = False
            return "G15"
        return ""

    def _z(self, z, state, form):
        """A rapid of Z alone to `z`, or nothing."""
        if z == state["z"]:
            return []
        line = (f"G00G91Z{fmt(round(z - state['z'], 3))}"
                if form == "incremental" else f"G00G90Z{fmt(z)}")
        state["z"] = z
        return [line]

    def _block(self, kind, data, form, state):
        if kind == "rapid":
            to, z = data
            return [f"G00{self._xy(to, state, form)}",
                    *self._z(z, state, form)]
        if kind == "line":
            to, corner = data
            return [f"G01{self._xy(to, state, form)}F500.{corner or ''}"]
        if kind == "arc":
            to, ccw, how, value = data
            start = state["at"]
            words = self._xy(to, state, form, polar=False)
            centre = (f"R{fmt(value)}" if how == "R" else
                      f"I{fmt(round(value[0] - start[0], 3))}"
                      f"J{fmt(round(value[1] - start[1], 3))}")
            return [f"G0{3 if ccw else 2}{words}{centre}F300."]
        if kind == "drill":
            holes, to_r = data
            lines = self._z(5.0, state, form)
            words = ("G91R-3.Z-4." if form == "incremental" else "Z-2.R2.")
            for k, hole in enumerate(holes):
                xy = self._xy(hole, state, form)
                lines.append(f"{'G99' if to_r else 'G98'}G81{xy}{words}F200."
                             if k == 0 else xy)
            lines.append("G80")
            state["z"] = 2.0 if to_r else 5.0
            return lines + self._z(5.0, state, form)
        points, code, offset = data
        # G90: in G91 the G10 would add to the offset.
        lines = [f"{self._cartesian(state)}G90G10L12P1R{fmt(offset)}"]
        for k, p in enumerate(points):
            xy = self._xy(p, state, form, polar=False)
            lines.append(f"{code}D1G01{xy}F400." if k == 0 else f"G01{xy}")
        leave = (points[-1][0] + 3.0, points[-1][1] - 2.0)
        lines.append(f"G40G01{self._xy(leave, state, form, polar=False)}")
        return lines


def frames(rng, compensates):
    """(name, program lines, the oracle's frame of workpiece positions and
    of machine positions, None when the same) of one frame at random."""
    choices = ["G52", "G92", "G68", "G51.1"] + ([] if compensates else
                                                ["G51"])
    name = rng.choice(choices)
    a, b = point(rng, 30)
    if name == "G52":
        return name, [f"G52X{fmt(a)}Y{fmt(b)}"], Frame(shift=(a, b)), None
    if name == "G92":
        # The tool at X0 Y0 becomes -a -b: every machine point moves by a b.
        return (name, [f"G92X{fmt(-a)}Y{fmt(-b)}"], Frame(),
                Frame(shift=(a, b)))
    if name == "G68":
        angle = round(rng.uniform(-180, 180), 3)
        return (name, [f"G68X{fmt(a)}Y{fmt(b)}R{fmt(angle)}"],
                Frame(angle=angle, rotation_center=(a, b)), None)
    if name == "G51.1":
        axes = rng.choice(("X", "Y", "XY"))
        words = "".join(f"{axis}{fmt(v)}" for axis, v in (("X", a), ("Y", b))
                        if axis in axes)
        return (name, [f"G51.1{words}"],
                Frame(mirror=(a if "X" in axes else None,
                              b if "Y" in axes else None)), None)
    scale = rng.choice((0.5, 0.75, 1.5, 2.0))
    return (name, [f"G51X{fmt(a)}Y{fmt(b)}Z0P{scale}"],
            Frame(scale=scale, scale_center=(a, b)), None)


def run(mbc, text, folder, name):
    """mbc's toolpath records of a program, or its error text."""
    source = folder / f"{name}.nc"
    source.write_text(text)
    toolpath = folder / f"{name}.jsonl"
    result = subprocess.run(
        [mbc, "run", str(source), "--engine", "interp", "--toolpath",
         str(toolpath)], capture_output=True, text=True, timeout=60)
    if result.returncode != 0:
        return None, result.stderr.strip()
    return [json.loads(line) for line in
            toolpath.read_text().splitlines()], None


def differences(plain, other, work=Frame(), machine=None, z_scale=1.0):
    """Where `other`'s records are not `plain`'s moved by the frames: each
    record's kind (an arc turning the other way under a mirror), end point
    and arc centre in workpiece coordinates by `work`, and its end in
    machine coordinates by `machine` (`work` when None: the tests' machine
    has no work or tool offsets in the plane)."""
    machine = machine or work
    # The first move goes to the start before any frame: not compared.
    plain, other = plain[1:], other[1:]
    if len(plain) != len(other):
        return [f"{len(plain)} moves, and {len(other)} with the relation"]
    found = []
    for n, (a, b) in enumerate(zip(plain, other), 1):
        kind = a["motion"]
        if work.reverses() and kind in ("cw", "ccw"):
            kind = "ccw" if kind == "cw" else "cw"
        pairs = [(work.point((a["x"], a["y"])), (b["x"], b["y"])),
                 (machine.point((a["mx"], a["my"])), (b["mx"], b["my"]))]
        if kind in ("cw", "ccw"):
            pairs.append((work.point((a["cx"], a["cy"])), (b["cx"], b["cy"])))
        wrong = kind != b["motion"] or \
            abs(a["z"] * z_scale - b["z"]) > TOLERANCE or \
            any(math.dist(want, got) > TOLERANCE for want, got in pairs)
        if wrong:
            want = pairs[0][0]
            found.append(f"move {n} (line {a['line']} / {b['line']}): "
                         f"{kind} to ({want[0]:.4f}, {want[1]:.4f}, "
                         f"{a['z'] * z_scale:.4f}) (machine "
                         f"{pairs[1][0][0]:.4f}, {pairs[1][0][1]:.4f}), but "
                         f"{b['motion']} to ({b['x']}, {b['y']}, {b['z']}) "
                         f"(machine {b['mx']}, {b['my']})")
    return found


def length_differences(plain, other, line):
    """Where `other` (the program with G43 H1 at `line`) is not `plain`
    with the machine Z higher by LENGTH from the moves of `line` on: the
    moves a held block makes during that block stay at its own length."""
    if len(plain) != len(other):
        return [f"{len(plain)} moves, and {len(other)} with G43 at line "
                f"{line}"]
    found = []
    for n, (a, b) in enumerate(zip(plain, other), 1):
        rise = LENGTH if a["line"] >= line else 0.0
        same = all(a[k] == b[k] for k in ("motion", "line", "x", "y", "z"))
        if not same or abs(a["mz"] + rise - b["mz"]) > TOLERANCE:
            found.append(f"move {n} (line {a['line']}): {a['motion']} to "
                         f"({a['x']}, {a['y']}, {a['z']}) at machine Z "
                         f"{a['mz'] + rise:.4f}, but {b['motion']} to "
                         f"({b['x']}, {b['y']}, {b['z']}) at {b['mz']}")
    return found


def relations(mbc, motion, folder, rng):
    """(relation name, what differs) for each relation that fails, and the
    number checked; an error of a run counts as a difference. None when
    the plain program alarms."""
    plain, error = run(mbc, motion.text(), folder, "plain")
    if plain is None:
        return None, 0  # the plain program alarms: nothing to compare
    failed = []
    checked = 0
    name, lines, frame, machine = frames(rng, motion.compensates())
    trials = [
        (f"under {name}", motion.text(frame_lines=lines), frame, machine,
         frame.scale if name == "G51" else 1.0),
        ("G91", motion.text(form="incremental"), Frame(), None, 1.0),
        ("M98", motion.text(caller="M98"), Frame(), None, 1.0),
        ("G65", motion.text(caller="G65"), Frame(), None, 1.0),
    ]
    twin, _ = run(mbc, motion.polar_twin().text(), folder, "twin")
    if twin is not None:  # the polar form against its Cartesian twin
        records, error = run(mbc, motion.text(form="polar"), folder, "G16")
        checked += 1
        found = [error] if records is None else differences(twin, records)
        if found:
            failed.append(("G16", found))
    at = motion.length_block()
    if at is not None:  # a tool length offset from a later block on
        text = motion.text(length_at=at)
        records, error = run(mbc, text, folder, "G43")
        checked += 1
        found = ([error] if records is None else
                 length_differences(plain, records, motion.line_of[at]))
        if found:
            failed.append(("G43", found))
    for relation, text, moved, on_machine, z_scale in trials:
        records, error = run(mbc, text, folder, relation.replace(" ", "_"))
        checked += 1
        found = ([error] if records is None else
                 differences(plain, records, moved, on_machine, z_scale))
        if found:
            failed.append((relation, found))
    return failed, checked
