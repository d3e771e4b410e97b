#!/usr/bin/env python3
"""difftest_engines, which runs every engine of a program in one process,
writes exactly what one `mbc run` per engine writes (status, standard error
with the trace, toolpath, DPRNT, variables), given the same run options and
machine profile, so that long difftest runs may use it instead; and a
difference between engines is found through it.

    engines_test.py MBC DIFFTEST_ENGINES
"""
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "tools"))
import difftest  # noqa: E402

mbc, engines = sys.argv[1], sys.argv[2]
with tempfile.TemporaryDirectory() as folder:
    work = Path(folder)
    # Among them programs run with --block-skip, --set and --arg, and with
    # a machine profile that makes G, M and T codes call.
    for seed in range(1, 13):
        source = work / "case.nc"
        text, options, profile = difftest.generate(seed)
        source.write_text(text)
        extra = difftest.case_options(options, profile, work)
        together = difftest.run_all(engines, source, work / "all", extra)
        if together is None:
            sys.exit(f"seed {seed}: difftest_engines failed")
        alone = [difftest.run(mbc, source, "interp", [], work / "interp",
                              extra)]
        alone += [difftest.run(mbc, source, engine, flags, work / engine,
                               extra)
                  for engine, flags in difftest.ENGINES]
        for k, (a, b) in enumerate(zip(alone, together)):
            if a != b:
                names = [n for n in difftest.OUTPUTS if a[n] != b[n]]
                sys.exit(f"seed {seed}, run {k}: {names} differ from mbc run")
    # A planted difference: an output that only one engine changed.
    runs = difftest.run_all(engines, source, work / "all", extra)
    runs[3]["dprnt"] = (runs[3]["dprnt"] or b"") + b"X"
    found = difftest.first_difference(runs[0], runs[1:])
    if found != ("jit -O1", "dprnt"):
        sys.exit(f"the planted difference was found as {found}")
print("difftest_engines: the same outputs as mbc run for 12 programs")
