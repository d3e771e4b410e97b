"""mbc.batch: one run per row of a pandas DataFrame, on every core."""
from __future__ import annotations

import os
import re
from typing import Any, Mapping, Optional, Union

import numpy

from . import _mbc

#: The result columns, in order (those of `mbc batch`'s results.csv, with
#: the id first and the alarm's number and code beside its report line).
RESULT_COLUMNS = ("id", "status", "blocks", "moves", "feed_length",
                  "rapid_length", "cycle_time", "alarm", "alarm_number",
                  "alarm_code", "dprnt", "variables")

_PRESET = re.compile(r"#(\d+)$")


def _rows(table, profile: Optional[str]) -> tuple:
    """The table's rows as (argument letters, their values, presets) and
    their ids; a column no row can use is refused before any row runs."""
    from . import argument_letter, number_value
    letters, presets = [], []
    probe = None
    for column in table.columns:
        name = str(column)
        if name == "id":
            continue
        if len(name) == 1:
            letters.append((column, argument_letter(name, "column")))
        elif _PRESET.match(name):
            # The machine says which variables a host may preset.
            probe = probe or _mbc.Context(profile)
            try:
                probe.write(float(name[1:]), 0.0)
            except (KeyError, ValueError) as e:
                raise ValueError(f"column {name}: {e}") from None
            presets.append((column, float(name[1:])))
        else:
            raise ValueError(f"column {name!r}: neither an argument letter, "
                             "a #N variable nor id")
    rows = []
    for record in table.itertuples(index=False, name=None):
        values = dict(zip(table.columns, record))
        given = [(letter, number_value(values[c], f"column {c}"))
                 for c, letter in letters if _present(values[c])]
        sets = [(number, number_value(values[c], f"column {c}"))
                for c, number in presets if _present(values[c])]
        rows.append(("".join(l for l, _ in given), [v for _, v in given],
                     sets))
    if "id" in table.columns:
        ids = [str(i) for i in table["id"]]
        if len(set(ids)) != len(ids):
            raise ValueError("the id column has duplicates")
    else:
        width = len(str(len(rows)))
        ids = [str(i + 1).zfill(width) for i in range(len(rows))]
    return rows, ids


def _present(value) -> bool:
    """An empty cell passes nothing, as in `mbc batch`."""
    if value is None:
        return False
    try:
        return not numpy.isnan(value)
    except TypeError:
        return value != ""


def _status(result) -> str:
    if result is None:
        return "not run"
    if result.alarm is None:
        return "ended"
    return "interrupted" if result.alarm.code == "MBC0004" else "alarm"


#: The statuses of rows a resumed batch keeps, as `mbc batch --resume` does.
_DONE = ("ended", "alarm")


class BatchInterrupted(KeyboardInterrupt):
    """Ctrl-C stopped mbc.batch: the rows it finished are kept.

    results: the results DataFrame of every row, those the signal cut
    short "interrupted", those it never started "not run"; motions: the
    motions DataFrame with motions=True (else None). mbc.batch(...,
    resume=the exception) runs the rest."""

    def __init__(self, results, motions=None):
        super().__init__("mbc.batch was interrupted: the finished rows are "
                         "in .results; resume=this exception runs the rest")
        self.results = results
        self.motions = motions


def _record(run) -> tuple:
    """A row of the results, in RESULT_COLUMNS order after the id."""
    if run is None:
        return ("not run", 0, 0, 0.0, 0.0, 0.0, None, 0, None, "", {})
    alarm = run.alarm
    return (_status(run), run.blocks, run.moves, run.feed_length,
            run.rapid_length, run.cycle_time,
            None if alarm is None else alarm.report.split("\n", 1)[0],
            0 if alarm is None else alarm.number,
            None if alarm is None else alarm.code, run.dprnt, run.variables)


def _resumed(resume, motions: bool) -> tuple:
    """The earlier batch a resume keeps: its results by id and its motions
    (or None)."""
    if isinstance(resume, BatchInterrupted):
        resume = resume.results if resume.motions is None else \
            (resume.results, resume.motions)
    earlier, earlier_motions = resume if isinstance(resume, tuple) else \
        (resume, None)
    if motions and earlier_motions is None:
        raise ValueError("resume: motions=True needs the earlier batch's "
                         "motions too (its BatchInterrupted, or (results, "
                         "motions))")
    done = earlier[earlier["status"].isin(_DONE)]
    return ({row_id: record for row_id, *record in
             done[list(RESULT_COLUMNS)].itertuples(index=False, name=None)},
            earlier_motions)


def run_table(program, table, threads: Optional[int] = None,
              motions: bool = False, max_blocks: int = 0,
              machine=None, resume=None):
    """The batch of one table (a pandas DataFrame), in this process: the
    results DataFrame, and with motions=True the motions DataFrame too."""
    import pandas
    from . import Result, _profile_text
    profile = _profile_text(machine) if machine is not None \
        else program.machine_profile
    rows, ids = _rows(table, profile)
    kept, kept_motions = _resumed(resume, motions) if resume is not None \
        else ({}, None)
    todo = [i for i, row_id in enumerate(ids) if row_id not in kept]
    raw, interrupt = _mbc.run_rows(program._compiled, profile,
                                   [rows[i] for i in todo],
                                   threads or os.cpu_count() or 1, max_blocks)
    runs = [None if r is None else Result._from(r) for r in raw]
    records = [kept.get(row_id) for row_id in ids]
    for i, run in zip(todo, runs):
        records[i] = _record(run)
    results = pandas.DataFrame(
        [(row_id, *record) for row_id, record in zip(ids, records)],
        columns=list(RESULT_COLUMNS), index=table.index)
    moves = None
    if motions:
        ran = [(ids[i], run) for i, run in zip(todo, runs) if run is not None]
        moves = motions_table([run for _, run in ran],
                              [row_id for row_id, _ in ran],
                              motion_dtype(profile))
        if kept:
            moves = _in_table_order(kept_motions, moves, kept, ids)
    if interrupt is not None:
        raise BatchInterrupted(results, moves) from interrupt
    return results if moves is None else (results, moves)


def _in_table_order(earlier, now, kept, ids):
    """The kept rows' motions from the earlier batch and the others' from
    this one, in table order."""
    import pandas
    earlier = earlier[earlier["id"].isin(kept)]
    moves = pandas.concat([earlier, now], ignore_index=True)
    for column in ("id", "prog", "file"):
        moves[column] = moves[column].astype(object).astype("category")
    position = {row_id: i for i, row_id in enumerate(ids)}
    order = numpy.argsort(moves["id"].map(position).to_numpy(),
                          kind="stable")
    moves = moves.iloc[order].reset_index(drop=True)
    moves["id"] = moves["id"].cat.set_categories(ids)
    return moves


def motion_dtype(profile: Optional[str]) -> numpy.dtype:
    """The motions' row type on a machine of this profile (JSON text)."""
    return _mbc.motion_dtype(_mbc.Context(profile).axes)


def _shared_codes(codes: numpy.ndarray, names: list, counts: numpy.ndarray):
    """One run's program (or file) numbers as numbers into one list of the
    names of all runs: each row's machine numbers them as it meets them."""
    first = names[0] if names else ()
    if all(n == first for n in names):
        return codes, list(first)
    index: dict = {}
    shared = numpy.empty_like(codes)
    start = 0
    for own, count in zip(names, counts):
        table = numpy.array([index.setdefault(n, len(index)) for n in own],
                            dtype=codes.dtype)
        shared[start:start + count] = table[codes[start:start + count]]
        start += count
    return shared, list(index)


def motions_table(runs, ids, dtype: numpy.dtype):
    """The motions of every run as one DataFrame, the run's id first: one
    copy of the rows, then a column each (a DataFrame per row and
    pandas.concat cost 40 times the runs). `dtype`: the rows' type, for a
    table of no runs."""
    import pandas
    from . import MOTION_NAMES
    arrays = [run.motions for run in runs]
    counts = numpy.fromiter((len(a) for a in arrays), dtype=numpy.intp,
                            count=len(arrays))
    rows = _mbc.concatenate(arrays) if arrays else numpy.empty(0, dtype)
    prog, programs = _shared_codes(rows["prog"],
                                   [run.programs for run in runs], counts)
    file, files = _shared_codes(rows["file"], [run.files for run in runs],
                                counts)
    columns = {"id": pandas.Categorical.from_codes(
        numpy.repeat(numpy.arange(len(ids)), counts), ids)}
    for name in rows.dtype.names:
        columns[name] = rows[name]
    columns["motion"] = pandas.Categorical.from_codes(rows["motion"],
                                                      MOTION_NAMES)
    columns["prog"] = pandas.Categorical.from_codes(prog, programs)
    columns["file"] = pandas.Categorical.from_codes(file, files)
    return pandas.DataFrame(columns, copy=False)


def batch(program, table, *, threads: Optional[int] = None,
          motions: bool = False, max_blocks: int = 0,
          machine: Union[None, str, Mapping[str, Any]] = None,
          resume=None):
    """Runs the program once per row of `table` (a pandas DataFrame) on every
    core, as `mbc batch` runs a CSV table: letter columns are G65 arguments
    (R sets #18), `#N` columns preset variables, an `id` column names the
    rows (otherwise they are numbered 1, 2... zero-padded), an empty cell
    (NaN, None) passes nothing. Each row starts from a machine at power-on
    (the program's profile, or `machine`).

    Returns a DataFrame with one row per table row, in table order and with
    the table's index: id, status ("ended", "alarm", "interrupted"),
    blocks, moves, feed_length, rapid_length, cycle_time, alarm (the
    report's first line), alarm_number, alarm_code, dprnt, variables. With
    motions=True returns (results, motions): every row's motions in one
    DataFrame with the row's id in the first column.

    Ctrl-C stops the rows going on and starts no more, and raises
    BatchInterrupted (a KeyboardInterrupt) with the results of every row
    so far (.results, .motions). resume= that exception (or an earlier
    results DataFrame, or (results, motions)) keeps the rows it finished
    ("ended" or "alarm", by id) and runs the others, as `mbc batch
    --resume` does."""
    return run_table(program, table, threads, motions, max_blocks, machine,
                     resume)
