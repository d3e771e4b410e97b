"""Plane geometry of the oracles, written apart from mbc's runtime: points,
lines and arcs of a programmed contour, the corners a chamfer or corner R
cuts into it, the frames that map it into the workpiece, and the distance
of a tool-centre point from it.

A segment is ("line", a, b) or ("arc", a, b, centre, ccw): a and b its ends,
an arc turning counter-clockwise from a to b when ccw, else clockwise, and
never more than a full turn."""

import math


def fmt(value):
    """A coordinate as a program writes it: three decimals at most, and a
    decimal point."""
    text = f"{value:.3f}".rstrip("0")
    return "0" if text in ("-0.", "0.") else text


def add(a, b):
    return (a[0] + b[0], a[1] + b[1])


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1])


def mul(k, a):
    return (k * a[0], k * a[1])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1]


def cross(a, b):
    return a[0] * b[1] - a[1] * b[0]


def norm(a):
    return math.hypot(a[0], a[1])


def unit(a):
    n = norm(a)
    return (a[0] / n, a[1] / n)


def left(a):
    return (-a[1], a[0])


def turned(a, angle):
    c, s = math.cos(angle), math.sin(angle)
    return (c * a[0] - s * a[1], s * a[0] + c * a[1])


def sweep(seg):
    """How far an arc turns from its start to its end, 0 to 2 pi."""
    _, a, b, c, ccw = seg
    start = math.atan2(a[1] - c[1], a[0] - c[0])
    end = math.atan2(b[1] - c[1], b[0] - c[0])
    turn = (end - start) if ccw else (start - end)
    turn %= 2 * math.pi
    return turn if turn > 1e-12 else 2 * math.pi


def tangent(seg, at_end):
    """The direction of travel at the start or the end of a segment."""
    if seg[0] == "line":
        return unit(sub(seg[2], seg[1]))
    _, a, b, c, ccw = seg
    radial = unit(sub(b if at_end else a, c))
    return left(radial) if ccw else mul(-1, left(radial))


def points(seg, count=24):
    """Points along a segment, both ends included."""
    if seg[0] == "line":
        a, b = seg[1], seg[2]
        return [add(a, mul(i / count, sub(b, a))) for i in range(count + 1)]
    _, a, _, c, ccw = seg
    radius = norm(sub(a, c))
    start = math.atan2(a[1] - c[1], a[0] - c[0])
    turn = sweep(seg) * (1 if ccw else -1)
    return [add(c, (radius * math.cos(start + turn * i / count),
                    radius * math.sin(start + turn * i / count)))
            for i in range(count + 1)]


def distance(p, seg):
    """The distance of p from the segment (its points, ends included)."""
    if seg[0] == "line":
        a, b = seg[1], seg[2]
        ab = sub(b, a)
        length2 = dot(ab, ab)
        t = 0.0 if length2 == 0 else max(0.0, min(1.0, dot(sub(p, a), ab) /
                                                  length2))
        return norm(sub(p, add(a, mul(t, ab))))
    _, a, b, c, ccw = seg
    radius = norm(sub(a, c))
    angle = math.atan2(p[1] - c[1], p[0] - c[0])
    start = math.atan2(a[1] - c[1], a[0] - c[0])
    along = ((angle - start) if ccw else (start - angle)) % (2 * math.pi)
    if along <= sweep(seg):
        return abs(norm(sub(p, c)) - radius)
    return min(norm(sub(p, a)), norm(sub(p, b)))


def beside(p, seg):
    """Where p lies across a segment's line or circle: positive on its left
    (travelling along it), negative on its right, the distance from it."""
    if seg[0] == "line":
        return cross(unit(sub(seg[2], seg[1])), sub(p, seg[1]))
    _, a, _, c, ccw = seg
    outside = norm(sub(p, c)) - norm(sub(a, c))
    return -outside if ccw else outside


def corner(first, second, kind, amount):
    """The chamfer (kind "C") or corner R ("R") of `amount` between two
    lines meeting at first's end: (first cut short, the inserted segment,
    second starting later), or None where it does not fit."""
    p = first[2]
    u1 = unit(sub(first[2], first[1]))
    u2 = unit(sub(second[2], second[1]))
    turn = cross(u1, u2)
    if kind == "C":
        back, ahead = amount, amount
    else:
        angle = math.atan2(abs(turn), dot(u1, u2))
        if angle < 1e-6:
            return None
        back = ahead = amount * math.tan(angle / 2)
    if back >= norm(sub(first[2], first[1])) or \
            ahead >= norm(sub(second[2], second[1])):
        return None
    leave = sub(p, mul(back, u1))
    join = add(p, mul(ahead, u2))
    if kind == "C":
        inserted = ("line", leave, join)
    else:
        side = left(u1) if turn > 0 else mul(-1, left(u1))
        inserted = ("arc", leave, join, add(leave, mul(amount, side)),
                    turn > 0)
    return ("line", first[1], leave), inserted, ("line", join, second[2])


class Frame:
    """What mirror, scaling, rotation and a shift do to a program point, in
    that order (FANUC: mirror, then scaling, then rotation), and whether it
    turns arcs the other way."""

    def __init__(self, mirror=(None, None), scale=1.0, scale_center=(0, 0),
                 angle=0.0, rotation_center=(0, 0), shift=(0, 0)):
        self.mirror = mirror
        self.scale = scale
        self.scale_center = scale_center
        self.angle = math.radians(angle)
        self.rotation_center = rotation_center
        self.shift = shift

    def point(self, p):
        x, y = p
        if self.mirror[0] is not None:
            x = 2 * self.mirror[0] - x
        if self.mirror[1] is not None:
            y = 2 * self.mirror[1] - y
        x = self.scale_center[0] + (x - self.scale_center[0]) * self.scale
        y = self.scale_center[1] + (y - self.scale_center[1]) * self.scale
        x, y = add(self.rotation_center,
                   turned(sub((x, y), self.rotation_center), self.angle))
        return add((x, y), self.shift)

    def reverses(self):
        return (self.mirror[0] is not None) != (self.mirror[1] is not None)

    def segment(self, seg):
        if seg[0] == "line":
            return ("line", self.point(seg[1]), self.point(seg[2]))
        _, a, b, c, ccw = seg
        return ("arc", self.point(a), self.point(b), self.point(c),
                ccw != self.reverses())
