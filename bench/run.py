#!/usr/bin/env python3
"""Runs the mbc benchmarks and prints one markdown table (bench/README.md).

Every number is the median of several runs in one session on one machine:
compare the ratios, not the absolute times, across machines.
"""
import argparse
import os
import platform
import re
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
TIME_LINE = re.compile(r"mbc: time: (.*)")
PHASE = re.compile(r"([a-zA-Z ]+?) ([0-9.]+) ms")
MOVES = re.compile(r"(\d+) blocks, (\d+) moves")


def run_once(command):
    """Wall time (s), peak memory (MiB), stderr of one run."""
    start = time.perf_counter()
    process = subprocess.Popen(command, stdout=subprocess.DEVNULL,
                               stderr=subprocess.PIPE, text=True)
    stderr = process.stderr.read()
    _, status, usage = os.wait4(process.pid, 0)
    wall = time.perf_counter() - start
    process.returncode = os.waitstatus_to_exitcode(status)
    if process.returncode not in (0,):
        sys.exit(f"bench: {' '.join(command)} failed:\n{stderr}")
    return wall, usage.ru_maxrss / 1024.0, stderr


def phases_of(stderr):
    match = TIME_LINE.search(stderr)
    return {name.strip(): float(ms) for name, ms in PHASE.findall(match.group(1))}


def measure(command, runs):
    """Medians over `runs`: wall s, peak MiB, phases (ms), moves."""
    walls, peaks, phase_runs, moves = [], [], [], 0
    for _ in range(runs):
        wall, peak, stderr = run_once(command)
        walls.append(wall)
        peaks.append(peak)
        phase_runs.append(phases_of(stderr))
        found = MOVES.search(stderr)
        moves = int(found.group(2)) if found else 0
    phases = {name: statistics.median(p[name] for p in phase_runs)
              for name in phase_runs[0]}
    return {"wall": statistics.median(walls), "peak": max(peaks),
            "phases": phases, "moves": moves}


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


def engines(mbc, workload, runs, work):
    base = [mbc, "run", str(workload), "--time", "--dprnt", "/dev/null"]
    results = {}
    for engine in ("interp", "ir", "jit"):
        results[engine] = measure(base + ["--engine", engine], runs)
    exe = Path(work) / workload.stem
    start = time.perf_counter()
    subprocess.run([mbc, "build", str(workload), "-o", str(exe)], check=True,
                   stderr=subprocess.DEVNULL)
    results["build"] = time.perf_counter() - start
    results["aot"] = measure([str(exe), "--time", "--dprnt", "/dev/null"],
                             runs)
    hand = Path(mbc).parent / "bench" / f"hand_{workload.stem}"
    if hand.exists():
        results["hand"] = measure([str(hand)], runs)
    return results


def ms(value):
    return f"{value:.1f}"


def ratio(a, b):
    return f"{a / b:.1f}x" if b > 0 else "-"


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--mbc", default=str(HERE.parent / "build" / "mbc"))
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--out", help="also write the report here")
    args = parser.parse_args()
    mbc = str(Path(args.mbc).resolve())
    rows = []
    with tempfile.TemporaryDirectory() as work:
        for workload in sorted((HERE / "workloads").glob("*.nc")):
            print(f"bench: {workload.name}", file=sys.stderr)
            r = engines(mbc, workload, args.runs, work)
            run = {name: r[name]["phases"]["run"]
                   for name in ("interp", "ir", "jit", "aot", "hand")
                   if name in r}
            jit_compile = sum(v for k, v in r["jit"]["phases"].items()
                              if k != "run")
            moves = r["jit"]["moves"]
            rate = moves / (run["jit"] / 1000.0) / 1e6 if run["jit"] else 0
            hand = run.get("hand")
            rows.append(
                f"| {workload.stem} | {moves} | {ms(run['interp'])} | "
                f"{ms(run['ir'])} | {ms(run['jit'])} | "
                f"{ms(run['jit'] + jit_compile)} | {ms(run['aot'])} | "
                f"{ms(hand) if hand else '-'} | "
                f"{ratio(run['interp'], run['jit'])} | "
                f"{ratio(run['jit'], hand) if hand else '-'} | {rate:.2f} | "
                f"{r['jit']['peak']:.0f} |")
    report = "\n".join([
        "# mbc benchmarks", "",
        f"Machine: {machine_text()}.",
        f"Median of {args.runs} runs; times in ms of the run phase (`mbc run"
        " --time`), no toolpath output (null sink). hand C++: the workload"
        " written in C++ on the same runtime path (bench/hand/); jit / hand"
        " is how much slower compiled Macro B is than that bound.", "",
        "| workload | moves | interp | ir | jit | jit incl. compile | aot |"
        " hand C++ | interp / jit | jit / hand | Mmoves/s (jit) |"
        " peak MiB (jit) |",
        "|---|---|---|---|---|---|---|---|---|---|---|---|",
        *rows, ""])
    print(report)
    if args.out:
        Path(args.out).write_text(report)


if __name__ == "__main__":
    main()
