#!/usr/bin/env python3
"""mbc check's findings on programs that are right: every golden program,
seed program and example is checked, and the warnings that only check
gives (a call held against its macro, a block no path reaches) must be the ones listed in
tests/check_findings.expected, which are true. A new one is either a false
positive (a bug) or a finding to read and add to the list.
    tests/check_findings.py MBC"""
import pathlib
import re
import subprocess
import sys

FLAGS = ("unused-argument", "repeat-count-argument", "unreachable-code",
         "endless-loop", "vacant-address", "maybe-vacant-address",
         "unpassed-argument", "m99-in-main")

root = pathlib.Path(__file__).resolve().parent.parent
mbc = str(pathlib.Path(sys.argv[1]).resolve())
programs = sorted(
    p for pattern in ("tests/programs/*.nc", "tests/seeds/*.nc",
                      "examples/**/*.nc", "bench/workloads/*.nc")
    for p in root.glob(pattern))
found = []
for program in programs:
    out = subprocess.run([mbc, "check", program.name], cwd=program.parent,
                         capture_output=True, text=True).stderr
    for line in out.splitlines():
        flag = re.search(r"\[-W([a-z0-9-]+)\]$", line)
        if flag and flag.group(1) in FLAGS:
            where = program.parent.relative_to(root) / line
            found.append(str(where))
expected_path = root / "tests" / "check_findings.expected"
expected = [line for line in expected_path.read_text().splitlines()
            if line and not line.startswith("#")]
for line in sorted(set(found) - set(expected)):
    print(f"new finding: {line}")
for line in sorted(set(expected) - set(found)):
    print(f"finding gone: {line}")
print(f"{len(programs)} programs checked, {len(found)} findings")
sys.exit(0 if sorted(found) == sorted(expected) and programs else 1)
