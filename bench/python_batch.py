#!/usr/bin/env python3
"""mbc.batch over a ROWS-row table of examples/sim-loop/pocket.nc with and
without motions=True, in one process: the median seconds of each and their
ratio (the motions' cost on top of the runs). Prints one JSON object.

    PYTHONPATH=build/python bench/python_batch.py [--rows N] [--runs N]"""
import argparse
import json
import statistics
import time
from pathlib import Path

import pandas

import mbc

HERE = Path(__file__).resolve().parent


def table(rows: int) -> pandas.DataFrame:
    """The rows of bench/run.py's batch table: pockets of 40 sizes."""
    return pandas.DataFrame({
        "X": [i % 5 * 100 for i in range(rows)],
        "Z": [-2 - i % 7 for i in range(rows)],
        "R": [10 + i % 40 * 0.5 for i in range(rows)],
        "D": [6 + i % 3 * 2 for i in range(rows)],
        "Q": [1.5] * rows,
        "F": [300 + i % 4 * 100 for i in range(rows)]})


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--rows", type=int, default=5000)
    parser.add_argument("--runs", type=int, default=5)
    args = parser.parse_args()
    program = mbc.compile(HERE.parent / "examples" / "sim-loop" / "pocket.nc")
    rows = table(args.rows)
    plain, motions = [], []
    moves = 0
    # Interleaved, so that a neighbour's load falls on both alike.
    for _ in range(args.runs):
        start = time.perf_counter()
        mbc.batch(program, rows)
        plain.append(time.perf_counter() - start)
        start = time.perf_counter()
        _, frame = mbc.batch(program, rows, motions=True)
        motions.append(time.perf_counter() - start)
        moves = len(frame)
    print(json.dumps({"rows": args.rows, "moves": moves,
                      "batch": statistics.median(plain),
                      "motions": statistics.median(motions)}))


if __name__ == "__main__":
    main()
