#!/usr/bin/env python3
"""What an editor waits for from `mbc lsp` on a 2 000-line macro: the
diagnostics after an edit (the goal is 100 ms), a hover, the semantic
tokens of the whole document and a code lens's run. Each is timed from
the request (or the change) to its answer, in ms, median, min and max.

    lsp_latency.py MBC [--edits N] [--json]
"""

import argparse
import json
import pathlib
import statistics
import sys
import tempfile
import time

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent / "tests"))
from lsp_client import ServerClient  # noqa: E402

LINES = 2000
GOAL_MS = 100


def macro():
    """A drilling macro of about 2 000 lines, as a shop writes one, and the
    main program that calls it: arguments checked, a row of holes per
    station in a loop, DPRNT reports, each station its own section."""
    out = ["%", "O1000(STATIONS FOR PLATE 12)", "G21G17G40G80G90",
           "G65P9100A4.D10.", "M30",
           "O9100(STATION PATTERNS)", "(ARGS: A=HOLES D=TOOL DIA)",
           "IF[#1EQ#0]GOTO9000", "IF[#7LE0]GOTO9001", "#100=0"]
    station = 0
    while len(out) < LINES - 12:
        station += 1
        out += [
            f"N{station * 10}(STATION {station})",
            f"#101={station * 25.}",
            "#102=0",
            "WHILE[#102LT#1]DO1",
            "#103=#101+[#102*12.5]",
            "G90G00X#103Y[#102*8.]",
            "G43Z25.H01",
            "G81Z-[#7*0.6]R2.F180.",
            "G80",
            "IF[#103GT400.]THEN#100=#100+1",
            "#102=#102+1",
            "END1",
            "#104=ROUND[#101*SIN[30.]]",
            "G01X[#104+5.]Y-12.F600.",
            "DPRNT[STATION*#101[43]*DONE]",
        ]
    out += ["M99", "N9000#3000=1(STATIONS MISSING)",
            "N9001#3000=2(TOOL DIA NOT POSITIVE)", "M99", "%", ""]
    return "\n".join(out)


def timed(work):
    start = time.perf_counter()
    work()
    return (time.perf_counter() - start) * 1000.0


def latencies(mbc, edits):
    with tempfile.TemporaryDirectory() as tmp:
        root = pathlib.Path(tmp)
        c = ServerClient(mbc, root)
        c.start()
        text = macro()
        rows = {}
        uri = None

        def open_document():
            nonlocal uri
            uri = c.open("stations.nc", text)
            c.diagnostics(uri)
        rows["open to diagnostics"] = [timed(open_document)]
        line = text.split("\n").index("#102=0")

        def edit(version):
            """#102=0 becomes #102=N, and its diagnostics arrive."""
            c.notify("textDocument/didChange", {
                "textDocument": {"uri": uri, "version": version},
                "contentChanges": [{"range": {
                    "start": {"line": line, "character": 5},
                    "end": {"line": line, "character": 6}},
                    "text": str(version % 10)}]})
            c.diagnostics(uri, version)
        rows["edit to diagnostics"] = [
            timed(lambda: edit(version)) for version in range(2, edits + 2)]
        rows["hover"] = [timed(lambda: c.ask("textDocument/hover", uri,
                                             line + 4, 3))
                         for _ in range(edits)]
        rows["semantic tokens"] = [timed(lambda: c.call(
            "textDocument/semanticTokens/full",
            {"textDocument": {"uri": uri}})) for _ in range(5)]

        def lens():
            lenses = c.call("textDocument/codeLens",
                            {"textDocument": {"uri": uri}})["result"]
            # O1000's, which runs the whole macro; a version of its own
            # each time, so that the run is not the one kept.
            c.call("codeLens/resolve", lenses[0])
        lens_times = []
        for version in range(edits + 2, edits + 7):
            edit(version)
            lens_times.append(timed(lens))
        rows["code lens (a run)"] = lens_times
        c.stop()
    return {name: {"median": statistics.median(t), "min": min(t),
                   "max": max(t), "n": len(t)} for name, t in rows.items()}


def table(rows):
    lines = ["| request | median ms | min ms | max ms | runs |",
             "|---|---|---|---|---|"]
    for name, r in rows.items():
        lines.append(f"| {name} | {r['median']:.1f} | {r['min']:.1f} | "
                     f"{r['max']:.1f} | {r['n']} |")
    return lines


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("mbc")
    parser.add_argument("--edits", type=int, default=20)
    parser.add_argument("--json", action="store_true")
    args = parser.parse_args()
    rows = latencies(args.mbc, args.edits)
    print(json.dumps(rows) if args.json else "\n".join(table(rows)))


if __name__ == "__main__":
    main()
