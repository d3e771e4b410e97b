#!/usr/bin/env python3
"""Writes a large Macro B program for the compile-time benchmark.

  gen_large.py LINES OUT.nc

A main program calls every subprogram once (G65 with arguments); each
subprogram is about 40 lines of what real cycles hold: a WHILE loop with
arithmetic and trig on locals, moves, an IF GOTO around a block, a nested
WHILE, indirection into a common table and a conditional assignment. The
bodies vary with a fixed seed, so that the same LINES gives the same file
and no two subprograms are identical.
"""
import random
import sys

LINES_PER_SUBPROGRAM = 40
FIRST_PROGRAM = 2000


def subprogram(number, rng):
    k = rng.randint(2, 9)
    angle = rng.choice([15, 30, 45, 60, 72, 90, 120])
    feed = rng.choice([200, 400, 800, 1200])
    depth = rng.randint(1, 9) / 10
    table = rng.randint(100, 190)
    lines = [
        f"O{number} (GENERATED CYCLE {number})",
        f"#10 = #1 + {k}",
        f"#11 = #2 * {rng.randint(1, 5)}.5",
        "#12 = 0",
        f"#13 = {rng.randint(1, 4)}",
        f"G90 G00 X#10 Y#11 Z{rng.randint(2, 9)}.",
        f"G01 Z-{depth} F{feed // 2}",
        f"WHILE [#12 LT #13] DO1",
        f"  #14 = #10 + {k}. * COS[#12 * {angle}]",
        f"  #15 = #11 + {k}. * SIN[#12 * {angle}]",
        f"  #16 = SQRT[#14 * #14 + #15 * #15] / {k + 1}",
        f"  IF [#16 GT {rng.randint(50, 500)}] GOTO {10 + k}",
        f"  G01 X#14 Y#15 F{feed}",
        f"  #[{table} + [#12 MOD 8]] = #16",
        f"  N{10 + k} #12 = #12 + 1",
        "END1",
        "#17 = 0",
        f"WHILE [#17 LT {rng.randint(1, 3)}] DO1",
        "  #18 = 0",
        "  WHILE [#18 LT 2] DO2",
        f"    #19 = #[{table} + #18] * {rng.randint(1, 9)} + #17",
        f"    G01 X[#10 + #19 / {k + 3}] Y[#11 - #18] F{feed}",
        "    #18 = #18 + 1",
        "  END2",
        "  #17 = #17 + 1",
        "END1",
        f"IF [#10 GT {rng.randint(1, 100)}] THEN #20 = #10 - {k}",
        "IF [#20 EQ #0] THEN #20 = 0",
        f"#21 = FIX[#20 * {rng.randint(2, 7)}] MOD {rng.randint(3, 11)}",
        f"#22 = ABS[#21 - {k}] + ROUND[#11 / {angle}]",
        f"#23 = ATAN[#22]/[{k}.] + ASIN[{rng.randint(1, 9)} / 10]",
        f"#24 = #23 * {rng.randint(2, 5)} - #22",
        f"IF [#24 LT 0] GOTO {90 + k}",
        f"#[{table} + 9] = #24",
        f"N{90 + k} G00 Z{rng.randint(2, 9)}.",
        f"#25 = [#10 AND {rng.randint(1, 255)}] + [#21 OR 1]",
        f"#26 = #25 * #25 + {rng.randint(1, 99)}",
        f"#27 = [#26 + #24] / {k + 7}",
        f"#100 = #100 + #27",
        "M99",
    ]
    return lines


def program(total_lines):
    rng = random.Random(1006)
    count = max(1, total_lines // (LINES_PER_SUBPROGRAM + 1))
    main = ["%", "O1000 (GENERATED: A MAIN PROGRAM AND "
            f"{count} SUBPROGRAMS)", "#100 = 0"]
    body = []
    for i in range(count):
        number = FIRST_PROGRAM + i
        main.append(f"G65 P{number} A{rng.randint(1, 99)}. "
                    f"B{rng.randint(1, 99)}.")
        body.extend(subprogram(number, rng))
    main.append("M30")
    return main + body + ["%"]


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    lines = program(int(sys.argv[1]))
    with open(sys.argv[2], "w") as out:
        out.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
