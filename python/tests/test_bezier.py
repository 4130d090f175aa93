"""The Python package `bezier` (installed from the registry), evaluated in-process and judged.

Expected verdicts are derived independently: the exact values and errors come from plain Python
fractions (tests/reference.py), never from tribez.
"""

import math
from fractions import Fraction as F

import numpy as np
import pytest

import tribez
from reference import bernstein_value, multi_indices, ulps_error

bezier = pytest.importorskip("bezier")

EPS = F(1, 2**53)


def random_triangle(degree, dim, seed, integers=False):
    rng = np.random.default_rng(seed)
    n = len(multi_indices(2, degree))
    if integers:
        nodes = rng.integers(-8, 9, (dim, n)).astype(np.float64)
    else:
        nodes = rng.uniform(-1, 1, (dim, n))
    return bezier.Triangle(np.asfortranarray(nodes), degree=degree, copy=True, verify=True)


def random_points(count, seed):
    rng = np.random.default_rng(seed)
    u = rng.random(count)
    v = (1 - u) * rng.random(count)
    return np.column_stack([u, v, 1.0 - u - v])


def bezier_values(tri, points):
    # bezier takes and returns (dimension, rows) Fortran arrays
    return tri.evaluate_barycentric_multi(np.asfortranarray(points)).T.copy()


def cond_ratio(nodes, degree, lam, y):
    """max over coordinates of |y - p(lam)| / (eps * sum |c| B(|lam|)), exactly."""
    lam = [F(x) for x in lam]
    exact = bernstein_value(nodes, degree, lam)
    absnodes = [[abs(F(c)) for c in row] for row in nodes]
    scale = bernstein_value(absnodes, degree, [abs(x) for x in lam])
    return max(abs(F(yi) - q) / (EPS * s) if s else (0 if F(yi) == q else math.inf)
               for yi, q, s in zip(y, exact, scale))


def test_bezier_triangle_passes_at_cond_9():
    tri = random_triangle(3, 2, seed=1)
    points = random_points(500, seed=2)
    values = bezier_values(tri, points)
    patch = tribez.Patch.from_nodes(tri.nodes)
    assert (patch.degree, patch.dimension) == (3, 2)
    report = tribez.check(patch, points, values, tolerance="cond=9")
    # the independent verdict: every row within 9 eps sum|c|B(|lam|)
    worst = max(cond_ratio(tri.nodes.tolist(), 3, p, y) for p, y in zip(points.tolist(), values.tolist()))
    assert worst <= 9
    assert (report.passed, report.failed, report.ok) == (500, 0, True)
    report.raise_if_failed()


def test_one_ulp_off_a_correctly_rounded_value_fails():
    tri = random_triangle(3, 2, seed=3)
    points = random_points(200, seed=4)
    values = bezier_values(tri, points)
    nodes = tri.nodes.tolist()
    # keep the rows bezier rounded correctly (by the fractions reference)
    exact = [bernstein_value(nodes, 3, p) for p in points.tolist()]
    cr = [all(float(q) == y for q, y in zip(e, v)) for e, v in zip(exact, values.tolist())]
    points, values = points[cr], values[cr].copy()
    assert len(points) > 20
    patch = tribez.Patch.from_nodes(tri.nodes)
    assert tribez.check(patch, points, values, tolerance="correctly_rounded").ok
    k = len(points) // 2
    values[k, 1] = math.nextafter(values[k, 1], math.inf)
    report = tribez.check(patch, points, values, tolerance="correctly_rounded")
    assert (report.passed, report.failed) == (len(points) - 1, 1)
    assert report.worst["row"] == k
    want = ulps_error(values[k, 1], bernstein_value(nodes, 3, points[k].tolist())[1])
    assert 0.5 < want < 1.5
    assert report.max_ulps == pytest.approx(float(want), rel=1e-9)
    with pytest.raises(tribez.CertificationError) as info:
        report.raise_if_failed()
    assert "1 failed" in str(info.value)


def test_degree_30_binomial_overflow_is_caught():
    # bezier's compiled evaluate_barycentric computes the binomial coefficients in 32-bit
    # integers; from degree 30 on an intermediate product overflows and the values are wrong.
    points = random_points(20, seed=30)
    ok = random_triangle(29, 2, seed=29, integers=True)
    bad = random_triangle(30, 2, seed=30, integers=True)
    for tri, degree in ((ok, 29), (bad, 30)):
        values = bezier_values(tri, points)
        ratios = [cond_ratio(tri.nodes.tolist(), degree, p, y) for p, y in zip(points.tolist(), values.tolist())]
        report = tribez.check(tribez.Patch.from_nodes(tri.nodes), points, values, tolerance="cond=9")
        if degree == 29:
            assert max(ratios) <= 9 and report.ok
        else:
            # the fractions reference: errors of order 1 where sum|c|B is at most 8, far beyond 9 eps
            assert min(ratios) > 1e10
            assert report.failed == len(points) and not report.ok
