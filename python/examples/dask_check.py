"""Check a results set too large for one machine on a Dask cluster, partition by partition, and
merge the partition reports into the report of the whole set.

    python python/examples/dask_check.py [SCHEDULER_ADDRESS] [--rows N] [--partitions P]

Without a scheduler address it starts a LocalCluster (two worker processes); with one, the same
code runs on a real multi-machine cluster (`dask scheduler` / `dask worker ADDRESS` on each
machine, each with `pip install ./python`).

Each partition is judged where it lives: the worker loads (here: makes) its rows and calls
`tribez.check` with `first_row`, the index of its first row in the whole set, so that row
indices in its report (the worst row, the failures) are those of the whole set. Only the small
reports travel back; `Report.merge` combines reports of disjoint row sets into the report of
their union: counts and histograms add, the worst row is the worse of the two (ties: the earlier
row), failures keep the first listed. The merged report equals the report of one single run over
all rows (python/tests/test_dask.py checks it on a small set).
"""

from __future__ import annotations

import argparse
import functools
import sys
from typing import Callable, Sequence, Tuple

import numpy as np

import tribez

# A partition: (first row index, a function that loads its points and values on the worker).
Partition = Tuple[int, Callable[[], Tuple[np.ndarray, np.ndarray]]]


def check_partition(patch: tribez.Patch, first_row: int, load, tolerance: str, precision):
    """Runs on a worker: load the partition's rows and judge them (both cores of the worker)."""
    points, values = load()
    return tribez.check(patch, points, values, tolerance=tolerance, precision=precision,
                        first_row=first_row)


def check_on_cluster(client, patch: tribez.Patch, partitions: Sequence[Partition],
                     tolerance: str = "cond=9", precision=None) -> tribez.Report:
    """Judge every partition on the cluster and merge the reports (in row order)."""
    futures = [
        client.submit(check_partition, patch, first, load, tolerance, precision, pure=False)
        for first, load in partitions
    ]
    reports = client.gather(futures)
    return functools.reduce(tribez.Report.merge, reports)


def split(points: np.ndarray, values: np.ndarray, parts: int) -> list:
    """In-memory partitions of arrays (for a demonstration or a test; a real set would give each
    partition a loader that reads its own file)."""
    bounds = np.linspace(0, len(points), parts + 1).astype(int)
    return [
        (int(a), functools.partial(_slice, points, values, int(a), int(b)))
        for a, b in zip(bounds[:-1], bounds[1:])
    ]


def _slice(points, values, a, b):
    return points[a:b], values[a:b]


def _generated(patch_nodes, first, count, seed):
    """A partition made on the worker: random points, values by tribez's f64 de Casteljau with
    one coordinate of every 1000th row nudged by 64 ulps (so that some rows fail)."""
    patch = tribez.Patch.from_nodes(patch_nodes)
    rng = np.random.default_rng([seed, first])
    u = rng.random(count)
    v = (1 - u) * rng.random(count)
    points = np.column_stack([u, v, 1.0 - u - v])
    values = patch.evaluate_float(points)
    rows = np.arange(first, first + count)
    bad = rows % 1000 == 999
    values[bad, 0] = values[bad, 0] + 64 * np.spacing(values[bad, 0])
    return points, values


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("scheduler", nargs="?", help="scheduler address (default: a LocalCluster)")
    ap.add_argument("--rows", type=int, default=2_000_000)
    ap.add_argument("--partitions", type=int, default=8)
    ap.add_argument("--tolerance", default="cond=9")
    args = ap.parse_args(argv)

    from dask.distributed import Client, LocalCluster

    nodes = [[0, 1, 0, 0, 1, 0], [0, 0, 2, 1, 1, 2], [0, 2, 0, 0, 1, 1]]
    patch = tribez.Patch.from_nodes(nodes)
    bounds = np.linspace(0, args.rows, args.partitions + 1).astype(int)
    partitions = [
        (int(a), functools.partial(_generated, nodes, int(a), int(b - a), 12))
        for a, b in zip(bounds[:-1], bounds[1:])
    ]
    if args.scheduler:
        client = Client(args.scheduler)
    else:
        client = Client(LocalCluster(n_workers=2, threads_per_worker=1, processes=True))
    with client:
        report = check_on_cluster(client, patch, partitions, tolerance=args.tolerance,
                                  precision="f64")
    print(report)
    return 0 if report.ok else 1


if __name__ == "__main__":
    sys.exit(main())
