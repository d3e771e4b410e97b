#!/usr/bin/env python3
"""G70's finishing contour against an independent oracle: rs274.

A shape program read by G71 and finished by G70 on a FANUC lathe (diameter
X, U/W increments in G code system A, arcs by R and by I/K as radii), and
the same profile in absolute words as a LinuxCNC subroutine that its G70 (lathe mode, G7)
follows. Every move of mbc's G70 but its rapid return to the start point
(LinuxCNC's G70 stays at the shape's end) must end, and every arc turn
about, the point rs274's does. Fails when rs274 is not installed.

    tests/lathe_g70_rs274.py MBC
"""

import sys

from lathe_rs274 import compare, run_mbc, run_rs274
from rs274_oracle import collect

# The shape's blocks: the FANUC lathe's and LinuxCNC's.
SHAPE = [
    ("N100G00X18.", "G0 X18"),
    ("G01Z0.F.08", "G1 Z0"),
    ("X24.Z-3.", "X24 Z-3"),
    ("W-12.", "Z-15"),
    ("G02U8.W-4.R4.", "G2 X32 Z-19 R4"),
    ("G01X36.987", "G1 X36.987"),
    ("G03X44.987Z-23.I0K-4.", "G3 X44.987 Z-23 I0 K-4"),
    ("G01Z-35.", "G1 Z-35"),
    ("G02X54.987Z-40.R5.", "G2 X54.987 Z-40 R5"),
    ("N200G01X60.Z-42.5", "G1 X60 Z-42.5"),
]

FANUC = ("%\nO4100(BUSH OD)\nG18G21G40G97G99S900M03\nT0101\n"
         "G00X64.Z2.\nG71U1.5R.5\nG71P100Q200U.4W.1F.25\n" +
         "\n".join(fanuc for fanuc, _ in SHAPE) +
         "\nG70P100Q200\nG00X100.Z100.\nM30\n%\n")

LINUXCNC = ("G18 G21 G7 G90\nS900 M3\nG0 X64 Z2\nF100\nG70 Q100\nM2\n"
            "O100 sub\n" + "\n".join(linuxcnc for _, linuxcnc in SHAPE) +
            "\nO100 endsub\n")


def main():
    both = collect(
        lambda folder: run_mbc(sys.argv[1], folder, FANUC, "G70")[:-1],
        lambda folder: run_rs274(folder, LINUXCNC)[1:], len(SHAPE))
    if isinstance(both, int):
        return both
    return compare(SHAPE, *both)


if __name__ == "__main__":
    sys.exit(main())
