#!/usr/bin/env python3
"""The same diagnostics in every format: for each program of tests/diag,
`mbc check` (with the options of its NAME.check-args) as text, as JSON and
as SARIF 2.1.0 (with and without -Werror)
must name the same diagnostics (file, line, column, severity, message, in
order, notes after their diagnostic) and the same fix-its, and the SARIF
log must have the structure the SARIF 2.1.0 specification requires of what
it holds. Usage: diagnostic_formats.py MBC DIAG_DIR"""
import json
import os
import re
import subprocess
import sys
import urllib.parse

TEXT_LINE = re.compile(r"^(.+?):(\d+):(\d+): (error|warning|note): (.*)$")


def run(mbc, cwd, args):
    p = subprocess.run([mbc, "check", *args], cwd=cwd, capture_output=True)
    return p.returncode, p.stderr.decode("utf-8", "replace")


def from_text(stderr):
    out = []
    for line in stderr.splitlines():
        m = TEXT_LINE.match(line)
        if m:
            f, ln, col, sev, msg = m.groups()
            out.append((f, int(ln), int(col), sev, msg))
        elif line.startswith("mbc: error: "):
            out.append(("", 0, 0, "error", line[len("mbc: error: "):]))
    return out


def from_json(stderr):
    out, fixits = [], []

    def add(d):
        locs = d["locations"]
        msg = d["message"] + (f" [{d['option']}]" if d.get("option") else "")
        if locs:
            c = locs[0]["caret"]
            out.append((c["file"], c["line"], c["column"], d["kind"], msg))
        else:
            out.append(("", 0, 0, d["kind"], msg))
        fixits.extend(f["string"] for f in d.get("fixits", []))
        for child in d.get("children", []):
            add(child)

    for d in json.loads(stderr.splitlines()[0]):
        add(d)
    return out, fixits


def code_point_column(path, line, byte_column):
    with open(path, "rb") as f:
        text = f.read().split(b"\n")[line - 1]
    # A byte of no valid UTF-8 character counts as one.
    return len(text[:byte_column - 1].decode("utf-8", "surrogateescape")) + 1


def check_region(region, where):
    for key in ("startLine", "startColumn", "endLine", "endColumn"):
        assert isinstance(region[key], int) and region[key] >= 1, where
    assert (region["endLine"], region["endColumn"]) >= (
        region["startLine"], region["startColumn"]), where


def from_sarif(stderr, cwd):
    log = json.loads(stderr.splitlines()[0])
    assert log["version"] == "2.1.0" and len(log["runs"]) == 1
    run_ = log["runs"][0]
    driver = run_["tool"]["driver"]
    assert driver["name"] == "mbc" and driver["version"]
    rules = driver["rules"]
    assert len({r["id"] for r in rules}) == len(rules)
    out, fixits = [], []
    for r in run_["results"]:
        assert rules[r["ruleIndex"]]["id"] == r["ruleId"]
        assert r["level"] in ("error", "warning", "note", "none")
        option = r.get("properties", {}).get("option")
        msg = r["message"]["text"] + (f" [{option}]" if option else "")
        places = [(loc, r["level"], msg) for loc in r.get("locations", [])]
        if not places:
            out.append(("", 0, 0, r["level"], msg))
        places += [(loc, "note", loc["message"]["text"])
                   for loc in r.get("relatedLocations", [])]
        for loc, level, text in places:
            phys = loc["physicalLocation"]
            path = urllib.parse.unquote(phys["artifactLocation"]["uri"])
            check_region(phys["region"], text)
            out.append((path, phys["region"]["startLine"],
                        phys["region"]["startColumn"], level, text))
        for fix in r.get("fixes", []):
            assert fix["description"]["text"]
            for change in fix["artifactChanges"]:
                for rep in change["replacements"]:
                    check_region(rep["deletedRegion"], "fix-it")
                    fixits.append(rep["insertedContent"]["text"])
    return out, fixits


def main():
    mbc, diag_dir = sys.argv[1], sys.argv[2]
    programs = sorted(p for p in os.listdir(diag_dir) if p.endswith(".nc"))
    failures = 0
    for name in programs:
        # NAME.check-args: the case's own options (run_case.sh).
        args_path = os.path.join(diag_dir, name[:-3] + ".check-args")
        own = (open(args_path).read().split()
               if os.path.exists(args_path) else [])
        for extra in (own, [*own, "-Werror"]):
            status, text = run(mbc, diag_dir, [name, *extra])
            expected = from_text(text)
            s_json, j = run(mbc, diag_dir,
                            [name, *extra, "--diagnostics-format=json"])
            s_sarif, s = run(mbc, diag_dir,
                             [name, *extra, "--diagnostics-format=sarif"])
            got_json, fix_json = from_json(j)
            got_sarif, fix_sarif = from_sarif(s, diag_dir)
            # SARIF counts columns in code points, the text in bytes.
            text_cp = [(f, ln, code_point_column(os.path.join(diag_dir, f),
                                                 ln, col) if ln else 0, sev,
                        msg) for f, ln, col, sev, msg in expected]
            problems = []
            if not expected and not name.startswith("ok_"):
                problems.append("no diagnostics in the text")
            if got_json != expected:
                problems.append(f"JSON {got_json} != text {expected}")
            if got_sarif != text_cp:
                problems.append(f"SARIF {got_sarif} != text {text_cp}")
            if fix_json != fix_sarif:
                problems.append(f"fix-its JSON {fix_json} SARIF {fix_sarif}")
            if not status == s_json == s_sarif:
                problems.append(f"exit {status} {s_json} {s_sarif}")
            for p in problems:
                print(f"{name} {' '.join(extra)}: {p}")
            failures += bool(problems)
    print(f"{len(programs)} programs, {failures} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
