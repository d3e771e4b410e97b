#!/usr/bin/env python3
"""The simulation loop of sim_loop.cpp from Python, with the mbc package.

pocket.nc is compiled in process (mbc.compile, through the compiled-code
cache); O9200 is called for the same parameter sets as sim_loop.cpp on one
mbc.Machine, each call's motions come back as a numpy array, and the same
totals are computed from them with numpy, a thousand calls' arrays joined
at a time (mbc.concatenate). It prints the totals and its own throughput.

    python3 sim_loop.py [CALLS] [--calls-only]
        CALLS: default 2000; --calls-only: the calls and their motions
        arrays without the totals, for the throughput of the calls alone
        (PYTHONPATH=build/python in the build tree)
"""
import os
import sys
import time

import numpy

import mbc

RAPID, LINEAR, CW, CCW = 0, 1, 2, 3  # mbc.MOTION_NAMES


class Totals:
    def __init__(self):
        self.alarms = self.motions = self.circles = 0
        self.feed_length = self.rapid_length = self.cutting_minutes = 0.0

    def add(self, calls):
        """Some calls' motions: lengths as sim_loop.cpp measures them."""
        m = mbc.concatenate(calls)
        calls.clear()
        self.motions += len(m)
        dx, dy, dz = m["x"] - m["sx"], m["y"] - m["sy"], m["z"] - m["sz"]
        length = numpy.sqrt(dx * dx + dy * dy + dz * dz)
        kind = m["motion"]
        arcs = numpy.flatnonzero(kind >= CW)
        a = m[arcs]
        sx, sy = a["sx"] - a["cx"], a["sy"] - a["cy"]
        ex, ey = a["x"] - a["cx"], a["y"] - a["cy"]
        sweep = numpy.arctan2(ey, ex) - numpy.arctan2(sy, sx)
        ccw = a["motion"] == CCW
        sweep[ccw & (sweep <= 0)] += 2 * numpy.pi
        sweep[~ccw & (sweep >= 0)] -= 2 * numpy.pi
        length[arcs] = numpy.hypot(numpy.abs(sweep) * numpy.hypot(sx, sy),
                                   dz[arcs])
        rapid = kind == RAPID
        feed = ~rapid
        self.rapid_length += float(length[rapid].sum())
        self.feed_length += float(length[feed].sum())
        self.cutting_minutes += float((length[feed] / m["f"][feed]).sum())


def pocket_args(i):
    """Parameter set i, the same as sim_loop.cpp's."""
    refused = i % 1000 == 999
    return {"X": (i % 5) * 100.0, "Y": 0.0, "Z": -2.0 - i % 7,
            "R": 10.0 if refused else 10.0 + (i % 40) * 0.5,
            "D": 40.0 if refused else 6.0 + (i % 3) * 2.0, "Q": 1.5,
            "F": 300.0 + (i % 4) * 100.0}


def main():
    calls = int(sys.argv[1]) if len(sys.argv) > 1 else 2000
    totalled = "--calls-only" not in sys.argv[2:]
    # From its folder, so that alarm reports name pocket.nc as sim_loop.cpp's do.
    os.chdir(os.path.dirname(os.path.abspath(__file__)))
    pocket = mbc.compile("pocket.nc")
    machine = mbc.Machine()
    totals = Totals()
    pending = []
    began = time.perf_counter()
    for i in range(calls):
        try:
            result = pocket(machine, **pocket_args(i))
        except mbc.Alarm as alarm:
            totals.alarms += 1
            if totals.alarms == 1:
                print(f"sim-loop: call {i}: {alarm.report}", end="")
            pending.append(alarm.result.motions)
            continue
        pending.append(result.motions)
        totals.circles += int(result.variables[100])
        if len(pending) >= 1000:
            if totalled:
                totals.add(pending)
            else:
                totals.motions += sum(len(m) for m in pending)
                pending.clear()
    if pending and totalled:
        totals.add(pending)
    elif pending:
        totals.motions += sum(len(m) for m in pending)
    seconds = time.perf_counter() - began
    print(f"sim-loop: {calls} calls, {totals.alarms} alarms, "
          f"{totals.motions} motions, {totals.circles} circles")
    if totalled:
        print(f"sim-loop: feed path {totals.feed_length:.3f} mm, rapid path "
              f"{totals.rapid_length:.3f} mm, cutting time "
              f"{totals.cutting_minutes:.3f} min")
    print(f"throughput: {calls / seconds:.0f} calls/s, "
          f"{totals.motions / seconds / 1e6:.2f} M motions/s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
