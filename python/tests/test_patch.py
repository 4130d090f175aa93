"""Patch: construction from files, text and bezier-style nodes; exact and float evaluation."""

from fractions import Fraction as F

import numpy as np
import pytest

import tribez
from reference import bernstein_value, multi_indices

FINN_NODES = [[0, 1, 0, 0, 1, 0], [0, 0, 2, 1, 1, 2], [0, 2, 0, 0, 1, 1]]


def test_worked_example_exactly(finn):
    # Finn's notes, Day 30, example (a): at (1/2, 1/3, 1/6) the point is exactly (4/9, 5/9, 29/36)
    assert finn.evaluate([[F(1, 2), F(1, 3), F(1, 6)]]) == [(F(4, 9), F(5, 9), F(29, 36))]
    # the same point given as strings, and as one flat point
    assert finn.evaluate(["1/2", "1/3", "1/6"]) == [(F(4, 9), F(5, 9), F(29, 36))]
    assert (finn.degree, finn.dimension, finn.simplex, finn.kind) == (2, 3, 2, "bezier")


def test_worked_example_file_equals_nodes(root, finn):
    p = tribez.Patch.from_file(root / "fixtures" / "finn_day30.toml")
    assert p.name == "Finn, day 30, worked example"
    assert p.nodes == [[F(x) for x in row] for row in FINN_NODES]
    assert p.evaluate([["1/2", "1/3", "1/6"]]) == [(F(4, 9), F(5, 9), F(29, 36))]
    # TOML and JSON text round-trip
    assert tribez.Patch.from_toml(finn.to_toml()) == finn
    assert tribez.Patch.from_json(finn.to_json()) == finn


def test_canonical_order_is_beziers():
    # column j is control point multi_indices(2, 2)[j]: 200 110 020 101 011 002
    assert multi_indices(2, 2) == [(2, 0, 0), (1, 1, 0), (0, 2, 0), (1, 0, 1), (0, 1, 1), (0, 0, 2)]
    p = tribez.Patch.from_nodes(FINN_NODES)
    text = p.to_toml()
    for j, a in enumerate(multi_indices(2, 2)):
        key = ",".join(map(str, a))
        want = ", ".join(f'"{FINN_NODES[i][j]}"' for i in range(3))
        assert f'"{key}" = [{want}]' in text


def test_corners_interpolate(finn):
    got = finn.evaluate([[1, 0, 0], [0, 1, 0], [0, 0, 1]])
    assert got == [(0, 0, 0), (0, 2, 0), (0, 2, 1)]


def test_number_kinds_are_exact():
    # ints, floats (the exact double), Fractions and strings (tribez's syntax), numpy scalars
    nodes = [[0, 0.1, F(1, 3), "0.1", np.float32(0.1), np.int64(7)]]
    p = tribez.Patch.from_nodes(nodes)
    assert p.nodes == [[F(0), F(0.1), F(1, 3), F(1, 10), F(float(np.float32(0.1))), F(7)]]
    assert F(0.1) == F(3602879701896397, 36028797018963968)
    assert tribez.parse_number("f64:0.1") == F(0.1)
    assert tribez.parse_number("-1.5e-3") == F(-3, 2000)
    assert tribez.parse_number("0x1.8p-3") == F(3, 16)


def test_degree_inferred_and_other_simplices():
    # a cubic curve (simplex=1) and a quadratic tetrahedron (simplex=3), degree inferred
    curve = tribez.Patch.from_nodes([[0, 1, 3, 4]], simplex=1)
    assert (curve.degree, curve.simplex) == (3, 1)
    t = F(1, 3)
    want = bernstein_value([[0, 1, 3, 4]], 3, [1 - t, t])
    assert curve.evaluate([[1 - t, t]]) == [tuple(want)]
    nodes = [[i * i - 3 for i in range(10)], [F(i, 7) for i in range(10)]]
    tet = tribez.Patch.from_nodes(nodes, simplex=3)
    assert (tet.degree, tet.simplex, tet.dimension) == (2, 3, 2)
    lam = [F(1, 5), F(2, 7), F(1, 11), 1 - F(1, 5) - F(2, 7) - F(1, 11)]
    assert tet.evaluate([lam]) == [tuple(bernstein_value(nodes, 2, lam))]


def test_numpy_nodes_and_explicit_degree():
    rng = np.random.default_rng(12)
    nodes = rng.standard_normal((3, 10))
    p = tribez.Patch.from_nodes(nodes, degree=3)
    assert p.degree == 3
    lam = [F(1, 3), F(1, 4), F(5, 12)]
    assert p.evaluate([lam]) == [tuple(bernstein_value(nodes.tolist(), 3, lam))]


def test_cartesian_points(finn):
    # reference domain (1,0), (0,1), (0,0): (x, y) -> (u, v, w) = (x, y, 1 - x - y)
    assert finn.evaluate([["1/2", "1/3"]], cartesian=True) == finn.evaluate([["1/2", "1/3", "1/6"]])


def test_rational_patch():
    # a quarter circle as a rational quadratic curve: weights 1, 1/sqrt2 ~ exact 1/2 here gives
    # a conic; check against the quotient of two Bernstein sums
    nodes = [[1, 1, 0], [0, 1, 1]]
    w = [1, F(1, 2), 1]
    p = tribez.Patch.from_nodes(nodes, weights=w, simplex=1)
    assert p.kind == "rational" and p.weights == [1, F(1, 2), 1]
    lam = [F(2, 3), F(1, 3)]
    num = bernstein_value([[x * wi for x, wi in zip(row, w)] for row in nodes], 2, lam)
    (den,) = bernstein_value([w], 2, lam)
    assert p.evaluate([lam]) == [tuple(x / den for x in num)]


def test_kinds_from_fixture_files(root):
    beyond = root / "fixtures" / "beyond"
    assert tribez.Patch.from_file(beyond / "octant_quartic.toml").kind == "rational"
    assert tribez.Patch.from_file(beyond / "pentagon_depth2.toml").kind == "s-patch"
    assert tribez.Patch.from_file(beyond / "functional_linear.toml").kind == "functional"


def test_evaluate_float_is_de_casteljau_in_floats(finn):
    pts = np.array([[0.5, 1 / 3, 1 / 6], [0.25, 0.25, 0.5], [0.1, 0.7, 0.2]])
    got = finn.evaluate_float(pts)
    assert got.dtype == np.float64 and got.shape == (3, 3)
    # de Casteljau in f64, in the library's documented operation order
    # ((l0*x0 + l1*x1) + l2*x2) per coordinate, no FMA
    c = {a: np.array([FINN_NODES[i][j] for i in range(3)], dtype=np.float64) for j, a in enumerate(multi_indices(2, 2))}
    for row, want_row in zip(pts, got):
        level = dict(c)
        for n in (2, 1):
            level = {
                a: (row[0] * level[(a[0] + 1, a[1], a[2])] + row[1] * level[(a[0], a[1] + 1, a[2])])
                + row[2] * level[(a[0], a[1], a[2] + 1)]
                for a in multi_indices(2, n - 1)
            }
        assert np.array_equal(level[(0, 0, 0)], want_row)
    f32 = finn.evaluate_float(pts.astype(np.float32), precision="f32")
    assert f32.dtype == np.float32
    assert np.allclose(f32, got, rtol=1e-6)


def test_patch_pickles_exactly(root):
    import pickle

    for f in ["finn_day30.toml", "beyond/octant_quartic.toml", "beyond/pentagon_depth2.toml"]:
        p = tribez.Patch.from_file(root / "fixtures" / f)
        q = pickle.loads(pickle.dumps(p))
        assert q == p and q.name == p.name and q.kind == p.kind
