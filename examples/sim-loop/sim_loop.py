#!/usr/bin/env python3
"""The simulation loop of sim_loop.cpp from Python, through ctypes.

`mbc compile --shared pocket.nc -o libpocket.so` makes a shared library
holding the compiled cycle O9200 (entry point mbc_O9200) and the whole mbc
runtime (its C ABI, mbc/runtime.h). This script calls the cycle for the
same parameter sets as sim_loop.cpp, consumes the motions through the
motion callback, and prints the same totals and its own throughput.

    python3 sim_loop.py path/to/libpocket.so [CALLS]    (default 2000)
"""
import ctypes
import math
import sys
import time

MAX_AXES = 8  # MBRT_MAX_AXES
RAPID, LINEAR, CW, CCW = 0, 1, 2, 3  # enum mbrt_motion_kind
WORD_VALUE = 2  # MBRT_WORD_VALUE: a real value, as from a variable


class Motion(ctypes.Structure):
    """struct mbrt_motion (runtime.h), field for field."""
    _fields_ = [("kind", ctypes.c_int),
                ("axis_count", ctypes.c_int),
                ("axis_names", ctypes.c_char_p),
                ("end", ctypes.c_double * MAX_AXES),
                ("feed", ctypes.c_double),
                ("plane", ctypes.c_int),
                ("center_axes", ctypes.c_char * 2),
                ("center", ctypes.c_double * 2),
                ("decimals", ctypes.c_int),
                ("file", ctypes.c_char_p),
                ("line", ctypes.c_int),
                ("program", ctypes.c_char_p),
                ("cycle", ctypes.c_int),
                ("machine", ctypes.c_double * MAX_AXES),
                ("start", ctypes.c_double * MAX_AXES)]


class Word(ctypes.Structure):
    """struct mbrt_word: an argument as G65 passes it."""
    _fields_ = [("letter", ctypes.c_char),
                ("kind", ctypes.c_ubyte),
                ("value", ctypes.c_double)]


MotionFn = ctypes.CFUNCTYPE(None, ctypes.c_void_p, ctypes.POINTER(Motion))


def load(path):
    lib = ctypes.CDLL(path)
    lib.mbrt_create.restype = ctypes.c_void_p
    lib.mbrt_create.argtypes = [ctypes.c_char_p, ctypes.c_char_p,
                                ctypes.c_size_t]
    lib.mbrt_destroy.argtypes = [ctypes.c_void_p]
    lib.mbrt_set_motion_sink.argtypes = [ctypes.c_void_p, MotionFn,
                                         ctypes.c_void_p]
    lib.mbrt_read_var.argtypes = [ctypes.c_void_p, ctypes.c_double,
                                  ctypes.POINTER(ctypes.c_double)]
    lib.mbrt_alarm_report.restype = ctypes.c_size_t
    lib.mbrt_alarm_report.argtypes = [ctypes.c_void_p, ctypes.c_char_p,
                                      ctypes.c_size_t]
    lib.mbc_O9200.restype = ctypes.c_int
    lib.mbc_O9200.argtypes = [ctypes.c_void_p, ctypes.POINTER(Word),
                              ctypes.c_size_t]
    return lib


class Totals:
    def __init__(self):
        self.alarms = self.motions = self.circles = 0
        self.feed_length = self.rapid_length = self.cutting_minutes = 0.0

    def add(self, m):
        """The motion callback: lengths as sim_loop.cpp measures them."""
        self.motions += 1
        start, end = m.start, m.end
        if m.kind == RAPID:
            self.rapid_length += math.dist(start[:3], end[:3])
            return
        if m.kind == LINEAR:
            length = math.dist(start[:3], end[:3])
        else:
            sx, sy = start[0] - m.center[0], start[1] - m.center[1]
            ex, ey = end[0] - m.center[0], end[1] - m.center[1]
            sweep = math.atan2(ey, ex) - math.atan2(sy, sx)
            if m.kind == CCW:
                sweep = sweep + 2 * math.pi if sweep <= 0 else sweep
            else:
                sweep = sweep - 2 * math.pi if sweep >= 0 else sweep
            planar = abs(sweep) * math.hypot(sx, sy)
            length = math.hypot(planar, end[2] - start[2])
        self.feed_length += length
        self.cutting_minutes += length / m.feed


def pocket_args(i):
    """Parameter set i, the same as sim_loop.cpp's."""
    refused = i % 1000 == 999
    values = (("X", (i % 5) * 100.0), ("Y", 0.0), ("Z", -2.0 - i % 7),
              ("R", 10.0 if refused else 10.0 + (i % 40) * 0.5),
              ("D", 40.0 if refused else 6.0 + (i % 3) * 2.0), ("Q", 1.5),
              ("F", 300.0 + (i % 4) * 100.0))
    return (Word * len(values))(*(Word(k.encode(), WORD_VALUE, v) for k, v in values))


def main():
    if len(sys.argv) < 2:
        print(__doc__, file=sys.stderr)
        return 2
    lib = load(sys.argv[1])
    calls = int(sys.argv[2]) if len(sys.argv) > 2 else 2000
    err = ctypes.create_string_buffer(256)
    ctx = lib.mbrt_create(None, err, len(err))
    if not ctx:
        print(f"sim-loop: cannot create a context: {err.value.decode()}",
              file=sys.stderr)
        return 1
    totals = Totals()
    sink = MotionFn(lambda user, m: totals.add(m.contents))
    lib.mbrt_set_motion_sink(ctx, sink, None)
    circles = ctypes.c_double()
    report = ctypes.create_string_buffer(512)
    began = time.perf_counter()
    for i in range(calls):
        args = pocket_args(i)
        if lib.mbc_O9200(ctx, args, len(args)) != 0:
            totals.alarms += 1
            if totals.alarms == 1:
                lib.mbrt_alarm_report(ctx, report, len(report))
                print(f"sim-loop: call {i}: {report.value.decode()}", end="")
            continue
        lib.mbrt_read_var(ctx, 100, ctypes.byref(circles))
        totals.circles += int(circles.value)
    seconds = time.perf_counter() - began
    lib.mbrt_destroy(ctx)
    print(f"sim-loop: {calls} calls, {totals.alarms} alarms, "
          f"{totals.motions} motions, {totals.circles} circles")
    print(f"sim-loop: feed path {totals.feed_length:.3f} mm, rapid path "
          f"{totals.rapid_length:.3f} mm, cutting time "
          f"{totals.cutting_minutes:.3f} min")
    print(f"throughput: {calls / seconds:.0f} calls/s, "
          f"{totals.motions / seconds / 1e6:.2f} M motions/s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
