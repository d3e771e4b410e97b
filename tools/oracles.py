#!/usr/bin/env python3
"""Oracles of the machine model that share no code with mbc's runtime, run
on random programs: every engine runs on the same runtime, so the engines'
differential test cannot see a wrong path the runtime makes.

* compensation (oracle_compensation.py): random contours under cutter
  compensation, with ,C and ,R corners, Z moves, G41/G42, types A and B,
  random D, under G68, G51.1, G51 and G52; the tool centre must keep the
  offset (no gouge), run on its element's offset path, and turn arcs about
  their centres;
* relations (oracle_relations.py): random motion programs under G52, G92,
  G68, G51.1 and G51 against the plain program moved by the oracle's own
  transform, and written with G91, G16, M98 and G65 against the plain
  program;
* isolation (oracle_isolation.py): the difftest generator's programs, each
  printing first what a control keeps over power-off, as three rows of a
  batch against the program run alone.

A failure is shrunk to a small case that still fails, written to --out,
and printed with what the oracle found. Exit status 0 when every case
holds, 1 at the first that does not.

    tools/oracles.py --mbc build/mbc -n 200 [--seed 1] [--jobs 2] [--out DIR]
"""

import argparse
import multiprocessing
import pathlib
import random
import sys
import tempfile

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))

import difftest  # noqa: E402
import oracle_compensation  # noqa: E402
import oracle_isolation  # noqa: E402
import oracle_relations  # noqa: E402

# At most this share of the random contours may end in an alarm of the
# control (no solution, interference) rather than be checked.
MOST_ALARMS = 0.3


def compensation_fails(mbc, case):
    """What the compensation oracle finds wrong with a case; [] when it
    holds, None when the control alarms (nothing to check)."""
    with tempfile.TemporaryDirectory() as folder:
        records, alarm = oracle_compensation.run(mbc, case,
                                                 pathlib.Path(folder))
    if records is None:
        return None
    return oracle_compensation.violations(case, records)


def relations_fail(mbc, motion, seed):
    """(relation, differences) of the first relation that fails, () when
    all hold, None when the plain program alarms."""
    with tempfile.TemporaryDirectory() as folder:
        failed, _ = oracle_relations.relations(
            mbc, motion, pathlib.Path(folder), random.Random(seed))
    if failed is None:
        return None
    return failed[0] if failed else ()


def isolation_fails(mbc, text, options, profile):
    """What the isolation oracle finds of a difftest program."""
    with tempfile.TemporaryDirectory() as folder:
        return oracle_isolation.differences(mbc, text, options, profile,
                                            pathlib.Path(folder))


def isolation_case(seed):
    text, options, profile = difftest.generate(seed)
    return oracle_isolation.reading_kept(text), options, profile


def check(job):
    mbc, seed = job
    return (seed,
            compensation_fails(mbc, oracle_compensation.Case(seed)),
            relations_fail(mbc, oracle_relations.Motion(seed), seed),
            isolation_fails(mbc, *isolation_case(seed)))


def shrink_motion(motion, still_fails):
    """A motion program with as few blocks as still fail."""
    changed = True
    while changed:
        changed = False
        for i in range(len(motion.blocks)):
            smaller = oracle_relations.Motion.__new__(oracle_relations.Motion)
            smaller.__dict__ = dict(motion.__dict__)
            smaller.blocks = motion.blocks[:i] + motion.blocks[i + 1:]
            if any(kind == "line" and data[1] for kind, data in
                   smaller.blocks[-1:]):
                continue  # a corner needs the line after it
            first, last = motion.call_span
            smaller.call_span = (first - (first > i),
                                 last - (last > i))
            if still_fails(smaller):
                motion, changed = smaller, True
                break
    return motion


def report_compensation(mbc, out, seed, found):
    case = oracle_compensation.shrink(
        oracle_compensation.Case(seed),
        lambda c: bool(compensation_fails(mbc, c)))
    lines = case.contour()[0]
    path = pathlib.Path(out) / f"oracle-compensation-{seed}.nc"
    path.write_text("\n".join(lines) + "\n")
    path.with_suffix(".json").write_text(case.profile())
    print(f"oracles: compensation, {case.describe()}: "
          f"{'; '.join((compensation_fails(mbc, case) or found)[:3])}\n"
          f"  shrunk case: {path} (machine profile beside it)\n"
          + "\n".join(lines), file=sys.stderr)


def report_relation(mbc, out, seed, found):
    relation = found[0]
    motion = shrink_motion(
        oracle_relations.Motion(seed),
        lambda m: (relations_fail(mbc, m, seed) or ("",))[0] == relation)
    path = pathlib.Path(out) / f"oracle-relations-{seed}.nc"
    path.write_text(motion.text())
    again = relations_fail(mbc, motion, seed) or found
    print(f"oracles: relation {relation}, seed {seed}: "
          f"{'; '.join(again[1][:3])}\n  shrunk plain program: {path}\n"
          + motion.text(), file=sys.stderr)


def report_isolation(mbc, out, seed, found):
    text, options, profile = isolation_case(seed)
    small = difftest.reduce(text, lambda t: bool(
        isolation_fails(mbc, t, options, profile)))
    path = difftest.keep_case(out, seed, small, profile)
    print(f"oracles: isolation, seed {seed}: {'; '.join(found[:3])}\n"
          f"  reduced case: {path} (run options: "
          f"{' '.join(options) or '(none)'})\n{small}", file=sys.stderr)


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    difftest.add_run_options(parser, "seeds")
    args = parser.parse_args()
    mbc = str(pathlib.Path(args.mbc).resolve())
    jobs = [(mbc, seed) for seed in range(args.seed, args.seed + args.n)]
    contours = alarmed = programs = plain_alarms = 0
    with multiprocessing.Pool(args.jobs) as pool:
        for seed, contour, relation, isolation in pool.imap(check, jobs):
            if contour:
                pool.terminate()
                report_compensation(mbc, args.out, seed, contour)
                return 1
            if relation:
                pool.terminate()
                report_relation(mbc, args.out, seed, relation)
                return 1
            if isolation:
                pool.terminate()
                report_isolation(mbc, args.out, seed, isolation)
                return 1
            contours += contour is not None
            alarmed += contour is None
            programs += relation is not None
            plain_alarms += relation is None
    print(f"oracles: seeds {args.seed}-{args.seed + args.n - 1}: "
          f"{contours} compensated contours hold ({alarmed} stopped at an "
          f"alarm of the control), {programs} motion programs keep every "
          f"relation ({plain_alarms} stopped at an alarm), {args.n} "
          f"programs run alike alone and as batch rows", file=sys.stderr)
    if alarmed > MOST_ALARMS * args.n:
        print(f"oracles: more than {MOST_ALARMS:.0%} of the contours "
              "alarmed: the generator no longer tests much", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
