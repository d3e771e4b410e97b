#!/usr/bin/env python3
"""Every diagnostic kind of frontend/diagnostic_kinds.def has a test: its
message appears in an expected file of a golden or diagnostics case
(.check, .stderr), or a unit test names it (DiagKind::Name). A new kind
without one fails here.
    tests/diagnostic_coverage.py"""
import pathlib
import re
import sys

root = pathlib.Path(__file__).resolve().parent.parent
table = (root / "frontend" / "diagnostic_kinds.def").read_text()
kinds = re.findall(r'^DIAG\((\w+), \w+, \w+, "(.*)"\)$', table, re.M)
kinds += re.findall(r'^WARNING\((\w+), "[^"]*", "(.*)"\)$', table, re.M)
expected = "".join(
    path.read_text(errors="replace")
    for pattern in ("*.check", "*.stderr")
    for path in (root / "tests").rglob(pattern))
units = "".join(path.read_text() for path in (root / "tests" / "unit").glob("*.cpp"))

untested = []
for name, message in kinds:
    # The message with each {} argument as "anything".
    text = message.replace('\\"', '"').replace("\\\\", "\\")
    pattern = ".*".join(re.escape(part) for part in re.split(r"\{[^}]*\}", text))
    if not re.search(pattern, expected) and f"DiagKind::{name}" not in units:
        untested.append(name)
for name in untested:
    print(f"frontend/diagnostic_kinds.def: {name} has no test (a case in "
          f"tests/diag, or a unit test naming DiagKind::{name})")
print(f"{len(kinds)} diagnostic kinds, {len(untested)} without a test")
sys.exit(1 if untested or not kinds else 0)
