#!/usr/bin/env python3
"""difftest_engines, which runs every engine of a program in one process,
writes exactly what one `mbc run` per engine writes (status, standard error
with the trace, toolpath, DPRNT, variables), so that long difftest runs
may use it instead; and a difference between engines is found through it.

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
    for seed in range(1, 13):
        source = work / "case.nc"
        source.write_text(difftest.Generator(seed).text())
        together = difftest.run_all(engines, source, work / "all")
        if together is None:
            sys.exit(f"seed {seed}: difftest_engines failed")
        alone = [difftest.run(mbc, source, "interp", [], work / "interp")]
        alone += [difftest.run(mbc, source, engine, options, work / engine)
                  for engine, options in difftest.ENGINES]
        for k, (a, b) in enumerate(zip(alone, together)):
            if a != b:
                names = [n for n in difftest.OUTPUTS if a[n] != b[n]]
                sys.exit(f"seed {seed}, run {k}: {names} differ from mbc run")
    # A planted difference: an output that only one engine changed.
    runs = difftest.run_all(engines, source, work / "all")
    runs[3]["dprnt"] = (runs[3]["dprnt"] or "") + "X"
    found = difftest.first_difference(runs[0], runs[1:])
    if found != ("jit -O1", "dprnt"):
        sys.exit(f"the planted difference was found as {found}")
print("difftest_engines: the same outputs as mbc run for 12 programs")
