"""mbc.batch on a DataFrame against `mbc batch` on the same table as CSV,
and mbc.dask on a LocalCluster of two worker processes against both."""
import json

import numpy
import pandas
import pytest

import mbc
from conftest import SOURCE, run_mbc

POCKET = SOURCE / "examples" / "sim-loop" / "pocket.nc"


@pytest.fixture(scope="module")
def table():
    """Pockets with a missing argument, a tool too large, presets."""
    rows = []
    for i in range(40):
        rows.append({"id": f"p{i:03}", "X": (i % 5) * 100.0, "Y": 0.0,
                     "Z": -2.0 - i % 3, "R": 10.0 + (i % 8),
                     "D": numpy.nan if i == 7 else (40.0 if i == 9 else 6.0),
                     "Q": 1.5, "F": 300.0 + i, "#500": float(i)})
    return pandas.DataFrame(rows)


@pytest.fixture(scope="module")
def pocket():
    return mbc.compile(str(POCKET))


def test_batch_matches_mbc_batch(tmp_path, table, pocket):
    results, motions = mbc.batch(pocket, table, threads=2, motions=True)
    csv = tmp_path / "table.csv"
    table.to_csv(csv, index=False)
    done = run_mbc("batch", POCKET, "--params", csv, "--out", tmp_path / "out",
                   "--combined", "-j", "2")
    assert done.returncode == 3, done.stderr  # rows 7 and 9 alarm
    lines = [json.loads(l) for l in
             (tmp_path / "out" / "batch.jsonl").read_text().splitlines()]
    assert list(results["id"]) == [l["id"] for l in lines]
    for (_, got), want in zip(results.iterrows(), lines):
        assert got["status"] == want["status"]
        assert got["alarm"] == want["alarm"]
        assert (got["blocks"], got["moves"]) == (want["blocks"], want["moves"])
        assert f'{got["feed_length"]:.3f}' == f'{want["feed_length"]:.3f}'
        assert f'{got["rapid_length"]:.3f}' == f'{want["rapid_length"]:.3f}'
        assert f'{got["cycle_time"]:.1f}' == f'{want["cycle_time"]:.1f}'
        assert got["dprnt"] == want["dprnt"]
        assert {str(k): v for k, v in got["variables"].items()} == want["variables"]
    assert list(results.loc[[7, 9], "alarm_number"]) == [3002, 3004]
    assert set(motions["id"]) == {l["id"] for l in lines if l["moves"]}
    first = motions[motions["id"] == "p000"]
    assert len(first) == lines[0]["moves"]
    assert list(first["motion"])[:2] == ["rapid", "rapid"]


# Rows that call different programs: each row's machine numbers its
# programs as it meets them, so the motions' program codes differ by row.
BRANCHES = """%
O4620(FACE OR FACE AND SPOT - BY ROW)
G90G00X0Y0Z5.
IF[#1EQ0]GOTO10
M98P4621
N10G01X[#2]F300.
M30
O4621(SPOT)
G00Z1.
G01Z-1.F100.
G00Z5.
M99
%
"""


def per_row_motions(results_ids, runs):
    """The motions as DataFrames row by row: the oracle of one pass."""
    frames = []
    for row_id, run in zip(results_ids, runs):
        frame = run.motions_frame()
        frame.insert(0, "id", row_id)
        frames.append(frame)
    return pandas.concat(frames, ignore_index=True)


def test_motions_of_all_rows_in_one_pass():
    program = mbc.compile(BRANCHES)
    table = pandas.DataFrame({"id": ["a", "b", "c", "d"],
                              "A": [0.0, 1.0, 0.0, 1.0],
                              "B": [10.0, 20.0, 30.0, 40.0]})
    results, motions = mbc.batch(program, table, motions=True)
    runs = [program(mbc.Machine(), A=a, B=b)
            for a, b in zip(table["A"], table["B"])]
    want = per_row_motions(table["id"], runs)
    names = {c: object for c in ("id", "motion", "prog", "file")}
    pandas.testing.assert_frame_equal(motions.astype(names),
                                      want.astype(names))
    assert set(motions["prog"]) == {"O4620", "O4621"}
    assert list(results["moves"]) == [2, 5, 2, 5]
    # No rows: no motions, in the same columns.
    empty = mbc.batch(program, table.iloc[[]], motions=True)[1]
    assert list(empty.columns) == list(motions.columns) and len(empty) == 0


def test_batch_rows_do_not_see_each_other(table, pocket):
    one = mbc.batch(pocket, table, threads=1)
    two = mbc.batch(pocket, table, threads=2)
    pandas.testing.assert_frame_equal(one, two)
    # Each row starts at power-on: row 3 alone gives row 3's result.
    alone = mbc.batch(pocket, table.iloc[[3]])
    pandas.testing.assert_frame_equal(alone, one.iloc[[3]])


def test_numbered_rows_and_bad_columns(pocket):
    results = mbc.batch(pocket, pandas.DataFrame({"R": [5.0] * 12, "D": 2.0,
                                                  "Z": -1.0}))
    assert list(results["id"])[:2] == ["01", "02"]
    with pytest.raises(ValueError, match="column"):
        mbc.batch(pocket, pandas.DataFrame({"depth": [1.0]}))
    with pytest.raises(ValueError, match="G, L, N, O and P"):
        mbc.batch(pocket, pandas.DataFrame({"P": [1.0]}))


def test_dask_on_two_worker_processes(table, pocket):
    distributed = pytest.importorskip("dask.distributed")
    import dask
    import mbc.dask
    local, local_motions = mbc.batch(pocket, table, motions=True)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1,
                                  processes=True, dashboard_address=None) \
            as cluster, distributed.Client(cluster):
        lazy = mbc.dask.batch(pocket, table, npartitions=4)
        remote = lazy.compute()
        # A Machine given for its profile: the profile travels.
        on_machine = mbc.dask.batch(pocket, table, npartitions=3,
                                    machine=mbc.Machine()).compute()
        # The motions, partitioned as the rows: each partition runs once.
        both, moves = mbc.dask.batch(pocket, table, npartitions=4,
                                     motions=True)
        assert moves.npartitions == 4
        with_motions, remote_motions = dask.compute(both, moves)
    pandas.testing.assert_frame_equal(remote, local)
    pandas.testing.assert_frame_equal(on_machine, local)
    pandas.testing.assert_frame_equal(with_motions, local)
    names = {c: object for c in ("id", "motion", "prog", "file")}
    pandas.testing.assert_frame_equal(
        remote_motions.reset_index(drop=True).astype(names),
        local_motions.astype(names))


MACHINE_DATA = SOURCE / "tests" / "batch" / "machine_data.nc"


@pytest.fixture(scope="module")
def machine_data():
    """A program that reads the machine data a control keeps over power-off
    (#3002, #3005, signals, counters, commons, offsets), then changes it."""
    return mbc.compile(str(MACHINE_DATA))


def changing_rows(count):
    return pandas.DataFrame({"id": [f"r{i:02}" for i in range(count)],
                             "A": [1.0 + i % 4 * 0.25 for i in range(count)],
                             "B": [float(5 + i % 3) for i in range(count)]})


def test_rows_that_change_machine_data_do_not_see_each_other(machine_data):
    distributed = pytest.importorskip("dask.distributed")
    import mbc.dask
    table = changing_rows(24)
    one = mbc.batch(machine_data, table, threads=1)
    assert (one["status"] == "ended").all()
    # What each row read before it changed anything is one text.
    assert len({"\n".join(d.splitlines()[:3]) for d in one["dprnt"]}) == 1
    pandas.testing.assert_frame_equal(
        mbc.batch(machine_data, table, threads=2), one)
    backwards = mbc.batch(machine_data, table.iloc[::-1], threads=1)
    pandas.testing.assert_frame_equal(backwards.iloc[::-1], one)
    for i in (0, 7, 23):
        pandas.testing.assert_frame_equal(
            mbc.batch(machine_data, table.iloc[[i]]), one.iloc[[i]])
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1,
                                  processes=True, dashboard_address=None) \
            as cluster, distributed.Client(cluster):
        remote = mbc.dask.batch(machine_data, table, npartitions=5).compute()
    pandas.testing.assert_frame_equal(remote, one)


def test_a_machine_after_reset_runs_as_a_new_one(machine_data):
    used = mbc.Machine()
    for step in (2.0, 0.5):
        machine_data(used, A=step, B=3)
    used.reset()
    again = machine_data(used, A=1, B=4)
    new = machine_data(mbc.Machine(), A=1, B=4)
    assert again.dprnt == new.dprnt
    assert again.variables == new.variables
    for field in new.motions.dtype.names:
        numpy.testing.assert_array_equal(again.motions[field],
                                         new.motions[field])


# A row that loops until Ctrl-C: A=0 ends at once, A=1 never does.
LOOPING = """%
O4630(COUNT - A1 LOOPS FOREVER)
G90G00X#24Y0
WHILE[#1EQ1]DO1
#100=#100+1
END1
G01X[#24+1.]F100.
M30
%
"""


def test_ctrl_c_keeps_the_finished_rows_and_resume_runs_the_rest():
    import os
    import signal
    import threading
    program = mbc.compile(LOOPING)
    table = pandas.DataFrame({"id": [f"r{i}" for i in range(6)],
                              "A": [0.0, 0.0, 0.0, 1.0, 0.0, 0.0],
                              "X": [float(i) for i in range(6)]})
    timer = threading.Timer(0.5, os.kill, (os.getpid(), signal.SIGINT))
    timer.start()
    with pytest.raises(mbc.BatchInterrupted) as stopped:
        mbc.batch(program, table, threads=1, motions=True,
                  max_blocks=10**15)
    assert isinstance(stopped.value, KeyboardInterrupt)
    partial = stopped.value.results
    assert list(partial["status"]) == ["ended"] * 3 + ["interrupted"] + \
        ["not run"] * 2
    assert list(partial.index) == list(table.index)
    assert set(stopped.value.motions["id"]) == {"r0", "r1", "r2", "r3"}
    # The looping row is fixed; the rows done are kept, the others run.
    fixed = table.assign(A=0.0)
    whole, whole_motions = mbc.batch(program, fixed, motions=True)
    results, motions = mbc.batch(program, fixed, motions=True,
                                 resume=stopped.value)
    pandas.testing.assert_frame_equal(results, whole)
    names = {c: object for c in ("id", "motion", "prog", "file")}
    pandas.testing.assert_frame_equal(motions.astype(names),
                                      whole_motions.astype(names))
    # A results DataFrame resumes too; motions=True then needs motions. A
    # kept row is not run again, whatever its cells say now.
    again = mbc.batch(program, fixed, resume=partial)
    pandas.testing.assert_frame_equal(again, whole)
    moved = mbc.batch(program, fixed.assign(X=50.0), resume=partial)
    assert list(moved["feed_length"])[:3] == list(whole["feed_length"])[:3]
    assert list(moved["rapid_length"])[:3] == list(whole["rapid_length"])[:3]
    assert list(moved["rapid_length"])[3:] != list(whole["rapid_length"])[3:]
    with pytest.raises(ValueError, match="motions"):
        mbc.batch(program, fixed, motions=True, resume=partial)
