#!/usr/bin/env python3
"""Differential testing of mbc's engines on random Macro B programs.

Generates valid programs (bounded loops, IF/GOTO with computed and
loop-leaving jumps, M99 P in the main program, G65/M98 nests with argument
specification I and II, G66 and G66.1 modal calls, calls by G, M and T
codes, indirection across variable ranges, vacant values, every function and
operator with edge arguments, DPRNT, BPRNT, motion with work and tool
offsets, planes, canned cycles, dwell, reference returns, skip moves,
G52/G92 shifts, scaling, rotation, mirror, polar coordinates, G10 offsets,
feed modes and units, #3006 messages, bounded backward GOTO loops, optional
block skip, system variables read and written; on a lathe profile, one in
five programs: diameter X with U/W, G50, G96/G97, T codes and G10 offsets,
single cycles, G74-G76, G71-G73 with shapes and G70 (on one lathe in
four in the one-block Series 10/11 format), nose radius
compensation), each with the run options
and machine profile it needs (--block-skip, --arg, --set, --machine), runs
each under every engine and optimisation level, and compares everything a
run writes with the interpreter's: exit status, stderr (alarms, the --trace
record), toolpath, DPRNT and variables. A program that differs is reduced
line by line to a small one that still differs the same way and written to
--out (with its machine profile beside it, and its run options printed).

    tools/difftest.py --mbc build/mbc [--engines build/tests/difftest_engines]
                      -n 1000 [--seed 1] [--jobs 2]

--engines runs all the engines of a program in one process (about twice as
fast; tests/difftest/engines_test.py checks it writes what mbc run does).

Exit status 0 when every program agreed, 1 when one differed.
"""
import argparse
import json
import multiprocessing
import random
import subprocess
import sys
import tempfile
from pathlib import Path

ENGINES = (("ir", []), ("jit", ["-O0"]), ("jit", ["-O1"]), ("jit", ["-O2"]))
OUTPUTS = ("status", "stderr", "toolpath.jsonl", "dprnt", "vars.json")
MAX_BLOCKS = "200000"

FUNCTIONS = ("SIN", "COS", "TAN", "ASIN", "ACOS", "ATAN", "SQRT", "ABS",
             "ROUND", "FIX", "FUP", "LN", "EXP", "BIN", "BCD", "ADP")
# Arguments at the edges of the functions' domains and of rounding.
EDGES = ("0", "1", "-1", "0.5", "-0.5", "1.5", "-2.5", "30", "90", "-90",
         "180", "270", "360", "720", "-360", "1.0001", "0.9999", "1000000",
         "0.000001", "2147483647", "-2147483648", "99999999", "45.", "0.")
# Most calls of a function with a domain get an argument inside it, so that
# most programs run to the end; the rest, and EDGES, reach the alarms.
SAFE_ARGUMENT = {"SQRT": "ABS[{}]", "LN": "ABS[{}] + 1", "ASIN": "SIN[{}]",
                 "ACOS": "COS[{}]", "TAN": "ABS[{}] MOD 80", "EXP": "SIN[{}]",
                 "BCD": "ABS[{}] MOD 99", "BIN": "BCD[ABS[{}] MOD 99]"}
RELATIONS = ("EQ", "NE", "GT", "GE", "LT", "LE")
ARGUMENT_LETTERS = "ABCDEFHIJKMQRSTUVWXYZ"
# Loop counters: never written but by their loop. #27-#29 in main and
# G65 macros (a level of their own), #30-#32 in M98 subprograms, which
# share their caller's level.
MACRO_COUNTERS = (27, 28, 29)
SUB_COUNTERS = (30, 31, 32)
BRACKET_LIMIT = 5  # PS0118: brackets nest at most 5 deep
# System variables a run changes: the last N, G codes, F, positions, the
# simulated clock, the G66 state, offsets, output signals, the parts count.
SYSTEM_READS = ("#4114", "#4001", "#4003", "#4109", "#4012", "#5001",
                "#5002", "#5003", "#5041", "#3001", "#5043", "#5023",
                "#5221", "#2001", "#1132", "#1101", "#3901", "#4002",
                "#4005", "#4006", "#4009", "#4010", "#4016", "#5021",
                "#5083", "#3002", "#5061")
# Calls by codes (machine profile parameter and its value, the code, the
# program called): a G code calling a macro, one whose call is modal
# (negative; G67 cancels it), an M code calling a macro, an M code calling
# a subprogram (no arguments). 6001 bit 5 makes T call O9000.
CODE_CALLS = (("6050", 100, "G100", 9010), ("6051", -101, "G101", 9011),
              ("6080", 200, "M200", 9020), ("6071", 300, "M300", 9001))
CYCLES = ("G73", "G74", "G76", "G81", "G82", "G83", "G84", "G85", "G86",
          "G87", "G88", "G89")
# A lathe's shape programs are numbered from here, apart from GOTO labels.
SHAPE_LABELS = 7000
# The counter of backward GOTO loops, which only the main program and G65
# macros have (an M98 subprogram would share its caller's).
BACK_COUNTER = 33


class Generator:
    """One random program: a main program, G65 macros that call later
    macros and M98 subprograms, and M98 subprograms that call nothing."""

    def __init__(self, seed):
        self.rng = random.Random(seed)
        self.macros = [2001 + i for i in range(self.rng.randint(0, 3))]
        self.subs = [3001 + i for i in range(self.rng.randint(0, 2))]
        # Programs the main program calls by a code, each a program that
        # calls nothing (a program called by a code calls by codes no more).
        self.code_calls = ([c for c in CODE_CALLS if self.chance(0.6)]
                           if self.chance(0.3) else [])
        self.t_call = self.chance(0.1)
        self.skip = self.chance(0.3)
        self.back_labels = 0
        # A stream of its own, so that the mill programs of a seed stay.
        self.lathe = random.Random(seed * 7919 + 1).random() < 0.2
        # A lathe in the Series 10/11 tape format (0001#1 FCV): one-block
        # multiple repetitive cycles.
        self.series_ten = (self.lathe and
                           random.Random(seed * 7919 + 2).random() < 0.25)
        self.shapes = 0

    def chance(self, p):
        return self.rng.random() < p

    def pick(self, items):
        return self.rng.choice(items)

    # Expressions. `depth` is the bracket nesting already used.

    def number(self):
        if self.chance(0.2):
            return self.pick(EDGES)
        value = self.pick((self.rng.randint(-20, 20),
                           round(self.rng.uniform(-100, 100), 3)))
        return f"{value}"

    def direct(self, last_local):
        """A variable by number: a local up to #last_local, a volatile
        common (#100-#110) or a kept one (#500-#505)."""
        roll = self.rng.random()
        if roll < 0.6:
            return f"#{self.rng.randint(1, last_local)}"
        if roll < 0.93:
            return f"#{self.rng.randint(100, 110)}"
        return f"#{self.rng.randint(500, 505)}"

    def variable(self, depth):
        roll = self.rng.random()
        if roll < 0.72:
            return self.direct(33)
        if roll < 0.75:
            return self.pick(SYSTEM_READS)
        if roll < 0.8:
            return "#0"
        if depth + 1 < BRACKET_LIMIT:
            return f"#[{self.index(depth + 1)}]"
        return f"#{self.rng.randint(1, 33)}"

    def index(self, depth):
        """A variable number that mostly stays in a range: locals, commons
        #100-#199 or #500-#999, sometimes crossing into what does not
        exist (PS0115)."""
        base = self.pick((1, 100, 100, 500, 100, 500, 30, 195, 990))
        if self.chance(0.95) and depth + 1 < BRACKET_LIMIT:
            return f"{base} + ABS[{self.operand(depth + 1)}] MOD 5"
        return f"{base} + {self.operand(depth).lstrip('-')}"

    def operand(self, depth):
        roll = self.rng.random()
        if roll < 0.35 or depth + 1 >= BRACKET_LIMIT:
            return self.pick((self.number(), self.variable(depth)))
        if roll < 0.55:
            return self.variable(depth)
        if roll < 0.8:
            name = self.pick(FUNCTIONS)
            if name == "ATAN" and depth + 2 < BRACKET_LIMIT:
                if self.chance(0.5):
                    return (f"ATAN[{self.expression(depth + 1, 1)}]"
                            f"/[{self.expression(depth + 1, 1)}]")
                return (f"ATAN[{self.expression(depth + 1, 1)},"
                        f"{self.expression(depth + 1, 1)}]")
            if name == "ADP":
                if self.chance(0.2):  # no macro argument: the identity
                    return f"ADP[{self.expression(depth + 1, 1)}]"
                return f"ADP[#{self.rng.randint(1, 26)}]"
            safe = SAFE_ARGUMENT.get(name)
            if self.chance(0.15 if safe is None else 0.04):
                return f"{name}[{self.pick(EDGES)}]"
            if safe and self.chance(0.95):
                inner = depth + 1 + safe.count("[")
                if inner < BRACKET_LIMIT:
                    return f"{name}[{safe.format(self.expression(inner, 1))}]"
                return f"{name}[1]"  # in every domain
            return f"{name}[{self.expression(depth + 1, 2)}]"
        if self.chance(0.15) and depth + 2 < BRACKET_LIMIT:
            exponent = self.pick(("0", "1", "2", "0.5", "3"))
            return f"POW[ABS[{self.operand(depth + 2)}] + 1,{exponent}]"
        return f"[{self.expression(depth + 1, 2)}]"

    def expression(self, depth, terms=3):
        text = self.operand(depth)
        if self.chance(0.1) and not text.startswith("-"):
            text = "-" + text
        for _ in range(self.rng.randint(0, terms)):
            op = self.pick(("+", "-", "*", "/", "+", "*", "MOD", "AND",
                            "OR", "XOR"))
            right = self.operand(depth)
            if op in ("/", "MOD") and self.chance(0.95):
                right = self.pick(("2", "3.", "0.5", "4", "7", "360"))
            if op in ("AND", "OR", "XOR"):
                right = str(self.rng.randint(0, 255))
            # `10+-#1` is no Macro B: a sign only starts an expression.
            text = f"{text} {op} {right.lstrip('-')}"
        return text

    def condition(self, depth=1):
        """The inside of IF [...] or WHILE [...] (which is bracket `depth`):
        one comparison, or two joined by AND or OR."""
        if self.chance(0.2) and depth + 2 < BRACKET_LIMIT:
            return (f"[{self.comparison(depth + 1)}] {self.pick(('AND', 'OR'))}"
                    f" [{self.comparison(depth + 1)}]")
        return self.comparison(depth)

    def comparison(self, depth):
        left = self.expression(depth, 1)
        if self.chance(0.1) and depth + 1 < BRACKET_LIMIT:
            left = f"[{self.variable(depth + 1)}]"
        right = self.pick((self.number(), self.variable(depth), "#0"))
        return f"{left} {self.pick(RELATIONS)} {right}"

    # Statements.

    def target(self):
        """A variable a statement may write: never a loop counter."""
        if self.chance(0.9):
            return self.direct(26)
        return f"#[{self.pick((100, 500))} + ABS[{self.expression(2, 1)}] MOD 6]"

    def assignment(self):
        if self.chance(0.08):
            return f"{self.target()} = #0"
        if self.chance(0.08):
            return f"{self.target()} = {self.variable(1)}"
        return f"{self.target()} = {self.expression(0)}"

    def lathe_motion(self):
        """A lathe's move: X a diameter, U/W incremental, arcs in G18."""
        code = self.pick(("G00", "G01", "G01", "G02", "G03"))
        words = [self.word(axis) for axis in
                 self.rng.sample(self.pick(("XZ", "UW", "XW", "UZ")),
                                 self.rng.randint(1, 2))]
        if code in ("G02", "G03"):
            words.append(f"R[{self.expression(1, 1)}]" if self.chance(0.7)
                         else f"I{self.number()} K{self.number()}")
        if code != "G00" and self.chance(0.4):
            words.append(f"F{self.rng.randint(50, 3000)}")
        prefix = f"N{self.rng.randint(1000, 1999)} " if self.chance(0.2) else ""
        return f"{self.skip_mark()}{prefix}{code} {' '.join(words)}"

    def lathe_feature(self):
        """A lathe's NC function: its cycles, G50, CSS, T codes and G10."""
        roll = self.rng.random()
        x, z = self.length(20, 60), self.length(-30, -5)
        if roll < 0.15:
            cycle = self.pick(("G90", "G92", "G94"))
            letter = ("R" if not self.series_ten else
                      "K" if cycle == "G94" else "I")
            taper = (f" {letter}{self.length(-2, 2)}" if self.chance(0.3)
                     else "")
            lines = [f"G00 X70. Z5. S{self.rng.randint(200, 2000)}",
                     f"{cycle} X{x} Z{z}{taper} F{self.length(0.1, 2)}"]
            lines += [self.word("X") for _ in range(self.rng.randint(0, 2))]
            return self.maybe_compensated(lines + ["G00 X80."])
        if roll < 0.2:
            return self.lathe_drilling(x, z)
        if roll < 0.25:
            cycle = self.pick(("G74", "G75"))
            start = f"G00 X{x} Z2. S{self.rng.randint(200, 2000)}"
            end = f"{cycle} X{self.length(10, 60)} Z{z}"
            along_x, along_z = (self.rng.randint(500, 4000) for _ in "XZ")
            feed = f"F{self.length(0.05, 0.3)}"
            if self.series_ten:
                return [start, f"{end} I{along_x} K{along_z} "
                               f"D{self.rng.randint(0, 500)} {feed}"]
            return [start, f"{cycle} R{self.length(0, 1)}",
                    f"{end} P{along_x} Q{along_z} {feed}"]
        if roll < 0.35:
            height = self.rng.randint(300, 2000)
            start = f"G00 X{x} Z5. S{self.rng.randint(200, 1500)}"
            end = (f"G76 X[#{self.rng.randint(1, 26)} MOD 5 + "
                   f"{float(x) - 5:.3f}] Z{z}")
            first = self.rng.randint(100, height)
            lead = f"F{self.length(1, 3)}"
            if self.series_ten:
                return [start, f"{end} K{height} D{first} {lead} "
                               f"A{self.pick(('60', '55', '0'))}"]
            return [start,
                    f"G76 P{self.pick(('01', '02'))}{self.pick(('00', '10'))}"
                    f"{self.pick(('60', '55', '00'))} "
                    f"Q{self.rng.randint(10, 200)} R{self.length(0, 0.05)}",
                    f"{end} P{height} Q{first} {lead}"]
        if roll < 0.5:
            return self.lathe_shape()
        if roll < 0.6:
            return [self.pick((f"G50 {self.word('X')} {self.word('Z')}",
                               f"G50 S{self.rng.randint(500, 4000)}",
                               f"G96 S{self.rng.randint(50, 300)}", "G97",
                               "G99", "G98",
                               f"G04 {self.word('U')}"))]
        if roll < 0.7:
            offset = self.rng.randint(1, 3)
            return [f"G10 P{self.pick((offset, 10000 + offset))} "
                    f"{self.word('X')} {self.word('Z')}",
                    f"T{self.rng.randint(1, 4):02d}{offset:02d}"]
        if roll < 0.75:
            # Work offsets, written as on a mill (W adds in system A).
            return [f"G10 L2 P{self.rng.randint(0, 2)} "
                    f"{self.pick(('Z', 'W'))}{self.length(-5, 5)}",
                    self.pick(("G54", "G55")), f"G00 {self.word('Z')}"]
        if roll < 0.8:
            return [f"#{self.pick((2001, 2101, 2701, 2801, 10002, 15002))} = "
                    f"{self.expression(0, 1)}",
                    f"T01{self.rng.randint(0, 3):02d}"]
        if roll < 0.9:
            return self.nose_radius_contour()
        if roll < 0.93:
            return self.corner_steps()
        if roll < 0.95:
            return ["G00 X30. Z2.", f"G01 F{self.length(0.05, 0.3)}"] + \
                self.comma_corners("Z", "X", (10, 80))
        return [self.pick(("G28 U0 W0", f"G28 {self.word('U')}"))]

    def line_or_arc(self, to, radii):
        """A G01 to `to`, or (less often) a G02/G03 with R from `radii`."""
        if self.chance(0.55 / 0.8):
            return f"G01 {to}"
        return f"{self.pick(('G02', 'G03'))} {to} R{self.length(*radii)}"

    def comma_corners(self, first, second, across=(-40, 40)):
        """Lines and arcs in the plane of `first` and `second` (absolute)
        with ,C and ,R at any angle and ,A lines, the amounts sometimes
        too large for the moves: a computed amount now and then."""
        lines = []
        for _ in range(self.rng.randint(2, 4)):
            amount = (self.length(0.2, 4) if self.chance(0.8)
                      else f"[{self.expression(1, 1)}]")
            comma = self.pick(("", f" ,C{amount}", f" ,R{amount}"))
            to = (f"{first}{self.length(-40, 40)} "
                  f"{second}{self.length(*across)}")
            if self.chance(0.8):
                lines.append(self.line_or_arc(to, (25, 60)) + comma)
            elif self.chance(0.5):
                lines.append(f"G01 {self.pick((first, second))}"
                             f"{self.length(-40, 40)} "
                             f",A{self.length(0, 360)}{comma}")
            else:
                lines.append(f"G01 ,A{self.length(0, 360)}{comma}")
                lines.append(f"G01 {to} ,A{self.length(0, 360)}")
        return lines + [f"G01 {first}{self.length(-40, 40)}"]

    def lathe_drilling(self, x, z):
        """A face cycle along Z on the centre or a side cycle along X, a
        peck Q now and then, another hole after it, then G80."""
        face = self.chance(0.6)
        cycle = self.pick(("G83", "G84", "G85") if face else
                          ("G87", "G88", "G89"))
        peck = (f" Q{self.rng.randint(500, 8000)}"
                if cycle in ("G83", "G87") and self.chance(0.6) else "")
        dwell = f" P{self.rng.randint(0, 900)}" if self.chance(0.3) else ""
        bottom = f"Z{z}" if face else f"X{self.length(5, 19)}"
        return [f"G00 X{'0' if face else '40.'} Z{'5.' if face else z}",
                f"{cycle} {bottom} R-{self.length(0.5, 3)}{peck}{dwell} "
                f"F{self.length(0.05, 0.3)}",
                self.pick((f"W{self.length(-5, -1)}" if face else
                           f"U{self.length(-8, -1)}",
                           f"{'U' if face else 'W'}{self.length(-3, 3)}")),
                "G80"]

    def corner_steps(self):
        """Steps along Z and X with chamfers (I, K) and corner R between
        them, their amounts drawn with either sign."""
        lines = ["G00 X20. Z2.", f"G01 Z0 F{self.length(0.05, 0.3)}"]
        for _ in range(self.rng.randint(1, 3)):
            lines.append(f"{self.pick(('X', 'U'))}{self.length(2, 40)} "
                         f"{self.pick(('K', 'R'))}{self.length(-1.5, 1.5)}")
            lines.append(f"{self.pick(('Z', 'W'))}{self.length(-30, -1)} "
                         f"{self.pick(('I', 'R'))}{self.length(-1.5, 1.5)}")
        return lines + ["G00 X80."]

    def nose_radius_contour(self):
        """A contour under tool nose radius compensation: the nose radius
        and tip of offset 4, then G41/G42 moves and the G40 move."""
        lines = [f"G10 P10004 R{self.length(0, 1.2)} Q{self.rng.randint(0, 9)}",
                 "T0104", "G00 X70. Z5.",
                 f"{self.pick(('G41', 'G42'))} G01 {self.word('X')} "
                 f"{self.word('Z')} F{self.length(0.05, 0.3)}"]
        for _ in range(self.rng.randint(1, 4)):
            if self.chance(0.7):
                lines.append(f"G01 {self.word('X')} {self.word('Z')}")
            else:
                lines.append(f"{self.pick(('G02', 'G03'))} {self.word('X')} "
                             f"{self.word('Z')} R{self.length(5, 30)}")
        lines.append(f"G40 G00 {self.word('X')}")
        return lines

    def lathe_shape(self):
        """G71, G72 or G73 with a shape program right after it, sometimes
        G70 along it."""
        self.shapes += 1
        first = SHAPE_LABELS + 10 * self.shapes
        last = first + 5
        cycle = self.pick(("G71", "G72", "G73"))
        settings = {"G71": f"U{self.length(0.5, 3)} R{self.length(0, 1)}",
                    "G72": f"W{self.length(0.5, 3)} R{self.length(0, 1)}",
                    "G73": f"U{self.length(0, 4)} W{self.length(0, 2)} "
                           f"R{self.rng.randint(1, 4)}"}[cycle]
        small = round(self.rng.uniform(10, 30), 3)
        step = round(self.rng.uniform(2, 15), 3)
        shape = (f"{cycle} P{first} Q{last} U{self.length(0, 0.5)} "
                 f"W{self.length(0, 0.2)} F{self.length(0.1, 0.4)}")
        if self.series_ten:
            one_block = {"G71": f"D{self.rng.randint(500, 3000)}",
                         "G72": f"D{self.rng.randint(500, 3000)}",
                         "G73": f"I{self.length(0, 4)} K{self.length(0, 2)} "
                                f"D{self.rng.randint(1, 4)}"}[cycle]
            lines = ["G00 X80. Z5. S1000", f"{shape} {one_block}"]
        else:
            lines = ["G00 X80. Z5. S1000", f"{cycle} {settings}", shape]
        if cycle == "G72":
            lines += [f"N{first} G00 Z{-step:.3f}",
                      f"G01 X{small + 30:.3f} F{self.length(0.05, 0.2)}",
                      f"N{last} X{small:.3f} Z0."]
        else:
            lines += [f"N{first} G00 X{small:.3f}",
                      f"G01 Z{-step:.3f} F{self.length(0.05, 0.2)}",
                      f"X{small + step:.3f} Z{-2 * step:.3f}",
                      f"N{last} Z{-3 * step:.3f}"]
        if self.chance(0.5):
            lines.append(f"G70 P{first} Q{last}")
        return self.maybe_compensated(lines)

    def maybe_compensated(self, lines):
        """Now and then the lines under tool nose radius compensation with
        the nose radius and tip of offset 4, which the cycles compensate."""
        if not self.chance(0.3):
            return lines
        return ([f"G10 P10004 R{self.length(0, 1.2)} "
                 f"Q{self.rng.randint(0, 9)}", "T0104",
                 self.pick(("G41", "G42"))] + lines + ["G40 G00 X90."])

    def motion(self):
        if self.lathe:
            return self.lathe_motion()
        code = self.pick(("G00", "G01", "G01", "G02", "G03"))
        words = []
        for axis in self.rng.sample("XYZ", self.rng.randint(1, 3)):
            if self.chance(0.2):
                words.append(f"{axis}#{self.rng.randint(1, 26)}")
            elif self.chance(0.3):
                words.append(f"{axis}{self.number()}")
            else:
                words.append(f"{axis}[{self.expression(1, 1)}]")
        if code in ("G02", "G03"):
            words.append(f"R[{self.expression(1, 1)}]" if self.chance(0.7)
                         else f"I{self.number()} J{self.number()}")
        if code != "G00" and self.chance(0.4):
            words.append(f"F{self.rng.randint(50, 3000)}")
        prefix = self.pick(("", "", "G90 ", "G91 "))
        if self.chance(0.15):
            prefix += self.pick(("G54 ", "G55 ", "G49 "))
        if code in ("G00", "G01") and self.chance(0.1):
            prefix += f"G43 H{self.rng.randint(1, 3)} "
        if self.chance(0.2):  # no GOTO target: #4114 reads it
            prefix = f"N{self.rng.randint(1000, 1999)} {prefix}"
        return f"{self.skip_mark()}{prefix}{code} {' '.join(words)}"

    def word(self, letter):
        """An NC word: a literal (one without a point is in least
        increments) or a computed value."""
        if self.chance(0.5):
            return f"{letter}{self.number()}"
        return f"{letter}[{self.expression(1, 1)}]"

    def length(self, low, high):
        return f"{round(self.rng.uniform(low, high), 3)}"

    def nc_feature(self):
        """The lines of an NC function beyond plain moves: a plane with an
        arc in it, a canned cycle, dwell, a reference return, a shift of
        the coordinate system, a transform or its cancel, G10, a feed
        mode, a skip move, a message, the unit."""
        if self.lathe:
            return self.lathe_feature()
        roll = self.rng.random()
        if roll < 0.12:
            plane = self.pick(("G17", "G18", "G19"))
            if self.chance(0.4):
                return [plane]
            first, second = {"G17": "XY", "G18": "ZX", "G19": "YZ"}[plane]
            centre = {"G17": "IJ", "G18": "KI", "G19": "JK"}[plane]
            arc = self.pick(("G02", "G03"))
            size = (f"R[{self.expression(1, 1)}]" if self.chance(0.5) else
                    f"{self.word(centre[0])} {self.word(centre[1])}")
            return [f"{plane} {arc} {self.word(first)} {self.word(second)} "
                    f"{size}"]
        if roll < 0.3:
            return self.canned_cycle()
        if roll < 0.35:
            return [self.pick((f"G04 P{self.rng.randint(0, 2000)}",
                               f"G04 {self.word('X')}"))]
        if roll < 0.43:
            return [self.pick(("G91 G28 Z0",
                               f"G28 {self.word('X')} {self.word('Y')}",
                               f"G30 P{self.rng.randint(2, 4)} "
                               f"Z{self.number()}",
                               f"G29 {self.word('X')}",
                               f"G53 {self.word('Z')}"))]
        if roll < 0.5:
            return [self.pick((f"G52 {self.word('X')} {self.word('Y')}",
                               "G52 X0 Y0"))]
        if roll < 0.55:
            return [self.pick((f"G92 {self.word('X')} {self.word('Z')}",
                               "G92.1 X0 Y0 Z0"))]
        if roll < 0.63:
            return [self.pick((f"G51 {self.word('X')} Y0 "
                               f"P{self.length(0.5, 2)}",
                               f"G51 P{self.rng.randint(50000, 200000)}",
                               "G50"))]
        if roll < 0.69:
            return [self.pick((f"G68 {self.word('X')} Y0 {self.word('R')}",
                               f"G68 R{self.length(-90, 90)}", "G69"))]
        if roll < 0.71:
            return self.polar()
        if roll < 0.73:
            return self.compensated_contour()
        if roll < 0.76:
            return ["G17 G01 F300."] + self.comma_corners("X", "Y")
        if roll < 0.79:
            return [self.pick((f"G51.1 {self.word('X')}",
                               f"G51.1 Y{self.length(-5, 5)}", "G50.1 X0",
                               "G50.1"))]
        if roll < 0.88:
            return [self.pick((
                f"G10 L2 P{self.rng.randint(0, 6)} {self.word('X')}",
                f"G10 L20 P{self.rng.randint(1, 3)} {self.word('Z')}",
                f"G10 L{self.rng.randint(10, 13)} P{self.rng.randint(1, 3)} "
                f"{self.word('R')}"))]
        if roll < 0.95:
            return [self.pick((f"G93 G01 {self.word('X')} "
                               f"F{self.length(1, 50)}",
                               "G94", f"G95 S{self.rng.randint(100, 3000)}",
                               f"S{self.rng.randint(0, 3000)} M03", "M05"))]
        if roll < 0.97:  # no probe scene: the move completes
            return [f"G31 {self.word('X')} {self.word('Y')} "
                    f"F{self.rng.randint(50, 500)}"]
        if roll < 0.98:
            return [f"#3006 = {self.rng.randint(1, 9)} (CHECK)"]
        return [self.pick(("G20", "G21"))]

    def polar(self):
        """Moves in polar coordinates (G16): radius and angle words of a
        plane, either left out, absolute or incremental, then G15."""
        plane = self.pick(("G17", "G18", "G19"))
        radius, angle = {"G17": "XY", "G18": "ZX", "G19": "YZ"}[plane]
        lines = [f"{plane} G16"]
        for _ in range(self.rng.randint(1, 3)):
            words = [self.word(letter) for letter in (radius, angle)
                     if self.chance(0.8)]
            mode = self.pick(("", "G90 ", "G91 "))
            lines.append(f"{mode}{self.pick(('G00', 'G01'))} {' '.join(words)}")
        lines.append("G15")
        return lines

    def compensated_contour(self):
        """A contour under cutter compensation (G41/G42 D): lines and arcs,
        sometimes a Z move or a D change in it, then the G40 move."""
        number = self.rng.randint(1, 3)
        lines = [f"G17 G10 L12 P{number} R{self.length(-3, 6)}",
                 f"{self.pick(('G41', 'G42'))} D{number} G01 "
                 f"{self.word('X')} {self.word('Y')} "
                 f"F{self.rng.randint(100, 900)}"]
        for _ in range(self.rng.randint(1, 5)):
            roll = self.rng.random()
            if roll < 0.8:
                lines.append(self.line_or_arc(
                    f"{self.word('X')} {self.word('Y')}", (8, 40)))
            elif roll < 0.9:
                lines.append(f"Z{self.length(-5, 0)}")
            else:
                lines.append(self.pick(("M08", f"D{self.rng.randint(0, 3)}",
                                        "G42" if self.chance(0.5) else "G41")))
        lines.append(f"G40 G01 {self.word('X')} {self.word('Y')}")
        return lines

    def canned_cycle(self):
        """A canned cycle block, the holes after it, mostly its G80."""
        code = self.pick(CYCLES)
        words = [self.pick(("", "G98 ", "G99 ")) + code, self.word("X"),
                 self.word("Y"), f"Z-{self.length(0.5, 10)}"]
        if self.chance(0.8):
            words.append(f"R{self.length(0, 5)}")
        if code in ("G73", "G83", "G76", "G87") and self.chance(0.9):
            words.append(f"Q{self.length(0.5, 4)}")
        if code in ("G82", "G88", "G89"):
            words.append(f"P{self.rng.randint(0, 1000)}")
        if self.chance(0.2):
            words.append(f"K{self.rng.randint(0, 3)}")
        words.append(f"F{self.rng.randint(50, 500)}")
        lines = [" ".join(words)]
        for _ in range(self.rng.randint(0, 2)):
            lines.append(f"{self.word('X')} {self.word('Y')}")
        if self.chance(0.6):
            lines.append("G80")
        return lines

    def skip_mark(self):
        """Optional block skip, / or /2, on some NC blocks."""
        if self.chance(0.1):
            return self.pick(("/ ", "/2 "))
        return ""

    def system_write(self):
        """A write to offsets or output signals that later blocks read."""
        roll = self.rng.random()
        if roll < 0.4:
            number = self.pick((5221, 5222, 5223, 5241, 5242, 5201))
            return f"#{number} = {self.expression(0, 1)}"
        if roll < 0.7:
            return f"#{self.rng.randint(2001, 2003)} = {self.expression(0, 1)}"
        if roll < 0.8:
            return f"#1132 = {self.rng.randint(-1000, 1000)}"
        if roll < 0.9:
            return f"#3901 = {self.rng.randint(0, 100)}"
        return f"#{self.rng.randint(1100, 1115)} = {self.rng.randint(0, 1)}"

    def code_call(self):
        """A block that calls by a code of the machine profile."""
        if self.t_call and (not self.code_calls or self.chance(0.2)):
            return f"{self.skip_mark()}T{self.rng.randint(1, 99)}"
        _, _, code, _ = self.pick(self.code_calls)
        arguments = "" if code == "M300" else self.arguments()
        return f"{self.skip_mark()}{code} {arguments}".rstrip()

    def dprnt(self):
        if self.chance(0.15):
            return self.pick(("POPEN", "PCLOS"))
        items = []
        if self.chance(0.2):  # BPRNT: each value a 32-bit integer
            for _ in range(self.rng.randint(1, 3)):
                items.append(f"{self.pick('AXYZ')}#{self.rng.randint(1, 33)}"
                             f"[{self.rng.randint(0, 5)}]")
            return f"BPRNT[{'*'.join(items)}]"
        for _ in range(self.rng.randint(1, 3)):
            text = self.pick(("A", "VAL", "X", "R*", "N1*"))
            items.append(f"{text}#{self.rng.randint(1, 33)}"
                         f"[{self.format_digits()}]")
        return f"DPRNT[{'*'.join(items)}]"

    def format_digits(self):
        """The [cd] of a DPRNT item: mostly small, sometimes up to 8 and
        8 (digits dropped, decimals past the value's)."""
        if self.chance(0.2):
            return f"{self.rng.randint(0, 8)}{self.rng.randint(0, 8)}"
        return f"{self.rng.randint(1, 5)}{self.rng.randint(0, 3)}"

    def arguments(self):
        """Argument specification I (letters) or, sometimes, II (A, B, C
        and sets of I, J, K: #4-#33)."""
        if self.chance(0.15):
            words = [f"{letter}{self.number()}" for letter in "ABC"
                     if self.chance(0.3)]
            for _ in range(self.rng.randint(1, 6)):
                words += [f"{letter}[{self.expression(1, 1)}]" for letter in
                          [c for c in "IJK" if self.chance(0.6)] or ["I"]]
            return " ".join(words)
        return " ".join(
            f"{letter}[{self.expression(1, 1)}]" if self.chance(0.6)
            else f"{letter}{self.number()}"
            for letter in self.rng.sample(ARGUMENT_LETTERS,
                                          self.rng.randint(0, 4)))

    def call(self, program, level):
        """G65 to a later macro or M98 to a subprogram, if any."""
        later = [m for m in self.macros if m > program]
        if level == "sub" or (not later and not self.subs):
            return None
        if later and (not self.subs or self.chance(0.6)):
            repeat = f" L{self.rng.randint(2, 3)}" if self.chance(0.2) else ""
            return f"G65 P{self.pick(later)}{repeat} {self.arguments()}".rstrip()
        repeat = f" L{self.rng.randint(1, 3)}" if self.chance(0.4) else ""
        return f"M98 P{self.pick(self.subs)}{repeat}"

    def body(self, program, level, loops, labels, budget, back=True):
        """Statements of one nesting level; `loops` open WHILE counters;
        `labels` the N numbers placed at the top level of the program;
        `back`: a backward GOTO loop may start here."""
        lines = []
        counters = SUB_COUNTERS if level == "sub" else MACRO_COUNTERS
        while budget > 0:
            budget -= 1
            roll = self.rng.random()
            if (level == "main" and (self.code_calls or self.t_call)
                    and self.chance(0.15)):
                lines.append(self.code_call())
            elif roll < 0.3:
                lines.append(self.assignment())
            elif roll < 0.38:
                lines.append(self.motion())
            elif roll < 0.42:
                lines += self.nc_feature()
            elif roll < 0.5:
                lines.append(self.dprnt())
            elif roll < 0.58 and len(loops) < 3:
                depth = len(loops) + 1
                counter = counters[len(loops)]
                trips = self.rng.randint(0, 4)
                lines.append(f"#{counter} = 0")
                lines.append(f"WHILE [#{counter} LT {trips}] DO{depth}")
                lines += self.body(program, level, loops + [counter], labels,
                                   self.rng.randint(1, 5))
                lines.append(f"#{counter} = #{counter} + 1")
                lines.append(f"END{depth}")
            elif roll < 0.66 and labels:
                # Forward to a top-level label: out of any loop it is in.
                label = self.pick(labels)
                lines.append(f"IF [{self.condition()}] GOTO {label}")
            elif roll < 0.7 and labels:
                label = self.pick(labels)
                variable = self.rng.randint(1, 26)
                lines.append(f"#{variable} = {label}")
                lines.append(f"IF [{self.condition()}] GOTO #{variable}")
            elif roll < 0.76:
                lines.append(f"IF [{self.condition()}] THEN "
                             f"{self.assignment()}")
            elif roll < 0.84:
                call = self.call(program, level)
                if call:
                    lines.append(call)
            elif roll < 0.86:
                lines.append(f"IF [{self.condition()}] THEN #3000 = "
                             f"{self.rng.randint(1, 9)} (STOPPED)")
            elif roll < 0.88 and labels:
                label = self.pick(labels)
                lines.append(f"GOTO [{label - 1} + 1]")
            elif roll < 0.89 and labels and level == "main":
                # In the main program M99 P jumps like GOTO.
                lines.append(f"M99 P{self.pick(labels)}")
            elif roll < 0.93:
                lines.append(self.system_write())
            elif roll < 0.95 and self.skip:
                # A macro statement under a numbered switch: /1 or /2.
                lines.append(f"/{self.rng.randint(1, 2)} {self.assignment()}")
            elif (roll < 0.97 and back and not loops
                  and level in ("main", "macro")):
                lines += self.backward_loop(program, level, labels)
            else:
                lines.append(self.assignment())
        return lines

    def backward_loop(self, program, level, labels):
        """A loop made by a GOTO back to a label, bounded by its counter;
        its forward GOTOs leave it."""
        self.back_labels += 1
        label = 5000 + self.back_labels
        trips = self.rng.randint(1, 3)
        return ([f"#{BACK_COUNTER} = 0", f"N{label} {self.assignment()}"]
                + self.body(program, level, [], labels,
                            self.rng.randint(1, 4), back=False)
                + [f"#{BACK_COUNTER} = #{BACK_COUNTER} + 1",
                   f"IF [#{BACK_COUNTER} LT {trips}] GOTO {label}"])

    def program(self, number, level):
        """A program whose top level is cut into labelled sections, so that
        every GOTO jumps forward to a section start."""
        sections = self.rng.randint(1, 4)
        labels = [10 * (i + 1) + 1 for i in range(sections)]
        lines = [f"O{number}"]
        if level == "main" and self.lathe:
            lines.append("G18 G21 G97 G98 G00 X100. Z50. F1000 S1000 M03")
        elif level == "main":
            lines.append("G90 G17 G21 G00 X0 Y0 Z0 F1000")
        for i, label in enumerate(labels):
            later = labels[i + 1:]
            # A section of the main program under a G66 or G66.1 modal
            # call, or a modal call by a G code; a GOTO past its G67
            # leaves it in force under the next one's.
            modal = level == "main" and self.modal_call()
            if modal:
                lines.append(modal)
            lines += self.body(number, level, [], later,
                               self.rng.randint(2, 8))
            if modal:
                lines.append("G67")
            lines.append(f"N{label} #{self.rng.randint(1, 26)} = {label}")
        lines.append("M30" if level == "main" else "M99")
        return lines

    def modal_call(self):
        """The block that starts a modal call, or None."""
        modal_code = [code for _, value, code, _ in self.code_calls
                      if value < 0]
        if not self.chance(0.25) or not (self.macros or modal_code):
            return None
        if modal_code and (not self.macros or self.chance(0.3)):
            return f"{modal_code[0]} {self.arguments()}".rstrip()
        kind = "G66.1" if self.chance(0.25) else "G66"
        return f"{kind} P{self.pick(self.macros)} {self.arguments()}".rstrip()

    def text(self):
        lines = ["%"] + self.program(1000, "main")
        for macro in self.macros:
            lines += self.program(macro, "macro")
        for sub in self.subs:
            lines += self.program(sub, "sub")
        called = [program for _, _, _, program in self.code_calls]
        for program in called + ([9000] if self.t_call else []):
            lines += self.program(program, "sub")
        return "\n".join(lines + ["%", ""])

    def profile(self):
        """The machine profile (JSON text) the calls by codes need, or
        None."""
        parameters = {name: value for name, value, _, _ in self.code_calls}
        if self.t_call:
            parameters["6001"] = 32
        if self.series_ten:
            parameters["1"] = 2
        if self.lathe:
            return json.dumps({"series": "T", "parameters": parameters})
        if not parameters:
            return None
        return json.dumps({"parameters": parameters})

    def options(self):
        """Run options: block skip switches, arguments of the main
        program, preset variables."""
        options = []
        if self.skip:
            options.append(self.pick(("--block-skip", "--block-skip=2")))
        if self.chance(0.2):
            for letter in self.rng.sample(ARGUMENT_LETTERS,
                                          self.rng.randint(1, 3)):
                options += ["--arg", f"{letter}={self.number()}"]
        if self.chance(0.2):
            number = self.pick((100, 105, 500, 503))
            options += ["--set", f"#{number}={self.number()}"]
        return options


def generate(seed):
    """The program of a seed, its run options and its machine profile
    (JSON text or None)."""
    generator = Generator(seed)
    text = generator.text()
    return text, generator.options(), generator.profile()


def run(mbc, source, engine, options, work, extra=()):
    """Everything one run writes, as a dict of output name to text (the
    files' bytes); `extra`: the case's run options."""
    work.mkdir(parents=True, exist_ok=True)
    for name in OUTPUTS:
        (work / name).unlink(missing_ok=True)
    try:
        result = subprocess.run(
            [mbc, "run", str(source), "--engine", engine, *options,
             "--trace", "--max-blocks", MAX_BLOCKS,
             "--toolpath", str(work / "toolpath.jsonl"),
             "--dprnt", str(work / "dprnt"),
             "--vars-out", str(work / "vars.json"), *extra],
            capture_output=True, text=True, timeout=60)
        status, stderr = str(result.returncode), result.stderr
    except subprocess.TimeoutExpired:
        status, stderr = "timeout", ""
    outputs = {"status": status, "stderr": stderr}
    for name in OUTPUTS[2:]:
        path = work / name
        outputs[name] = path.read_bytes() if path.exists() else None
    return outputs


def run_all(engines, source, work, extra=()):
    """What every run wrote, interp first then ENGINES, from one process of
    difftest_engines (tests/difftest/engines_main.cpp); None when that
    process itself failed (a crash in one engine ends them all)."""
    try:
        result = subprocess.run(
            [engines, str(source), MAX_BLOCKS, str(work), *extra],
            capture_output=True, timeout=300)
    except subprocess.TimeoutExpired:
        return None
    if result.returncode != 0:
        return None
    runs = []
    for k in range(1 + len(ENGINES)):
        folder = work / str(k)
        outputs = {"status": (folder / "status").read_text(),
                   "stderr": (folder / "stderr").read_text()}
        for name in OUTPUTS[2:]:
            path = folder / name
            outputs[name] = path.read_bytes() if path.exists() else None
        runs.append(outputs)
    return runs


def first_difference(reference, runs):
    """(engine, output) of the first run of ENGINES that differs from the
    interpreter's, or None."""
    for (engine, options), outputs in zip(ENGINES, runs):
        for name in OUTPUTS:
            if outputs[name] != reference[name]:
                return f"{engine} {' '.join(options)}".strip(), name
    return None


def case_options(options, profile, work):
    """The run options of a case, its machine profile written to `work`."""
    if profile is None:
        return list(options)
    path = work / "machine.json"
    path.write_text(profile)
    return [*options, "--machine", str(path)]


def compare(mbc, text, work, engines=None, options=(), profile=None):
    """The interpreter's exit status, and (engine, output) of the first
    engine that differs from the interpreter or None. With `engines`, one
    process runs them all; when it fails, each runs in an mbc of its own,
    which tells which one."""
    source = work / "case.nc"
    source.write_text(text)
    extra = case_options(options, profile, work)
    runs = run_all(engines, source, work / "all", extra) if engines else None
    if runs is None:
        runs = [run(mbc, source, "interp", [], work / "interp", extra)]
        runs += [run(mbc, source, engine, flags, work / engine, extra)
                 for engine, flags in ENGINES]
    return runs[0]["status"], first_difference(runs[0], runs[1:])


def reduce(text, still_differs):
    """Removes runs of lines, halving their length down to single lines,
    while `still_differs` holds for what is left; the first and last line
    (the % marks) stay."""
    lines = text.splitlines()
    chunk = max(1, len(lines) // 2)
    while chunk >= 1:
        start, removed = 1, False
        while start < len(lines) - 1:
            trial = lines[:start] + lines[min(start + chunk, len(lines) - 1):]
            if still_differs("\n".join(trial) + "\n"):
                lines, removed = trial, True
            else:
                start += chunk
        if not removed:
            chunk //= 2
    return "\n".join(lines) + "\n"


def check(job):
    mbc, engines, seed = job
    text, options, profile = generate(seed)
    with tempfile.TemporaryDirectory() as work:
        status, found = compare(mbc, text, Path(work), engines, options,
                                profile)
    return seed, status, found


def keep_case(out, seed, text, profile):
    """Writes a case to `out`: its program and its machine profile."""
    path = Path(out) / f"difftest-{seed}.nc"
    path.write_text(text)
    if profile is not None:
        path.with_suffix(".json").write_text(profile)
    return path


def add_run_options(parser, items):
    """The options of a run over random seeds (this one and
    tools/oracles.py): mbc, how many `items` from which seed, the jobs at
    once, and where reduced cases go."""
    parser.add_argument("--mbc", default="build/mbc")
    parser.add_argument("-n", type=int, default=100, help=items)
    parser.add_argument("--seed", type=int, default=1, help="first seed")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--out", default=".", help="where reduced cases go")


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    add_run_options(parser, "programs")
    parser.add_argument("--show", type=int, help="print the program of a seed")
    parser.add_argument("--engines", help="build/tests/difftest_engines: all "
                        "engines of a program in one process (faster)")
    args = parser.parse_args()
    if args.show is not None:
        text, options, profile = generate(args.show)
        print(text, end="")
        print(f"run options: {' '.join(options) or '(none)'}; machine "
              f"profile: {profile or '(none)'}", file=sys.stderr)
        return 0
    mbc = str(Path(args.mbc).resolve())
    engines = str(Path(args.engines).resolve()) if args.engines else None
    jobs = [(mbc, engines, seed)
            for seed in range(args.seed, args.seed + args.n)]
    ends = {}
    with multiprocessing.Pool(args.jobs) as pool:
        for done, (seed, status, found) in enumerate(
                pool.imap(check, jobs), 1):
            ends[status] = ends.get(status, 0) + 1
            if status not in ("0", "3") or found:
                pool.terminate()
                text, options, profile = generate(seed)
                shown = f"run options: {' '.join(options) or '(none)'}"
            if status not in ("0", "3"):
                # Not a valid program (a generator bug), an internal error,
                # a crash or a hang: each worth a look.
                path = keep_case(args.out, seed, text, profile)
                print(f"difftest: seed {seed}: the interpreter's run ended "
                      f"with status {status} ({path}; {shown})",
                      file=sys.stderr)
                return 1
            if found:
                print(f"difftest: seed {seed}: --engine {found[0]} differs "
                      f"from interp in {found[1]}; reducing", file=sys.stderr)
                with tempfile.TemporaryDirectory() as work:
                    small = reduce(text, lambda t: compare(
                        mbc, t, Path(work), None, options, profile)[1] == found)
                path = keep_case(args.out, seed, small, profile)
                print(f"difftest: reduced case in {path} ({shown}):\n{small}",
                      file=sys.stderr)
                return 1
            if done % 100 == 0:
                # In seed order, so that a long run can resume after it.
                print(f"difftest: {done} programs agree (seeds {args.seed}-"
                      f"{args.seed + done - 1})", file=sys.stderr)
    print(f"difftest: {args.n} programs (seeds {args.seed}-"
          f"{args.seed + args.n - 1}; {ends.get('0', 0)} ran to the end,"
          f" {ends.get('3', 0)} stopped with an alarm) agree under interp, "
          + ", ".join(f"{e} {' '.join(o)}".strip() for e, o in ENGINES),
          file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
