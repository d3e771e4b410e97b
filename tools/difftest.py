#!/usr/bin/env python3
"""Differential testing of mbc's engines on random Macro B programs.

Generates valid programs (bounded loops, IF/GOTO with computed and
loop-leaving jumps, M99 P in the main program, G65/M98 nests, G66 modal
calls, indirection across variable ranges, vacant values, every function
and operator with edge arguments, DPRNT, motion, system variables), runs
each under every engine and optimisation level, and compares everything a
run writes with the interpreter's: exit status, stderr (alarms,
the --trace record), toolpath, DPRNT and variables. A program that differs is
reduced line by line to a small one that still differs the same way and
written to --out.

    tools/difftest.py --mbc build/mbc [--engines build/tests/difftest_engines]
                      -n 1000 [--seed 1] [--jobs 2]

--engines runs all the engines of a program in one process (about twice as
fast; tests/difftest/engines_test.py checks it writes what mbc run does).

Exit status 0 when every program agreed, 1 when one differed.
"""
import argparse
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
# simulated clock, the G66 state.
SYSTEM_READS = ("#4114", "#4001", "#4003", "#4109", "#4012", "#5001",
                "#5002", "#5003", "#5041", "#3001")


class Generator:
    """One random program: a main program, G65 macros that call later
    macros and M98 subprograms, and M98 subprograms that call nothing."""

    def __init__(self, seed):
        self.rng = random.Random(seed)
        self.macros = [2001 + i for i in range(self.rng.randint(0, 3))]
        self.subs = [3001 + i for i in range(self.rng.randint(0, 2))]

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

    def motion(self):
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
        if self.chance(0.2):  # no GOTO target: #4114 reads it
            prefix = f"N{self.rng.randint(1000, 1999)} {prefix}"
        return f"{prefix}{code} {' '.join(words)}"

    def dprnt(self):
        items = []
        for _ in range(self.rng.randint(1, 3)):
            text = self.pick(("A", "VAL", "X", "R*", "N1*"))
            items.append(f"{text}#{self.rng.randint(1, 33)}"
                         f"[{self.rng.randint(1, 5)}{self.rng.randint(0, 3)}]")
        return f"DPRNT[{'*'.join(items)}]"

    def arguments(self):
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

    def body(self, program, level, loops, labels, budget):
        """Statements of one nesting level; `loops` open WHILE counters;
        `labels` the N numbers placed at the top level of the program."""
        lines = []
        counters = SUB_COUNTERS if level == "sub" else MACRO_COUNTERS
        while budget > 0:
            budget -= 1
            roll = self.rng.random()
            if roll < 0.3:
                lines.append(self.assignment())
            elif roll < 0.42:
                lines.append(self.motion())
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
            else:
                lines.append(self.assignment())
        return lines

    def program(self, number, level):
        """A program whose top level is cut into labelled sections, so that
        every GOTO jumps forward to a section start."""
        sections = self.rng.randint(1, 4)
        labels = [10 * (i + 1) + 1 for i in range(sections)]
        lines = [f"O{number}"]
        if level == "main":
            lines.append("G90 G17 G21 G00 X0 Y0 Z0 F1000")
        for i, label in enumerate(labels):
            later = labels[i + 1:]
            # A section of the main program under a G66 modal call; a GOTO
            # past its G67 leaves it in force under the next one's.
            modal = level == "main" and self.macros and self.chance(0.2)
            if modal:
                lines.append(f"G66 P{self.pick(self.macros)} "
                             f"{self.arguments()}".rstrip())
            lines += self.body(number, level, [], later,
                               self.rng.randint(2, 8))
            if modal:
                lines.append("G67")
            lines.append(f"N{label} #{self.rng.randint(1, 26)} = {label}")
        lines.append("M30" if level == "main" else "M99")
        return lines

    def text(self):
        lines = ["%"] + self.program(1000, "main")
        for macro in self.macros:
            lines += self.program(macro, "macro")
        for sub in self.subs:
            lines += self.program(sub, "sub")
        return "\n".join(lines + ["%", ""])


def run(mbc, source, engine, options, work):
    """Everything one run writes, as a dict of output name to text."""
    work.mkdir(parents=True, exist_ok=True)
    for name in OUTPUTS:
        (work / name).unlink(missing_ok=True)
    try:
        result = subprocess.run(
            [mbc, "run", str(source), "--engine", engine, *options,
             "--trace", "--max-blocks", MAX_BLOCKS,
             "--toolpath", str(work / "toolpath.jsonl"),
             "--dprnt", str(work / "dprnt"),
             "--vars-out", str(work / "vars.json")],
            capture_output=True, text=True, timeout=60)
        status, stderr = str(result.returncode), result.stderr
    except subprocess.TimeoutExpired:
        status, stderr = "timeout", ""
    outputs = {"status": status, "stderr": stderr}
    for name in OUTPUTS[2:]:
        path = work / name
        outputs[name] = path.read_text() if path.exists() else None
    return outputs


def run_all(engines, source, work):
    """What every run wrote, interp first then ENGINES, from one process of
    difftest_engines (tests/difftest/engines_main.cpp); None when that
    process itself failed (a crash in one engine ends them all)."""
    try:
        result = subprocess.run([engines, str(source), MAX_BLOCKS, str(work)],
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
            outputs[name] = path.read_text() if path.exists() else None
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


def compare(mbc, text, work, engines=None):
    """The interpreter's exit status, and (engine, output) of the first
    engine that differs from the interpreter or None. With `engines`, one
    process runs them all; when it fails, each runs in an mbc of its own,
    which tells which one."""
    source = work / "case.nc"
    source.write_text(text)
    runs = run_all(engines, source, work / "all") if engines else None
    if runs is None:
        runs = [run(mbc, source, "interp", [], work / "interp")]
        runs += [run(mbc, source, engine, options, work / engine)
                 for engine, options in ENGINES]
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
    text = Generator(seed).text()
    with tempfile.TemporaryDirectory() as work:
        status, found = compare(mbc, text, Path(work), engines)
    return seed, text, status, found


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--mbc", default="build/mbc")
    parser.add_argument("-n", type=int, default=100, help="programs")
    parser.add_argument("--seed", type=int, default=1, help="first seed")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--out", default=".", help="where reduced cases go")
    parser.add_argument("--show", type=int, help="print the program of a seed")
    parser.add_argument("--engines", help="build/tests/difftest_engines: all "
                        "engines of a program in one process (faster)")
    args = parser.parse_args()
    if args.show is not None:
        print(Generator(args.show).text(), end="")
        return 0
    mbc = str(Path(args.mbc).resolve())
    engines = str(Path(args.engines).resolve()) if args.engines else None
    jobs = [(mbc, engines, seed)
            for seed in range(args.seed, args.seed + args.n)]
    ends = {}
    with multiprocessing.Pool(args.jobs) as pool:
        for done, (seed, text, status, found) in enumerate(
                pool.imap(check, jobs), 1):
            ends[status] = ends.get(status, 0) + 1
            if status not in ("0", "3"):
                # Not a valid program (a generator bug), an internal error,
                # a crash or a hang: each worth a look.
                pool.terminate()
                path = Path(args.out) / f"difftest-{seed}.nc"
                path.write_text(text)
                print(f"difftest: seed {seed}: the interpreter's run ended "
                      f"with status {status} ({path})", file=sys.stderr)
                return 1
            if found:
                pool.terminate()
                print(f"difftest: seed {seed}: --engine {found[0]} differs "
                      f"from interp in {found[1]}; reducing", file=sys.stderr)
                with tempfile.TemporaryDirectory() as work:
                    small = reduce(text, lambda t: compare(
                        mbc, t, Path(work))[1] == found)
                path = Path(args.out) / f"difftest-{seed}.nc"
                path.write_text(small)
                print(f"difftest: reduced case in {path}:\n{small}",
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
