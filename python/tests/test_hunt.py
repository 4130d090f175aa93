"""tribez.hunt: the library's hunt (what `tribez hunt` runs) with a Python function as the target.

The targets here compute their answers with plain Python fractions (tests/reference.py), so the
expected verdicts are known by construction: a correctly rounded target breaks no tolerance, and
a target with a fault planted in a region breaks it there and only there.
"""

import json
import math
import os
import pathlib
import subprocess
import sys
import textwrap
from fractions import Fraction as F

import numpy as np
import pytest

import tribez
from reference import bernstein_value, ulp, ulps_error

CLI = os.environ.get("TRIBEZ_CLI")
ROOT = pathlib.Path(__file__).resolve().parents[2]
FINN = ROOT / "fixtures" / "finn_day30.toml"

# A cubic triangle in R^2 (bezier's layout: one column per control point, canonical order 300 210
# 120 030 201 111 021 102 012 003). Its control points are floats, so that the values the judge
# takes (at the control points rounded to the precision, as tribez.check) are those of the exact
# patch; one coordinate changes sign inside the triangle.
CUBIC = [
    ["0", "3/8", "5/8", "1", "1/8", "1/2", "7/8", "1/4", "9/16", "3/8"],
    ["0", "-1/8", "1/8", "0", "5/16", "3/8", "5/16", "11/16", "3/4", "1"],
]


def cubic():
    return tribez.Patch.from_nodes(CUBIC)


def exact_rows(nodes, degree, points):
    """The exact values at the rows as given (the homogeneous form at the floats)."""
    return [bernstein_value(nodes, degree, [F(x) for x in row]) for row in points.tolist()]


def correctly_rounded_f64(nodes, degree):
    def fn(points):
        assert points.dtype == np.float64
        return np.array([[float(q) for q in v] for v in exact_rows(nodes, degree, points)])
    return fn


def nearest_f32(q):
    """The float32 nearest q (ties to even), by comparing the candidates exactly."""
    x = np.float32(float(q))
    cands = {x, np.nextafter(x, np.float32(np.inf)), np.nextafter(x, np.float32(-np.inf))}
    best = min(cands, key=lambda c: (abs(F(float(c)) - q), int(np.frombuffer(c.tobytes(), np.uint32)[0]) & 1))
    return best


def steps(x, k):
    """x moved up by k floats (float64)."""
    for _ in range(k):
        x = math.nextafter(x, math.inf)
    return x


# -- correctness of the verdicts --------------------------------------------------------------


def test_a_correctly_rounded_target_breaks_nothing():
    nodes = [[F(c) for c in row] for row in CUBIC]
    report = tribez.hunt(cubic(), correctly_rounded_f64(nodes, 3), tolerance="correctly_rounded",
                         budget=600, seed=7)
    assert (report.evaluated, report.broke, report.ok) == (600, 0, True)
    assert sum(report.by_kind.values()) == 600
    assert len(report.worst) == 10
    # the worst rows: their exact values and errors, recomputed with fractions
    for r in report.worst:
        assert r.passed and r.reason is None
        assert list(r.exact) == bernstein_value(nodes, 3, r.input)
        assert r.claimed == tuple(float(q) for q in r.exact)
        want = max(ulps_error(y, q) for y, q in zip(r.claimed, r.exact))
        assert want <= F(1, 2)
        assert r.ulps == pytest.approx(float(want), rel=1e-12, abs=1e-300)
    assert [r.ulps for r in report.worst] == sorted((r.ulps for r in report.worst), reverse=True)
    assert report.max_ulps == report.worst[0].ulps


def faulty_f64(nodes, degree, region, moved=16):
    """Correctly rounded, but `moved` floats up in every coordinate where `region(row)` holds."""
    def fn(points):
        out = []
        for row, v in zip(points.tolist(), exact_rows(nodes, degree, points)):
            y = [float(q) for q in v]
            if region(row):
                y = [steps(x, moved) for x in y]
            out.append(y)
        return np.array(out)
    return fn


def near_corner_0(row):
    return row[0] > 1 - 2.0**-10


def test_a_planted_fault_is_found_where_it_was_planted():
    nodes = [[F(c) for c in row] for row in CUBIC]
    report = tribez.hunt(cubic(), faulty_f64(nodes, 3, near_corner_0), tolerance="ulps=4",
                         budget=2000, seed=3)
    assert not report.ok and report.broke > 0
    worst = report.worst[0]
    assert near_corner_0(worst.input) and not worst.passed
    assert "ulps=4" in worst.reason or "ulp" in worst.reason
    # 16 floats up from the nearest float: between 8 and 32 ulps of the exact value's binade, so the
    # independent error is what the report says
    want = max(ulps_error(y, q) for y, q in zip(worst.claimed, worst.exact))
    assert 8 < want < 33
    assert worst.ulps == pytest.approx(float(want), rel=1e-12)
    for r in report.worst:
        # every row that breaks the tolerance is in the region; the others are within 1/2 ulp
        assert r.passed == (not near_corner_0(r.input))


def test_an_exception_of_the_function_propagates_at_once():
    class Boom(Exception):
        pass

    calls = []
    raised = Boom("second call")

    def fn(points):
        calls.append(len(points))
        if len(calls) == 2:
            raise raised
        return np.zeros((len(points), 2))

    with pytest.raises(Boom) as info:
        tribez.hunt(cubic(), fn, budget=10_000, batch=100, seed=1)
    assert info.value is raised
    assert calls == [100, 100]


@pytest.mark.parametrize("answer, message", [
    (lambda p: np.zeros((len(p), 3)), r"fn: its answer for rows 1 to 100 has shape \(100, 3\), expected \(100, 2\)"),
    (lambda p: np.zeros((len(p) - 1, 2)), r"rows 1 to 100 has shape \(99, 2\), expected \(100, 2\)"),
    (lambda p: np.zeros(2 * len(p)), r"has shape \(200,\), expected \(100, 2\)"),
    (lambda p: np.zeros((len(p), 2), dtype=np.int64), r"rows 1 to 100 has dtype int64, expected float64 or float32"),
    (lambda p: [["a", "b"]] * len(p), r"has dtype <U1, expected float64 or float32"),
    (lambda p: None, r"has dtype object, expected float64 or float32"),
    (lambda p: [[0.0, 0.0], [0.0]], r"rows 1 to 100 is not an array of numbers"),
])
def test_a_wrong_answer_is_an_input_error_naming_the_rows(answer, message):
    with pytest.raises(tribez.InputError, match=message):
        tribez.hunt(cubic(), answer, budget=1000, batch=100, seed=1)


def test_a_wrong_answer_later_names_its_rows():
    calls = []

    def fn(points):
        calls.append(len(points))
        return np.zeros((len(points), 2 if len(calls) < 3 else 1))

    with pytest.raises(tribez.InputError, match=r"rows 201 to 300 has shape \(100, 1\)"):
        tribez.hunt(cubic(), fn, budget=1000, batch=100, seed=1)


def test_bad_options():
    fn = lambda p: np.zeros((len(p), 2))  # noqa: E731
    p = cubic()
    with pytest.raises(tribez.InputError, match=r"budget: 0: expected a whole number from 1 to 1099511627776"):
        tribez.hunt(p, fn, budget=0)
    with pytest.raises(tribez.InputError, match=r"batch: 0: expected a whole number from 1 to 1048576"):
        tribez.hunt(p, fn, batch=0)
    with pytest.raises(tribez.InputError, match=r"top: 10001: expected a whole number from 1 to 10000"):
        tribez.hunt(p, fn, top=10_001)
    with pytest.raises(tribez.InputError, match=r"seed: -1: expected a whole number from 0 to 18446744073709551615"):
        tribez.hunt(p, fn, seed=-1)
    with pytest.raises(tribez.InputError, match="precision: unknown precision `f16`"):
        tribez.hunt(p, fn, precision="f16")
    with pytest.raises(tribez.InputError, match="tolerance: tolerance `cond=x`"):
        tribez.hunt(p, fn, tolerance="cond=x")
    with pytest.raises(tribez.InputError, match="fn: expected a function, got int"):
        tribez.hunt(p, 3)
    rational = tribez.Patch.from_nodes([[0, 1, 0, 0, 1, 0]], weights=[1, 2, 1, 1, 1, 1])
    with pytest.raises(tribez.InputError, match="hunt takes a polynomial Bézier patch"):
        tribez.hunt(rational, fn)


def test_the_same_seed_gives_the_same_report():
    nodes = [[F(c) for c in row] for row in CUBIC]
    fn = faulty_f64(nodes, 3, near_corner_0)
    a = tribez.hunt(cubic(), fn, tolerance="ulps=4", budget=500, seed=11)
    b = tribez.hunt(cubic(), fn, tolerance="ulps=4", budget=500, seed=11)
    assert (a.text(), a.json(), a.worst) == (b.text(), b.json(), b.worst)
    # a seed drawn at random is reported, and repeats the hunt
    c = tribez.hunt(cubic(), fn, tolerance="ulps=4", budget=500)
    assert 0 <= c.seed < 2**64
    assert f"seed={c.seed})" in c.text()
    d = tribez.hunt(cubic(), fn, tolerance="ulps=4", budget=500, seed=c.seed)
    assert (c.text(), c.worst) == (d.text(), d.worst)


def test_the_report_renders():
    nodes = [[F(c) for c in row] for row in CUBIC]
    r = tribez.hunt(cubic(), faulty_f64(nodes, 3, near_corner_0), tolerance="ulps=4", budget=500, seed=5,
                    top=3)
    text = r.text()
    assert text.startswith("tribez.hunt: fn on <patch> (barycentric f64, tolerance ulps=4)\n")
    assert f"500 rows evaluated ({r.by_kind['uniform']} uniform, " in text
    assert "the 3 worst rows:\n" in text
    assert text.endswith('reproduce: tribez.hunt(patch, fn, precision="f64", tolerance="ulps=4", '
                         'budget=500, seed=5, top=3)\n')
    assert str(r) == text
    j = json.loads(r.json())
    assert (j["evaluated"], j["broke"], j["seed"], j["passed"]) == (500, r.broke, 5, r.ok)
    assert [w["row"] for w in j["worst"]] == [w.row for w in r.worst]
    assert [F(x) for x in j["worst"][0]["exact"]] == list(r.worst[0].exact)
    assert [float.fromhex(x) for x in j["worst"][0]["input"]] == list(r.worst[0].input)
    assert repr(r) == f"<tribez.HuntReport evaluated=500 broke={r.broke} max_ulps={r.max_ulps} seed=5>"


def test_a_report_pickles(tmp_path):
    import pickle

    nodes = [[F(c) for c in row] for row in CUBIC]
    r = tribez.hunt(cubic(), faulty_f64(nodes, 3, near_corner_0), tolerance="ulps=4", budget=300, seed=7,
                    top=3)
    back = pickle.loads(pickle.dumps(r))
    assert (back.text(), back.json(), back.worst, back.by_kind) == (r.text(), r.json(), r.worst, r.by_kind)
    assert (back.evaluated, back.broke, back.seed, back.max_ulps) == (r.evaluated, r.broke, r.seed, r.max_ulps)
    # the unpickled report writes the same claim file
    a, b = tmp_path / "a.toml", tmp_path / "b.toml"
    r.to_claims(a)
    back.to_claims(b)
    assert a.read_text() == b.read_text()
    # a broken state is refused with the field named, not a panic
    _, (native, state, _) = back.__reduce__()
    bad = list(state)
    bad[8] = [(1, [1.0, 0.0, 0.0], [0.0, 0.0], ["1/0", "0"], 0.0, True, None)]
    with pytest.raises(tribez.InputError, match="row 1: exact value"):
        native.from_state(tuple(bad))


def test_cartesian_rows():
    nodes = [[F(c) for c in row] for row in CUBIC]
    seen = []

    def fn(points):
        # Cartesian points of the reference triangle (1,0), (0,1), (0,0): lambda = (x, y, 1 - x - y)
        assert points.shape[1] == 2 and points.dtype == np.float64
        seen.append(points.copy())
        out = []
        for x, y in points.tolist():
            lam = [F(x), F(y), 1 - F(x) - F(y)]
            out.append([float(q) for q in bernstein_value(nodes, 3, lam)])
        return np.array(out)

    report = tribez.hunt(cubic(), fn, tolerance="correctly_rounded", cartesian=True, budget=500, seed=2)
    assert report.cartesian and report.ok and report.evaluated == 500
    pts = np.concatenate(seen)
    assert len(pts) == 500
    assert (pts >= 0).all() and (pts.sum(axis=1) <= 1).all()
    w = report.worst[0]
    assert len(w.input) == 2
    lam = [F(w.input[0]), F(w.input[1]), 1 - F(w.input[0]) - F(w.input[1])]
    assert list(w.exact) == bernstein_value(nodes, 3, lam)
    assert "(Cartesian f64, tolerance correctly_rounded)" in report.text()


def test_f32_rows_and_answers():
    nodes = [[F(c) for c in row] for row in CUBIC]
    dtypes = set()

    def right(points):
        dtypes.add(points.dtype)
        return np.array([[nearest_f32(q) for q in v] for v in exact_rows(nodes, 3, points)], dtype=np.float32)

    report = tribez.hunt(cubic(), right, precision="f32", tolerance="correctly_rounded", budget=400, seed=4)
    assert dtypes == {np.dtype(np.float32)}
    assert report.ok and report.precision == "f32"
    for r in report.worst:
        assert all(float(np.float32(x)) == x for x in r.input + r.claimed)

    # one float32 up everywhere: 1/2 to 2 ulps of f32 (never within 1/2 ulp at the exact value's binade
    # unless the binade changes), so it breaks correctly_rounded and holds ulps=4
    def off(points):
        return np.nextafter(right(points), np.float32(np.inf))

    bad = tribez.hunt(cubic(), off, precision="f32", tolerance="correctly_rounded", budget=400, seed=4)
    assert bad.broke > 0
    w = bad.worst[0]
    want = max(abs(F(y) - q) / ulp(q, 24, -126) for y, q in zip(w.claimed, w.exact))
    assert w.ulps == pytest.approx(float(want), rel=1e-9)
    assert tribez.hunt(cubic(), off, precision="f32", tolerance="ulps=4", budget=400, seed=4).ok


# -- claim files ---------------------------------------------------------------------------------


def verdicts_of(claims):
    """{claim id: passed} of a claims report's JSON (`tribez check FILE --format json`)."""
    assert {c["verdict"] for c in claims["claims"]} <= {"passed", "FAILED"}
    return {c["id"]: c["verdict"] == "passed" for c in claims["claims"]}


@pytest.mark.parametrize("from_file", [True, False], ids=["patch-file", "in-memory"])
def test_to_claims_is_judged_again_with_the_same_verdicts(tmp_path, from_file):
    patch = tribez.Patch.from_file(FINN) if from_file else tribez.Patch.from_toml(FINN.read_text())
    nodes = [[F(c) for c in row] for row in patch.nodes]
    # the fault at the corners only: a few rows break the tolerance, the other worst rows hold it
    report = tribez.hunt(patch, faulty_f64(nodes, 2, lambda row: sorted(row) == [0, 0, 1]), tolerance="ulps=4",
                         budget=1500, seed=9, top=12)
    assert 0 < report.broke and any(r.passed for r in report.worst) and any(not r.passed for r in report.worst)
    out = tmp_path / "sub" / "worst.claims.toml"
    out.parent.mkdir()
    report.to_claims(out)
    text = out.read_text()
    if from_file:
        assert f'patch = "{os.path.relpath(FINN, out.parent)}"' in text
    else:
        assert "\n[patch]\n" in text
    assert sorted(os.listdir(out.parent)) == ["worst.claims.toml"]
    want = {f"hunt-row-{r.row}": r.passed for r in report.worst}
    assert verdicts_of(json.loads(tribez.check_claims(out).to_json())) == want
    if CLI:
        res = subprocess.run([CLI, "check", str(out), "--format", "json"], capture_output=True, text=True)
        assert res.returncode == (0 if report.ok else 1), res.stderr
        assert verdicts_of(json.loads(res.stdout)) == want


def at_corner(x, y):
    return (x, y) in ((1, 0), (0, 1), (0, 0))


def test_to_claims_of_an_f32_cartesian_hunt(tmp_path):
    nodes = [[F(c) for c in row] for row in CUBIC]

    def fn(points):
        # Cartesian (x, y) of the reference triangle: lambda = (x, y, 1 - x - y); the float32
        # nearest the value, one float32 up at the corners
        out = []
        for x, y in points.tolist():
            v = [nearest_f32(q) for q in bernstein_value(nodes, 3, [F(x), F(y), 1 - F(x) - F(y)])]
            out.append([np.nextafter(c, np.float32(np.inf)) if at_corner(x, y) else c for c in v])
        return np.array(out, dtype=np.float32)

    report = tribez.hunt(cubic(), fn, precision="f32", tolerance="correctly_rounded", cartesian=True,
                         budget=400, seed=6, top=30)
    assert any(r.passed for r in report.worst) and any(not r.passed for r in report.worst)
    assert all(r.passed == (not at_corner(*r.input)) for r in report.worst)
    out = tmp_path / "f32.claims.toml"
    report.to_claims(out)
    assert 'precision = "f32"' in out.read_text() and "\ncartesian = [" in out.read_text()
    want = {f"hunt-row-{r.row}": r.passed for r in report.worst}
    assert verdicts_of(json.loads(tribez.check_claims(out).to_json())) == want
    if CLI:
        res = subprocess.run([CLI, "check", str(out), "--format", "json"], capture_output=True, text=True)
        assert verdicts_of(json.loads(res.stdout)) == want


# -- the same hunt as the command line's -----------------------------------------------------------

# The target, for the Python hunt and (as a program reading hex floats on standard input) for
# `tribez hunt`: correctly rounded, but 16 floats up near corner 0.
TARGET = textwrap.dedent("""
    import math
    from fractions import Fraction as F

    NODES = [[0, 1, 0, 0, 1, 0], [0, 0, 2, 1, 1, 2], [0, 2, 0, 0, 1, 1]]  # Finn's, bezier's layout
    INDICES = [(2, 0, 0), (1, 1, 0), (0, 2, 0), (1, 0, 1), (0, 1, 1), (0, 0, 2)]

    def answer(lam):
        l = [F(x) for x in lam]
        out = []
        for row in NODES:
            q = sum(c * (2 if max(a) == 1 else 1) * l[0] ** a[0] * l[1] ** a[1] * l[2] ** a[2]
                    for c, a in zip(row, INDICES))
            y = float(q)
            if lam[0] > 1 - 2.0 ** -10:
                for _ in range(16):
                    y = math.nextafter(y, math.inf)
            out.append(y)
        return out
""")

MAIN = textwrap.dedent("""
    import sys
    while True:
        line = sys.stdin.readline()
        if not line:
            break
        y = answer([float.fromhex(t) for t in line.strip().split(",")])
        sys.stdout.write(",".join(x.hex() for x in y) + "\\n")
        sys.stdout.flush()
""")


@pytest.mark.skipif(not CLI, reason="TRIBEZ_CLI (the tribez binary) not set; .ci/run sets it")
def test_the_same_hunt_as_the_command_line(tmp_path):
    script = tmp_path / "target.py"
    script.write_text(TARGET + MAIN)
    space = {}
    exec(TARGET, space)
    answer = space["answer"]

    def target(points):
        return np.array([answer(row) for row in points.tolist()])

    args = ["--tolerance", "ulps=4", "--budget", "1200", "--seed", "21", "--batch", "256", "--top", "5"]
    res = subprocess.run([CLI, "hunt", str(FINN), *args, "--format", "json", "--", sys.executable, str(script)],
                         capture_output=True, text=True)
    assert res.returncode == 1, res.stderr  # some row breaks the tolerance
    cli = json.loads(res.stdout)
    report = tribez.hunt(tribez.Patch.from_file(str(FINN)), target, tolerance="ulps=4", budget=1200, seed=21,
                         batch=256, top=5)
    ours = json.loads(report.json())
    assert ours["program"] == ["target"] and cli["program"] == [sys.executable, str(script)]
    for j in (cli, ours):
        del j["program"], j["reproduce"]
    assert ours == cli
    assert cli["broke"] > 0
    # the text too, but for the first line (the program's name) and the last (the call that repeats it)
    res = subprocess.run([CLI, "hunt", str(FINN), *args, "--", sys.executable, str(script)],
                         capture_output=True, text=True)
    assert res.stdout.splitlines()[1:-1] == report.text().splitlines()[1:-1]


# -- the Python package `bezier` -------------------------------------------------------------------
#
# Measured before these tests were written (docs/python.md, "Example: the package bezier"): the
# rows near the edge w = λ_2 = 0 are not less accurate than those near the other edges. On random
# cubics (control points in [-1, 1]) judged at 100,000 uniform points against cond=1, rows with
# w < 0.06 failed less often than rows with u < 0.06 or v < 0.06 on 3 triangles of 4; hunts on
# cubics with control points in [1, 2] found their worst rows near w = 0 in 3 hunts of 8, near
# v = 0 in 3. So these tests state what holds: every row within cond (K = 9), the worst rows in
# ULPs at near-zeros of a coordinate of the value, and the degree-30 overflow found.


def bezier_triangle(degree, seed, integers=False):
    bezier = pytest.importorskip("bezier")
    rng = np.random.default_rng(seed)
    n = (degree + 1) * (degree + 2) // 2
    nodes = rng.integers(-8, 9, (2, n)).astype(np.float64) if integers else rng.uniform(-1, 1, (2, n))
    return bezier.Triangle(np.asfortranarray(nodes), degree=degree, copy=True, verify=True)


def bezier_target(tri):
    def evaluate_barycentric(points):
        # bezier takes and returns (dimension, rows) Fortran arrays; its rows must sum to 1 only
        # with verify=True (the hunt's rows are floats, which need not)
        return tri.evaluate_barycentric_multi(np.asfortranarray(points), verify=False).T
    return evaluate_barycentric


def cond_ratio_and_smallness(nodes, degree, lam, y):
    """max_i |y_i - q_i| / (eps sum |c_i| B(|lam|)), and min_i |q_i| / sum |c_i| B(|lam|), exactly."""
    exact = bernstein_value(nodes, degree, lam)
    scale = bernstein_value([[abs(F(c)) for c in row] for row in nodes], degree, [abs(F(x)) for x in lam])
    eps = F(1, 2**53)
    ratio = max(abs(F(yi) - q) / (eps * s) if math.isfinite(yi) else math.inf for yi, q, s in zip(y, exact, scale))
    return ratio, min(abs(q) / s for q, s in zip(exact, scale))


def test_bezier_cubic_is_within_cond_and_worst_at_near_zeros():
    tri = bezier_triangle(3, seed=1)
    nodes = tri.nodes.tolist()
    report = tribez.hunt(tribez.Patch.from_nodes(tri.nodes), bezier_target(tri), budget=3000, seed=1)
    # `cond` is judged as cond=K with K = (m + 1)·n = 3·3 = 9 for a cubic triangle (guide §7)
    assert report.ok and report.tolerance == "cond=9"
    for r in report.worst:
        ratio, _ = cond_ratio_and_smallness(nodes, 3, r.input, r.claimed)
        assert ratio <= 9  # the hunt's cond: K = (m + 1) n = 9
    # the worst row in ULPs: far beyond 1 ulp, at a value with a coordinate near zero (relative to
    # the size of the terms), where the relative error of any float evaluation is large
    w = report.worst[0]
    _, small = cond_ratio_and_smallness(nodes, 3, w.input, w.claimed)
    assert w.ulps > 1e6 and small < F(1, 2**20)


def test_bezier_degree_30_overflow_is_found():
    # bezier's compiled evaluate_barycentric computes binomial coefficients in 32-bit integers;
    # from degree 30 on an intermediate product overflows (tests/test_bezier.py)
    ok = bezier_triangle(29, seed=29, integers=True)
    assert tribez.hunt(tribez.Patch.from_nodes(ok.nodes), bezier_target(ok), budget=300, seed=1).ok
    bad = bezier_triangle(30, seed=30, integers=True)
    report = tribez.hunt(tribez.Patch.from_nodes(bad.nodes), bezier_target(bad), budget=300, seed=1, top=3)
    assert not report.ok
    for r in report.worst:
        ratio, _ = cond_ratio_and_smallness(bad.nodes.tolist(), 30, r.input, r.claimed)
        assert not r.passed and ratio > 1e10
