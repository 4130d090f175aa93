"""examples/dask_check.py on a LocalCluster: the merged report of the partitions equals one single
run over all rows (counts, histogram, maximum, worst row, the whole JSON report)."""

import importlib.util
import json
import math
import pathlib

import numpy as np
import pytest

import tribez

distributed = pytest.importorskip("dask.distributed")

EXAMPLE = pathlib.Path(__file__).resolve().parents[1] / "examples" / "dask_check.py"


def load_example():
    spec = importlib.util.spec_from_file_location("dask_check", EXAMPLE)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def test_partitions_on_a_local_cluster_merge_into_the_single_run(finn):
    ex = load_example()
    rng = np.random.default_rng(77)
    u = rng.random(3000)
    v = (1 - u) * rng.random(3000)
    points = np.column_stack([u, v, 1.0 - u - v])
    values = finn.evaluate_float(points)
    for r in (10, 1234, 2999):  # a few rows off by 2**(r % 7) ulps
        values[r, r % 3] += (2 ** (r % 7)) * np.spacing(values[r, r % 3])
    single = tribez.check(finn, points, values, tolerance="ulps=1")
    assert single.failed >= 1
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, distributed.Client(cluster) as client:
        merged = ex.check_on_cluster(client, finn, ex.split(points, values, 5), tolerance="ulps=1")
    assert (merged.passed, merged.failed, merged.fell_back) == (single.passed, single.failed, single.fell_back)
    assert merged.histogram == single.histogram
    assert merged.max_ulps == single.max_ulps
    assert merged.worst == single.worst
    assert json.loads(merged.to_json()) == json.loads(single.to_json())
