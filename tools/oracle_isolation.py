"""Runs that must not see each other, on the difftest generator's random
programs: `mbc batch` runs a program once per row of a table in one
context per thread, resetting it before each row; each of three identical
rows, run one after the other on one thread, must write what `mbc run` of
the program alone writes (toolpath, DPRNT, variables). A state a run
leaves behind that the reset does not clear (a clock, a setting, a signal,
an offset...) shows as a difference in the second row. Each program first
prints what a control keeps over power-off, so that a leak shows even
where the program does not read it."""

import subprocess

import difftest

ROWS = ("r1", "r2", "r3")
# What a control keeps over power-off and programs can read, printed first.
KEPT = ("#3002", "#3005", "#1132", "#1133", "#3901", "#3902", "#5201",
        "#5221", "#5241", "#500", "#501", "#999", "#4001", "#4003",
        "#4006", "#4109", "#5001", "#5002")


def reading_kept(text):
    """The program with a DPRNT of KEPT after its first O line."""
    lines = text.split("\n")
    at = next(i for i, line in enumerate(lines) if line.startswith("O")) + 1
    items = "".join(f"*{number[1:]}*{number}[63]" for number in KEPT)
    return "\n".join(lines[:at] + [f"DPRNT[KEPT{items}]"] + lines[at:])
OUTPUTS = ("toolpath.jsonl", "dprnt", "vars.json")


def outputs(folder, stem):
    """The files a run wrote, None for one it did not."""
    found = {}
    for name in OUTPUTS:
        path = folder / f"{stem}.{name}"
        found[name] = path.read_bytes() if path.exists() else None
    return found


def differences(mbc, text, options, profile, folder):
    """What a row of the batch writes differently from the program `text`
    (with its run options and machine profile) run alone, as text; []
    when every row agrees."""
    source = folder / "case.nc"
    source.write_text(text)
    extra = difftest.case_options(options, profile, folder)
    limit = ["--max-blocks", difftest.MAX_BLOCKS]
    subprocess.run(
        [mbc, "run", str(source), *extra, *limit,
         "--toolpath", str(folder / "alone.toolpath.jsonl"),
         "--dprnt", str(folder / "alone.dprnt"),
         "--vars-out", str(folder / "alone.vars.json")],
        capture_output=True, timeout=120)
    table = folder / "rows.csv"
    table.write_text("id\n" + "\n".join(ROWS) + "\n")
    subprocess.run(
        [mbc, "batch", str(source), "--params", str(table), "--out",
         str(folder / "rows"), "-j", "1", *extra, *limit],
        capture_output=True, timeout=300)
    alone = outputs(folder, "alone")
    found = []
    for row in ROWS:
        for name, data in outputs(folder / "rows", row).items():
            # An output that stays empty is no file in a batch.
            if data != alone[name] and (data or alone[name]):
                found.append(f"row {row}: its {name} differs from the "
                             "program run alone")
    return found
