#!/usr/bin/env python3
"""Runs the mbc benchmarks and prints one markdown report (bench/README.md).

Every number is measured in one session on one machine: compare the
ratios, not the absolute times, across machines.
"""
import argparse
import json
import os
import platform
import re
import shutil
import signal
import statistics
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

import lsp_latency

HERE = Path(__file__).resolve().parent
TIME_LINE = re.compile(r"mbc: time: (.*)")
PHASE = re.compile(r"([a-zA-Z ]+?) ([0-9.]+) ms")
MOVES = re.compile(r"(\d+) blocks, (\d+) moves")
INSTRUCTIONS = re.compile(r"I\s+refs:\s+([0-9,]+)")
RS274_MOVES = re.compile(r"STRAIGHT_FEED|STRAIGHT_TRAVERSE|ARC_FEED")
SIZES = (1000, 10000, 100000)
LEVELS = ("-O0", "-O1", "-O2")


def run_once(command, timeout=None):
    """Wall time (s), peak memory (MiB), stderr of one run; None when it
    ran past `timeout` seconds and was killed."""
    with tempfile.TemporaryFile("w+") as err:
        start = time.perf_counter()
        process = subprocess.Popen(command, stdout=subprocess.DEVNULL,
                                   stderr=err, text=True)
        timer = threading.Timer(timeout, process.kill) if timeout else None
        if timer:
            timer.start()
        _, status, usage = os.wait4(process.pid, 0)
        wall = time.perf_counter() - start
        if timer:
            timer.cancel()
        process.returncode = os.waitstatus_to_exitcode(status)
        err.seek(0)
        stderr = err.read()
    if timer and process.returncode == -signal.SIGKILL:
        return None
    if process.returncode != 0:
        sys.exit(f"bench: {' '.join(command)} failed:\n{stderr}")
    return wall, usage.ru_maxrss / 1024.0, stderr


def phases_of(stderr):
    match = TIME_LINE.search(stderr)
    if not match:
        return {}
    return {name.strip(): float(ms) for name, ms in PHASE.findall(match.group(1))}


def measure(command, runs):
    """Medians over `runs`: wall s, peak MiB, phases (ms), moves."""
    walls, phase_runs, moves, peak = [], [], 0, 0.0
    for _ in range(runs):
        wall, run_peak, stderr = run_once(command)
        walls.append(wall)
        peak = max(peak, run_peak)
        phase_runs.append(phases_of(stderr))
        found = MOVES.search(stderr)
        moves = int(found.group(2)) if found else 0
    # A first run that fills the cache of compiled code has phases the
    # others do not: the medians are of the phases of every run.
    phases = {name: statistics.median(p[name] for p in phase_runs)
              for name in phase_runs[0]
              if all(name in p for p in phase_runs)}
    return {"wall": statistics.median(walls), "peak": peak, "phases": phases,
            "moves": moves}


def machine_text():
    cpu = "unknown CPU"
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    commit = subprocess.run(["git", "-C", str(HERE), "rev-parse", "--short",
                             "HEAD"], capture_output=True, text=True).stdout
    return (f"{cpu}, {os.cpu_count()} cores, {platform.system()} "
            f"{platform.release()}; mbc {commit.strip() or 'unknown'}")


def build_exe(mbc, workload, work):
    exe = Path(work) / workload.stem
    subprocess.run([mbc, "build", str(workload), "-o", str(exe)], check=True,
                   stderr=subprocess.DEVNULL)
    return exe


def hand_of(mbc, workload):
    hand = Path(mbc).parent / "bench" / f"hand_{workload.stem}"
    return hand if hand.exists() else None


def engines(mbc, workload, runs, exe):
    base = [mbc, "run", str(workload), "--time", "--dprnt", "/dev/null"]
    results = {}
    for engine in ("interp", "ir"):
        results[engine] = measure(base + ["--engine", engine], runs)
    # Compiled each time: "jit incl. compile" is a first run's cost.
    results["jit"] = measure(base + ["--engine", "jit", "--no-cache"], runs)
    results["aot"] = measure([str(exe), "--time", "--dprnt", "/dev/null"],
                             runs)
    if hand := hand_of(mbc, workload):
        results["hand"] = measure([str(hand)], runs)
    return results


def rs274_of(workload, runs, startup):
    """LinuxCNC's interpreter on the .ngc twin: seconds less its start-up,
    and the moves of its canonical output (to check the twin)."""
    ngc = HERE / "ngc" / f"{workload.stem}.ngc"
    if not ngc.exists():
        return None
    with tempfile.NamedTemporaryFile("r", suffix=".txt") as out:
        run_once(["rs274", "-g", str(ngc), out.name])
        # Line by line: a child's peak memory counts this process's at the
        # fork, so the script must stay small.
        moves = sum(1 for line in out if RS274_MOVES.search(line))
    walls = [run_once(["rs274", "-g", str(ngc), "/dev/null"])[0]
             for _ in range(runs)]
    return {"ms": (statistics.median(walls) - startup) * 1000.0,
            "moves": moves}


def rs274_startup(runs, work):
    empty = Path(work) / "empty.ngc"
    empty.write_text("M2\n")
    return statistics.median(
        run_once(["rs274", "-g", str(empty), "/dev/null"])[0]
        for _ in range(runs))


def instructions(command):
    """Instructions executed (valgrind's Ir) by the whole process, a count
    that machine noise leaves alone."""
    process = subprocess.run(
        ["valgrind", "--tool=cachegrind", "--cache-sim=no",
         "--cachegrind-out-file=/dev/null", *command],
        stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    found = INSTRUCTIONS.search(process.stderr)
    return int(found.group(1).replace(",", "")) if found else None


def output_modes(mbc, workload, runs, work):
    """Run-phase ms of the JIT with no sink, a JSONL toolpath, G-code."""
    base = [mbc, "run", str(workload), "--time", "--dprnt", "/dev/null"]
    sink = str(Path(work) / "out")
    return {mode: measure(base + extra, runs)["phases"]["run"]
            for mode, extra in (("null", []), ("jsonl", ["--toolpath", sink]),
                                ("gcode", ["--gcode", sink]))}


def compile_scaling(mbc, work, timeout):
    """Wall s and peak MiB of `mbc compile -c` per program size and level;
    None past the timeout. One run each: these take seconds."""
    table = {}
    for size in SIZES:
        source = Path(work) / f"large_{size}.nc"
        subprocess.run([sys.executable, str(HERE / "gen_large.py"), str(size),
                        str(source)], check=True)
        for level in LEVELS:
            print(f"bench: compile {size} lines {level}", file=sys.stderr)
            result = run_once([mbc, "compile", "-c", str(source), "-o",
                               str(Path(work) / "large.o"), level],
                              timeout=timeout)
            table[(size, level)] = result
    return table


def startup(mbc, runs, work):
    """Whole-process wall ms for a small macro: what a user waits for."""
    example = HERE.parent / "examples" / "bolt_circle.nc"
    exe = Path(work) / "bolt_circle"
    subprocess.run([mbc, "build", str(example), "-o", str(exe)], check=True,
                   stderr=subprocess.DEVNULL)
    base = [mbc, "run", str(example), "--time", "--dprnt", "/dev/null"]
    # The cache holds the -O2 code after its first run.
    run_once(base)
    rows = {}
    for name, command in (
            ("interp", base + ["--engine", "interp"]),
            ("ir", base + ["--engine", "ir"]),
            ("jit, cold", base + ["--no-cache"]),
            ("jit -O0, cold", base + ["--no-cache", "-O0"]),
            ("jit, cache hit", base),
            ("aot (mbc build)", [str(exe), "--time", "--dprnt", "/dev/null"])):
        rows[name] = measure(command, max(runs, 15))
    return rows


def end_to_end(mbc, workloads, runs, work):
    """Whole-process wall s of `mbc run` (code in the cache) with no sink,
    the JSONL toolpath and the JSONL toolpath compiled anew, and of rs274
    on the twin, per toolpath workload."""
    rows = {}
    sink = str(Path(work) / "out.jsonl")
    for workload in workloads:
        ngc = HERE / "ngc" / f"{workload.stem}.ngc"
        if not ngc.exists():
            continue
        base = [mbc, "run", str(workload), "--dprnt", "/dev/null"]
        run_once(base)
        rows[workload.stem] = {
            "null": measure(base, runs)["wall"],
            "jsonl": measure(base + ["--toolpath", sink], runs)["wall"],
            "cold": measure(base + ["--toolpath", sink, "--no-cache"],
                            runs)["wall"],
            "rs274": statistics.median(
                run_once(["rs274", "-g", str(ngc), "/dev/null"])[0]
                for _ in range(3))}
    return rows


def end_to_end_table(rows):
    lines = ["| workload | rs274 ms | mbc, null sink ms | mbc, JSONL ms |"
             " mbc, JSONL, compiled anew ms | rs274 / null | rs274 / JSONL |"
             " rs274 / JSONL anew |", "|---|---|---|---|---|---|---|---|"]
    for name, r in rows.items():
        lines.append(
            f"| {name} | {r['rs274'] * 1000:.0f} | {r['null'] * 1000:.1f} | "
            f"{r['jsonl'] * 1000:.1f} | {r['cold'] * 1000:.1f} | "
            f"{ratio(r['rs274'], r['null'])} | {ratio(r['rs274'], r['jsonl'])}"
            f" | {ratio(r['rs274'], r['cold'])} |")
    return lines


RASTER_ROWS = (200, 1000)  # of 1000 points: 200 000 and 1 000 000 moves
RASTER_LINE = "#21 = 1000"
WRITER_RUNS = 11


def raster_of(rows, work):
    """bench's raster and its .ngc twin with `rows` rows of 1000 points."""
    pair = []
    for source in (HERE / "workloads" / "raster.nc",
                   HERE / "ngc" / "raster.ngc"):
        text = source.read_text()
        if RASTER_LINE not in text:
            sys.exit(f"bench: {source} does not set {RASTER_LINE}")
        made = Path(work) / f"raster_{rows}{source.suffix}"
        made.write_text(text.replace(RASTER_LINE, f"#21 = {rows}"))
        pair.append(made)
    return pair


def taking_turns(commands, runs):
    """measure() of each command, their runs taking turns: the kernel
    writes back what one run wrote while the next runs, on the cores the
    writer thread needs, and a series of one mode after a series of
    another would meet another's write-back."""
    os.sync()
    samples = {name: [] for name in commands}
    for _ in range(runs):
        for name, command in commands.items():
            samples[name].append(measure(command, 1))
    return {name: {"wall": statistics.median(m["wall"] for m in taken),
                   "phases": {"run": statistics.median(
                       m["phases"]["run"] for m in taken)},
                   "moves": taken[0]["moves"]}
            for name, taken in samples.items()}


def writer_thread(mbc, runs, rs274_runs, work):
    """Per raster size: whole-process s and run-phase ms of `mbc run` (code
    in the cache) with no toolpath, the JSONL toolpath written by the run
    and on the writer thread, and rs274's whole process."""
    rows = {}
    sink = str(Path(work) / "raster.jsonl")
    # Runs of tens of ms, and a ratio of two of them: more runs than the
    # others, or one noisy run of the null sink decides the ratio.
    runs = max(runs, WRITER_RUNS)
    for raster_rows in RASTER_ROWS:
        workload, ngc = raster_of(raster_rows, work)
        print(f"bench: writer thread, {workload.name}", file=sys.stderr)
        base = [mbc, "run", str(workload), "--time", "--dprnt", "/dev/null"]
        run_once(base)
        modes = taking_turns({
            "null": base,
            "inline": base + ["--toolpath", sink, "--writer-thread", "off"],
            "thread": base + ["--toolpath", sink, "--writer-thread", "on"]},
            runs)
        modes["rs274"] = statistics.median(
            run_once(["rs274", "-g", str(ngc), "/dev/null"])[0]
            for _ in range(rs274_runs)) if shutil.which("rs274") else None
        rows[modes["null"]["moves"]] = modes
    return rows


def writer_thread_table(rows):
    lines = ["| moves | rs274 ms | null sink ms (run) | JSONL on the run's"
             " thread ms (run) | JSONL on the writer thread ms (run) |"
             " run phase, thread / null | rs274 / JSONL on the thread |",
             "|---|---|---|---|---|---|---|"]
    for moves, r in rows.items():
        def cell(mode):
            return (f"{r[mode]['wall'] * 1000:.1f}"
                    f" ({r[mode]['phases']['run']:.1f})")
        lines.append(
            f"| {moves} | {r['rs274'] * 1000 if r['rs274'] else 0:.0f} |"
            f" {cell('null')} | {cell('inline')} | {cell('thread')} |"
            f" {ratio(r['thread']['phases']['run'], r['null']['phases']['run'])}"
            f" | {ratio(r['rs274'], r['thread']['wall'])} |")
    return lines


def writer_thread_bound(rows, operations):
    """What keeps the run phase on the writer thread above the null sink's,
    per move: the motion built for any sink (bench/micro), and the rest."""
    if "LinearMoveToSink" not in operations or not rows:
        return []
    moves = max(rows)
    r = rows[moves]
    over = (r["thread"]["phases"]["run"] - r["null"]["phases"]["run"]) \
        * 1e6 / moves
    sink = operations["LinearMoveToSink"] - operations["LinearMove"]
    return [f"At {moves} moves the run phase on the writer thread is"
            f" {over:.0f} ns a move over the null sink's. {sink:.0f} ns of"
            " it is the motion the C API gives any sink, which the null"
            " sink never builds (its workpiece, machine, start and"
            " programmed points in units; bench/micro's LinearMoveToSink"
            f" less LinearMove); the other {over - sink:.0f} ns are handing"
            " it over (copying what a record prints, counting its bound,"
            " keeping its program's name) and the writer's traffic in the"
            " caches and memory it shares with the run. Formatting and"
            " writing are off the run's thread.", "",
            "Taken apart by hand at 1M moves (b0fa2ce, 9 runs each, the"
            " variants taking turns): the run's thread building the motion"
            " and handing the sink nothing took 20 ns a move over the null"
            " sink; counting each record's bound 4 ns more; copying the"
            " records into the ring and publishing them, with a writer that"
            " wrote nothing, 15 to 20 ns more (136 ms against 92). With the"
            " writer writing, the rest varies from run to run: 129 to 143 ms"
            " run after run, 133 to 300 ms taking turns with runs that"
            " truncate and write files of their own, whose write-back the"
            " writer's writes then wait on, and the run with them once the"
            " ring is full.", "",
            "The drawing (`--svg`) and the page (`--html`) are made on the"
            " writer thread too, what a move may add to them counted ahead"
            " as a record's bound is. The flattened G-code (`--gcode`) stays"
            " on the run's thread: a flattened block's text is made by the"
            " runtime from the block's words and the modal state at that"
            " block, which a hand-over would have to copy whole.", ""]


def writer_thread_text(runs, rs274_runs):
    return (f"bench's raster at 200 and 1000 rows of 1000 points, whole"
            f" processes, median of {max(runs, WRITER_RUNS)}, the modes"
            f" taking turns (rs274: of {rs274_runs}): `mbc"
            " run` with its code in the cache, writing no toolpath (null"
            " sink) or the JSONL toolpath to a file, formatted on the run's"
            " thread (`--writer-thread off`) or on a thread of its own (`on`;"
            " `auto`, the default, where a second core is free), and"
            " LinuxCNC's rs274 on the .ngc twin, its start-up included. In"
            " brackets the run phase (`--time`). The goal: the run phase"
            " with the toolpath within 1.3x the null sink's, the whole"
            " process at least 25x rs274.")


BATCH_ROWS = 10000
BATCH_SUMMARY = re.compile(r"mbc: batch: \d+ rows in ([0-9.]+) s")


def batch_throughput(mbc, runs, work):
    """Median (whole process s, rows phase s) of `mbc batch` over a
    BATCH_ROWS-row table of examples/sim-loop/pocket.nc, per output mode,
    engine and thread count. The rows phase is the time the summary line
    reports: after compilation, which one thread does."""
    table = Path(work) / "pockets.csv"
    with open(table, "w") as f:
        f.write("X,Z,R,D,Q,F\n")
        for i in range(BATCH_ROWS):
            f.write(f"{i % 5 * 100},{-2 - i % 7},{10 + i % 40 * 0.5},"
                    f"{6 + i % 3 * 2},1.5,{300 + i % 4 * 100}\n")
    cycle = HERE.parent / "examples" / "sim-loop" / "pocket.nc"
    results = {}
    for mode, extra in (("combined JSONL", ["--combined"]),
                        ("files per row", [])):
        for engine in ("jit", "interp"):
            for jobs in (1, 2):
                print(f"bench: batch {mode} {engine} -j {jobs}",
                      file=sys.stderr)
                walls, phases = [], []
                for run in range(runs):
                    # A new folder each time: deleting 40 000 files just
                    # before a run would be timed with it.
                    out = Path(work) / f"batch-{len(results)}-{run}"
                    wall, _, stderr = run_once(
                        [mbc, "batch", str(cycle), "--params", str(table),
                         "--out", str(out), "--engine", engine, "-j",
                         str(jobs), *extra])
                    walls.append(wall)
                    phases.append(float(BATCH_SUMMARY.search(stderr)[1]))
                results[(mode, engine, jobs)] = (statistics.median(walls),
                                                 statistics.median(phases))
    for out in Path(work).glob("batch-*"):
        shutil.rmtree(out)
    return results


SIM_CALLS = 20000
THROUGHPUT = re.compile(r"throughput: (\d+) calls/s")


def embedded_calls(build, runs):
    """Median calls per second of the simulation loop around the pocket
    cycle, in C++ (examples/sim-loop/sim_loop.cpp: the compiled cycle
    through the C ABI, a motion callback) and in Python (sim_loop.py: the
    mbc package, a numpy array of motions per call)."""
    sim = HERE.parent / "examples" / "sim-loop"
    calls = str(SIM_CALLS)
    python = ["/usr/bin/python3", str(sim / "sim_loop.py"), calls]
    loops = {"C++ (mbc_O9200, motion callback)":
             [str(build / "examples" / "sim-loop" / "sim_loop"), calls],
             "Python, the loop (calls, numpy totals)": python,
             "Python, the calls alone (Result and motions array)":
             [*python, "--calls-only"]}
    os.environ["PYTHONPATH"] = str(build / "python")
    samples = {name: [] for name in loops}
    # Interleaved, so that a neighbour's load falls on all three alike.
    for run in range(runs):
        print(f"bench: simulation loops, run {run + 1}", file=sys.stderr)
        for name, command in loops.items():
            out = subprocess.run(command, check=True, capture_output=True,
                                 text=True).stdout
            samples[name].append(float(THROUGHPUT.search(out)[1]))
    return {name: statistics.median(s) for name, s in samples.items()}


def python_batch(build, runs):
    """bench/python_batch.py's medians: mbc.batch without and with the
    motions DataFrame."""
    print("bench: Python batch", file=sys.stderr)
    out = subprocess.run(
        ["/usr/bin/python3", str(HERE / "python_batch.py"), "--runs",
         str(runs)], check=True, capture_output=True, text=True,
        env={**os.environ, "PYTHONPATH": str(build / "python")}).stdout
    return json.loads(out)


def python_batch_table(medians):
    return ["| mbc.batch | s | per the batch alone |", "|---|---|---|",
            f"| results only | {medians['batch']:.3f} | 1.00 |",
            f"| with motions=True | {medians['motions']:.3f} | "
            f"{medians['motions'] / medians['batch']:.2f} |"]


def embedded_table(rates):
    lines = ["| loop | calls/s | C++ calls/s per these |", "|---|---|---|"]
    cpp = next(iter(rates.values()))
    for name, rate in rates.items():
        lines.append(f"| {name} | {rate:.0f} | {cpp / rate:.2f} |")
    return lines


def batch_table(results):
    lines = ["| output | engine | rows/s, 1 thread | rows/s, 2 threads |"
             " speed-up, rows phase | speed-up, whole process |",
             "|---|---|---|---|---|---|"]
    for mode, engine in dict.fromkeys((m, e) for m, e, _ in results):
        one, two = results[(mode, engine, 1)], results[(mode, engine, 2)]
        lines.append(f"| {mode} | {engine} | {BATCH_ROWS / one[1]:.0f} | "
                     f"{BATCH_ROWS / two[1]:.0f} | {one[1] / two[1]:.2f} | "
                     f"{one[0] / two[0]:.2f} |")
    return lines


def micro(exe, runs):
    """Median ns per operation of each Google Benchmark in bench/micro."""
    output = subprocess.run(
        [exe, f"--benchmark_repetitions={runs}",
         "--benchmark_report_aggregates_only=true",
         "--benchmark_format=json"],
        check=True, capture_output=True, text=True).stdout
    return {b["run_name"]: b["cpu_time"]
            for b in json.loads(output)["benchmarks"]
            if b.get("aggregate_name") == "median"}


def micro_table(medians):
    return ["| operation | ns |", "|---|---|",
            *(f"| {name} | {ns:.1f} |" for name, ns in medians.items())]


def writer_table(medians):
    """The writers alone: ns per record less the same moves without them."""
    pairs = (("JSONL toolpath record", "LinearMoveToJsonl",
              "LinearMoveToSink"),
             ("flattened G-code block", "LinearMoveToGcode", "LinearMove"))
    return ["| writer | ns per move |", "|---|---|",
            *(f"| {name} | {medians[with_] - medians[without]:.1f} |"
              for name, with_, without in pairs
              if with_ in medians and without in medians)]


def block_split_table(medians):
    """A straight-move block: reading it, and its motion alone."""
    if "LinearMove" not in medians or "LinearMotion" not in medians:
        return ["bench/micro has no LinearMove or LinearMotion."]
    whole, motion = medians["LinearMove"], medians["LinearMotion"]
    return ["| part of a G01 X block | ns |", "|---|---|",
            f"| reading the block: words, G codes, calls, statement start"
            f" | {whole - motion:.1f} |",
            f"| the move: coordinates, clock, box | {motion:.1f} |",
            f"| the whole block | {whole:.1f} |"]


def ms(value):
    return f"{value:.1f}"


def ratio(a, b):
    return f"{a / b:.1f}x" if a and b else "-"


def engine_table(results, rs274):
    rows = []
    for name, r in results.items():
        run = {engine: r[engine]["phases"]["run"]
               for engine in ("interp", "ir", "jit", "aot", "hand")
               if engine in r}
        compile_ms = sum(v for k, v in r["jit"]["phases"].items()
                         if k != "run")
        moves = r["jit"]["moves"]
        rate = moves / (run["jit"] / 1000.0) / 1e6 if run["jit"] else 0
        hand = run.get("hand")
        theirs = rs274.get(name)
        rows.append(
            f"| {name} | {moves} | {ms(run['interp'])} | {ms(run['ir'])} | "
            f"{ms(run['jit'])} | {ms(run['jit'] + compile_ms)} | "
            f"{ms(run['aot'])} | {ms(hand) if hand else '-'} | "
            f"{ms(theirs['ms']) if theirs else '-'} | "
            f"{ratio(run['jit'], hand)} | {ratio(run['interp'], run['jit'])} | "
            f"{ratio(theirs['ms'], run['jit']) if theirs else '-'} | "
            f"{rate:.2f} | {r['jit']['peak']:.0f} |")
    return [
        "| workload | moves | interp | ir | jit | jit incl. compile | aot |"
        " hand C++ | rs274 | jit / hand | interp / jit | rs274 / jit |"
        " Mmoves/s (jit) | peak MiB (jit) |",
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|",
        *rows]


def instruction_table(counts):
    rows = []
    for name, c in counts.items():
        cells = [f"{c[k] / 1e6:.0f}" if c.get(k) else "-"
                 for k in ("interp", "aot", "hand")]
        rows.append(f"| {name} | {' | '.join(cells)} | "
                    f"{ratio(c.get('aot'), c.get('hand'))} | "
                    f"{ratio(c.get('interp'), c.get('aot'))} |")
    return ["| workload | interp | aot | hand C++ | aot / hand |"
            " interp / aot |", "|---|---|---|---|---|---|", *rows]


def mode_table(modes):
    rows = [f"| {name} | {ms(m['null'])} | {ms(m['jsonl'])} | "
            f"{ms(m['gcode'])} | {ratio(m['jsonl'], m['null'])} | "
            f"{ratio(m['gcode'], m['null'])} |" for name, m in modes.items()]
    return ["| workload | null sink | JSONL toolpath | flattened G-code |"
            " JSONL / null | G-code / null |", "|---|---|---|---|---|---|",
            *rows]


def compile_table(table, timeout):
    def cell(result):
        if result is None:
            return f"> {timeout:.0f} s"
        return f"{result[0]:.2f} s, {result[1]:.0f} MiB"
    rows = [f"| {size} | " + " | ".join(cell(table[(size, level)])
                                        for level in LEVELS) + " |"
            for size in SIZES]
    return ["| lines | " + " | ".join(LEVELS) + " |",
            "|---|---|---|---|", *rows]


def startup_table(rows):
    lines = ["| engine | process wall ms | code generation ms | cache ms |"
             " run ms |", "|---|---|---|---|---|"]
    for name, r in rows.items():
        cells = [r["phases"].get(phase)
                 for phase in ("code generation", "cache", "run")]
        lines.append(f"| {name} | {r['wall'] * 1000:.1f} | " + " | ".join(
            ms(c) if c is not None else "-" for c in cells) + " |")
    return lines


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--mbc", default=str(HERE.parent / "build" / "mbc"))
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--rs274-runs", type=int, default=3)
    parser.add_argument("--compile-timeout", type=float, default=60.0)
    parser.add_argument("--micro", help="bench/micro's mbc_micro, when built")
    parser.add_argument("--out", help="also write the report here")
    parser.add_argument("--writer-thread-only", action="store_true",
                        help="print only the section of the writer thread")
    args = parser.parse_args()
    mbc = str(Path(args.mbc).resolve())
    if args.writer_thread_only:
        with tempfile.TemporaryDirectory() as work:
            os.environ["MBC_CACHE_DIR"] = str(Path(work) / "cache")
            rows = writer_thread(mbc, args.runs, args.rs274_runs, work)
        print("\n".join([writer_thread_text(args.runs, args.rs274_runs), "",
                         *writer_thread_table(rows)]))
        return
    has_rs274 = shutil.which("rs274") is not None
    has_valgrind = shutil.which("valgrind") is not None
    results, rs274, counts, modes = {}, {}, {}, {}
    with tempfile.TemporaryDirectory() as work:
        # A cache of this run's own, empty at first, not the user's.
        os.environ["MBC_CACHE_DIR"] = str(Path(work) / "cache")
        startup_rs274 = rs274_startup(args.runs, work) if has_rs274 else 0.0
        for workload in sorted((HERE / "workloads").glob("*.nc")):
            name = workload.stem
            print(f"bench: {workload.name}", file=sys.stderr)
            exe = build_exe(mbc, workload, work)
            results[name] = engines(mbc, workload, args.runs, exe)
            moves = results[name]["jit"]["moves"]
            if has_rs274 and (theirs := rs274_of(workload, args.rs274_runs,
                                                  startup_rs274)):
                if abs(theirs["moves"] - moves) > 1:
                    sys.exit(f"bench: rs274 made {theirs['moves']} moves of "
                             f"{name}, mbc {moves}: the .ngc is no twin")
                rs274[name] = theirs
            if has_valgrind:
                hand = hand_of(mbc, workload)
                counts[name] = {
                    "interp": instructions([mbc, "run", str(workload),
                                            "--engine", "interp"]),
                    "aot": instructions([str(exe)]),
                    "hand": instructions([str(hand)]) if hand else None}
            if moves:
                modes[name] = output_modes(mbc, workload, args.runs, work)
        compiles = compile_scaling(mbc, work, args.compile_timeout)
        small = startup(mbc, args.runs, work)
        whole = end_to_end(mbc, [HERE / "workloads" / f"{name}.nc"
                                 for name in modes], args.runs,
                           work) if has_rs274 else {}
        threaded = writer_thread(mbc, args.runs, args.rs274_runs, work)
        batch = batch_throughput(mbc, args.runs, work)
        embedded = embedded_calls(Path(mbc).parent, args.runs)
        python = python_batch(Path(mbc).parent, args.runs)
        operations = micro(args.micro, args.runs) if args.micro else {}
        editor = lsp_latency.latencies(mbc, 20)
    report = "\n".join([
        "# mbc benchmarks", "",
        f"Machine: {machine_text()}.", "",
        "## Engines", "",
        f"Median of {args.runs} runs; ms of the run phase (`mbc run --time`)"
        " with no toolpath output (null sink). hand C++: the workload written"
        " in C++ on the same runtime calls (bench/hand/), the practical bound."
        f" rs274: LinuxCNC's interpreter on the .ngc twin (bench/ngc/, same"
        f" move count checked), median of {args.rs274_runs} whole runs less"
        f" its start-up ({startup_rs274 * 1000:.0f} ms), output to /dev/null."
        if has_rs274 else " rs274 was not installed.", "",
        *engine_table(results, rs274), "",
        "## Instructions", "",
        "Millions of instructions per whole run (valgrind), which machine"
        " noise leaves alone; interp includes the front end, aot and hand"
        " their start-up.", "",
        *(instruction_table(counts) if counts else ["valgrind missing."]), "",
        "## Output modes (jit)", "",
        "Run-phase ms writing nothing, the JSONL toolpath (on the writer"
        " thread, as `--writer-thread auto` chooses on two cores), or the"
        " flattened G-code (on the run's thread): what output costs the"
        " run.", "",
        *mode_table(modes), "",
        "## Compile time and memory against program size", "",
        "`mbc compile -c` of programs from bench/gen_large.py (a main program"
        " calling 40-line subprograms): wall time and peak memory, one run"
        " each.", "",
        *compile_table(compiles, args.compile_timeout), "",
        "## End to end", "",
        "Whole processes as a user runs them, median of"
        f" {args.runs} (rs274: of 3): `mbc run` of the workload with its"
        " code in the cache (the second run of an unchanged program) with"
        " no toolpath output and with the JSONL toolpath, the JSONL run"
        " compiled anew (`--no-cache`), and LinuxCNC's rs274 on the .ngc"
        " twin, its start-up included.", "",
        *(end_to_end_table(whole) if whole else ["rs274 was not installed."]),
        "",
        "## The toolpath on a writer thread", "",
        writer_thread_text(args.runs, args.rs274_runs), "",
        *writer_thread_table(threaded), "",
        *writer_thread_bound(threaded, operations),
        "## Start-up for a small macro", "",
        "examples/bolt_circle.nc, whole process, median of"
        f" {max(args.runs, 15)}: the interpreter and the IR evaluator, the"
        " JIT compiling (`--no-cache`, which loads LLVM) or loading its"
        " code from the cache (which does not), and the executable of"
        " `mbc build`.", "",
        *startup_table(small), "",
        "## Batch throughput", "",
        f"`mbc batch` of a {BATCH_ROWS}-row table of examples/sim-loop/"
        "pocket.nc (a circular pocket, about 40 moves a row), median of"
        f" {args.runs}: rows per second of the rows phase (after"
        " compilation, as the summary line reports it) on one thread and"
        " on two (`-j`), and the speed-up of that phase and of the whole"
        " process (start-up and compilation are not shared out), with the"
        " rows' results in one combined JSONL file or in four files per"
        " row.", "",
        *batch_table(batch), "",
        "## Embedded calls: C++ and Python", "",
        f"The simulation loop of examples/sim-loop, {SIM_CALLS} calls of the"
        " pocket cycle O9200 on one machine (each call goes on from where the"
        " last left the tool) with every motion measured, median of"
        f" {args.runs}: sim_loop.cpp through the C ABI, sim_loop.py through"
        " the Python package (keyword arguments in, a Result with a numpy"
        " motions array out, lengths computed with numpy).", "",
        *embedded_table(embedded), "",
        "## Python batch", "",
        f"`mbc.batch` of a {python['rows']}-row table of examples/sim-loop/"
        f"pocket.nc ({python['moves']} motions in all) in one process on"
        " every core, without and with `motions=True` (the motions of all"
        f" rows as one DataFrame), median of {args.runs}"
        " (bench/python_batch.py).", "",
        *python_batch_table(python), "",
        "## The language server", "",
        f"`mbc lsp` on a {lsp_latency.LINES}-line macro and its main program"
        " (bench/lsp_latency.py), from the request or the change to its"
        " answer as a client of the tests sees it: the diagnostics after an"
        f" edit (the goal: {lsp_latency.GOAL_MS} ms), a hover, the semantic"
        " tokens of the whole document, and O1000's code lens (a run of the"
        " whole macro by the interpreter).", "",
        *lsp_latency.table(editor), "",
        "## Writers alone", "",
        "What writing one move costs beyond making it (bench/micro, the"
        " differences below): the run phase's share of the output modes"
        " above comes from these and from the kernel's write.", "",
        *(writer_table(operations) if operations
          else ["bench/micro was not built (MBC_MICRO_BENCH)."]), "",
        "## The per-block path", "",
        "Where an NC block with a straight move spends its time (bench/micro:"
        " LinearMotion runs the same moves from their words in counts, below"
        " the C API, so the difference from LinearMove is the reading of the"
        " block).", "",
        *(block_split_table(operations) if operations
          else ["bench/micro was not built (MBC_MICRO_BENCH)."]), "",
        "The goal was 30 ns for the whole block. What stops the move near"
        " 30 ns on its own is the simulated clock (#3001, #3002 and the"
        " summary's cycle time): the move's length is a square root, and"
        " its time divisions by the counts per unit, the feed and 3600, one"
        " after another, each rounded as the goldens pin them, so none"
        " becomes a multiplication. Under perf, with the coordinates in"
        " one pass (frames.h placeProgramPoint), the length and the clock"
        " take half the move's samples, waiting on those results. The"
        " reading has no one hot spot: its largest share, the block's own"
        " function (its state cleared, its words handed to their readers),"
        " is a third of it, and rounding the axis word to counts a sixth.",
        "",
        "## Runtime operations", "",
        "In-process CPU time of one operation of the runtime that every"
        " engine calls (bench/micro, Google Benchmark), median of"
        f" {args.runs} repetitions: an NC block with a straight move, its"
        " motion alone, the same block into a motion sink, written as a"
        " JSONL record and as a flattened G-code block (the writers alone"
        " are the differences), a half-circle arc, a block without motion,"
        " the start of a statement, a common variable access and functions"
        " of the language.", "",
        *(micro_table(operations) if operations
          else ["bench/micro was not built (MBC_MICRO_BENCH)."]), ""])
    print(report)
    if args.out:
        Path(args.out).write_text(report)


if __name__ == "__main__":
    main()
