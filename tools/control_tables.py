#!/usr/bin/env python3
"""Writes and checks the tables of docs/control-tables.md from the runtime's.

The G code lists of both series, the system variable map and a lathe's
offset variables are printed from the tables the runtime executes by
(tests/tables/dump_control_tables.cpp dumps them as JSON): each sits in the
document between the lines

    <!-- generated: NAME -->
    <!-- end generated -->

and nothing else there is touched. The tables written by hand are checked
against the same dump: every parameter a profile may set is a row of
docs/machine-profile.md's table and every row there is one a profile may
set; every function mbc has is a row of the functions table, and no row of
the functions mbc lacks names one it has.

    tools/control_tables.py --dump build/tests/dump_control_tables [--check]

--check writes nothing and fails if the document differs from what it would
write or a hand-written table disagrees with the runtime.
"""

import argparse
import difflib
import json
import pathlib
import re
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
DOC = ROOT / "docs" / "control-tables.md"
PROFILE_DOC = ROOT / "docs" / "machine-profile.md"
REGION = re.compile(r"(<!-- generated: ([a-z-]+) -->\n)(.*?)(<!-- end generated -->)",
                    re.S)
NO_CODE = -1


def g_code(tenths):
    if tenths == NO_CODE:
        return "-"
    whole, tenth = divmod(tenths, 10)
    return f"G{whole:02d}" + (f".{tenth}" if tenth else "")


def status(modelled):
    return "executes" if modelled else "MBC0001"


def table(header, rows):
    """A markdown table: the header's cells, then one line per row."""
    lines = ["| " + " | ".join(header) + " |",
             "|" + "---|" * len(header)]
    return lines + ["| " + " | ".join(cells) + " |" for cells in rows]


def mill_codes(tables):
    return table(["Code", "Function", "mbc"],
                 [[g_code(row["tenths"]), row["name"], status(row["modelled"])]
                  for row in tables["gcodes_m"]])


def lathe_codes(tables):
    return table(["System A", "System B", "System C", "Function", "mbc"],
                 [[g_code(row["a"]), g_code(row["b"]), g_code(row["c"]),
                   row["name"], status(row["modelled"])]
                  for row in tables["gcodes_t"]])


def numbers(first, last):
    return f"#{first}" if first == last else f"#{first}-#{last}"


def variable_status(row):
    note = row["note"]
    if not row["modelled"]:
        return f"PS0115: {note}"
    what = "read and write" if row["writable"] else "read only"
    if row["by_profile"]:
        return what + (f", by profile ({note})" if note else ", by profile")
    return what + (f"; {note}" if note else "")


def system_variables(tables):
    return table(["Variables", "Meaning", "mbc", "Unit"],
                 [[numbers(row["first"], row["last"]), row["meaning"],
                   variable_status(row), row["unit"]]
                  for row in tables["system_variables"]])


def lathe_offsets(tables):
    return table(["Offsets 1-64 (Y: 1-49)", "Offsets 1-999", "Profile key"],
                 [[numbers(row["short_base"] + 1,
                           row["short_base"] + row["short_count"]),
                   numbers(row["long_base"] + 1, row["long_base"] + 999),
                   f"`{row['key']}`"]
                  for row in tables["lathe_offsets"]])


RENDER = {
    "gcodes-m": mill_codes,
    "gcodes-t": lathe_codes,
    "system-variables": system_variables,
    "lathe-offsets": lathe_offsets,
}


def render(text, tables, problems):
    seen = set()

    def replace(match):
        name = match.group(2)
        if name not in RENDER:
            problems.append(f"{DOC.name}: no table is called '{name}'")
            return match.group(0)
        seen.add(name)
        body = "\n".join(RENDER[name](tables)) + "\n"
        return match.group(1) + body + match.group(4)

    out = REGION.sub(replace, text)
    for name in sorted(set(RENDER) - seen):
        problems.append(f"{DOC.name}: the table '{name}' is missing")
    return out


def parameter_numbers(specs):
    return {n for spec in specs for n in range(spec["first"], spec["last"] + 1)}


def documented_parameters():
    """The numbers of docs/machine-profile.md's parameter rows."""
    found = set()
    text = PROFILE_DOC.read_text()
    section = text[text.index("### Parameters"):]
    section = section[:section.index("\n#", 1)]
    for line in section.splitlines():
        if not line.startswith("| `"):
            continue
        first_cell = line.split("|")[1]
        for match in re.finditer(r"`(\d{4,5})`(?:-`(\d{4,5})`)?", first_cell):
            first = int(match.group(1))
            last = int(match.group(2) or first)
            found.update(range(first, last + 1))
    return found


def function_rows(text, heading):
    """The first cells of the table under a heading of the document."""
    at = text.find(heading)
    if at < 0:
        return None
    names = []
    for line in text[at:].splitlines()[1:]:
        if line.startswith("#"):
            break
        if line.startswith("| `"):
            first = line.split("|")[1]
            names += re.findall(r"`([A-Z]+)`", first)
    return names


def check_hand_written(text, tables, problems):
    allowed = parameter_numbers(tables["parameters"])
    documented = documented_parameters()
    for n in sorted(allowed - documented):
        problems.append(f"{PROFILE_DOC.name}: parameter {n:04d} is not listed")
    for n in sorted(documented - allowed):
        problems.append(f"{PROFILE_DOC.name}: parameter {n:04d} is listed, "
                        "but a profile cannot set it")
    have = {f["name"] for f in tables["functions"]}
    executed = function_rows(text, "### Functions mbc executes")
    missing = function_rows(text, "### Functions mbc does not have")
    if executed is None or missing is None:
        problems.append(f"{DOC.name}: the two function tables are missing")
        return
    for name in sorted(have - set(executed)):
        problems.append(f"{DOC.name}: function {name} is not listed")
    for name in sorted(set(executed) - have):
        problems.append(f"{DOC.name}: {name} is listed as executed, "
                        "but mbc has no such function")
    for name in sorted(set(missing) & have):
        problems.append(f"{DOC.name}: {name} is listed as missing, "
                        "but mbc has it")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--dump", required=True,
                        help="the dump_control_tables executable")
    parser.add_argument("--check", action="store_true",
                        help="write nothing; fail on a difference")
    args = parser.parse_args()
    tables = json.loads(subprocess.run([args.dump], check=True,
                                       capture_output=True, text=True).stdout)
    text = DOC.read_text()
    problems = []
    new = render(text, tables, problems)
    check_hand_written(new, tables, problems)
    if args.check and new != text:
        sys.stdout.writelines(difflib.unified_diff(
            text.splitlines(True), new.splitlines(True),
            str(DOC), "what tools/control_tables.py writes"))
        problems.append(f"{DOC.name} is not current: run "
                        "tools/control_tables.py --dump "
                        "build/tests/dump_control_tables")
    elif new != text:
        DOC.write_text(new)
        print(f"updated {DOC}")
    for problem in problems:
        print(problem, file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
