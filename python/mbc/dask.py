"""mbc.dask: the batch of mbc.batch on a dask.distributed cluster.

    from dask.distributed import Client
    import mbc, mbc.dask
    client = Client("scheduler:8786")          # or LocalCluster()
    pocket = mbc.compile("pocket.nc")
    results = mbc.dask.batch(pocket, table, npartitions=64).compute()
    results, motions = mbc.dask.batch(pocket, table, motions=True)

Each worker process compiles the program once (or loads it from its
compiled-code cache) and runs partitions of the table with mbc.batch;
the results come back in table order, identical to mbc.batch's.
"""
from __future__ import annotations

import json
from typing import Optional

import pandas

from .batch import RESULT_COLUMNS, motion_dtype, motions_table, run_table


def _meta() -> pandas.DataFrame:
    types = {"id": object, "status": object, "blocks": "int64",
             "moves": "int64", "feed_length": "float64",
             "rapid_length": "float64", "cycle_time": "float64",
             "alarm": object, "alarm_number": "int64", "alarm_code": object,
             "dprnt": object, "variables": object}
    return pandas.DataFrame({c: pandas.Series(dtype=types[c])
                             for c in RESULT_COLUMNS})


def _run_partition(part: pandas.DataFrame, program, threads, max_blocks,
                   machine) -> pandas.DataFrame:
    if len(part) == 0:
        return _meta()
    return run_table(program, part, threads, False, max_blocks, machine)


def _run_partition_motions(part: pandas.DataFrame, program, threads,
                           max_blocks, machine, dtype) -> tuple:
    if len(part) == 0:
        return _meta(), motions_table([], [], dtype)
    return run_table(program, part, threads, True, max_blocks, machine)


def batch(program, table, *, npartitions: Optional[int] = None,
          threads: Optional[int] = None, max_blocks: int = 0, machine=None,
          motions: bool = False):
    """mbc.batch on a Dask cluster: `table` is a pandas or dask DataFrame;
    returns a lazy dask DataFrame of the results (the columns of
    mbc.batch, the table's index, table order); .compute() runs it on the
    current dask.distributed Client's workers. Without an id column the rows
    are numbered over the whole table, as mbc.batch numbers them.
    motions=True returns (results, motions): the motions as a lazy dask
    DataFrame, partitioned as the rows (the motions of a partition's rows
    in its partition, the row's id first), each partition run once for
    both.
    npartitions: how a pandas table is split (default: 4 per worker thread
    of the current client, or 1 without one). threads: per worker process
    (default: its cores). machine: a profile (dict or a path the workers
    can read) or a Machine, whose profile is used (each row starts from
    power-on, as in mbc.batch)."""
    import dask.dataframe as dd
    from . import Machine
    if isinstance(machine, Machine):
        # The profile travels, not the machine (whose state is this process's).
        machine = json.loads(machine.profile) if machine.profile else None
    if isinstance(table, pandas.DataFrame):
        if "id" not in table.columns:
            width = len(str(len(table)))
            table = table.assign(id=[str(i + 1).zfill(width)
                                     for i in range(len(table))])
        table = dd.from_pandas(table, npartitions=npartitions or _partitions(),
                               sort=False)
    elif "id" not in table.columns:
        raise ValueError("a dask table needs an id column (rows cannot be "
                         "numbered over partitions cheaply)")
    if not motions:
        return table.map_partitions(_run_partition, program, threads,
                                    max_blocks, machine, meta=_meta())
    import dask
    from . import _profile_text
    dtype = motion_dtype(_profile_text(machine) if machine is not None
                         else program.machine_profile)
    runs = [dask.delayed(_run_partition_motions, nout=2)(
        part, program, threads, max_blocks, machine, dtype)
        for part in table.to_delayed()]
    results = dd.from_delayed([run[0] for run in runs], meta=_meta(),
                              divisions=table.divisions)
    moves = dd.from_delayed([run[1] for run in runs],
                            meta=_motions_meta(dtype))
    return results, moves


def _motions_meta(dtype) -> pandas.DataFrame:
    """The motions' columns; the ids, programs and files are categories
    that differ by partition (each names those of its rows)."""
    from dask.dataframe.utils import UNKNOWN_CATEGORIES
    meta = motions_table([], [], dtype)
    for column in ("id", "prog", "file"):
        meta[column] = pandas.Categorical([], [UNKNOWN_CATEGORIES])
    return meta


def _partitions() -> int:
    try:
        from dask.distributed import get_client
        workers = get_client().nthreads()
        return max(1, 4 * sum(workers.values()))
    except (ImportError, ValueError):
        return 1
