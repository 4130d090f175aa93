"""tribez.check and tribez.Report: verdicts, figures, merge, text and JSON, errors.

Expected values come from tests/reference.py (plain Python fractions), never from tribez.
"""

import json
import math
import os
import subprocess
import threading
from fractions import Fraction as F

import numpy as np
import pytest

import tribez
from reference import bernstein_value, ulp, ulps_error

FINN = [[0, 1, 0, 0, 1, 0], [0, 0, 2, 1, 1, 2], [0, 2, 0, 0, 1, 1]]


def points(count, seed=5):
    rng = np.random.default_rng(seed)
    u = rng.random(count)
    v = (1 - u) * rng.random(count)
    return np.column_stack([u, v, 1.0 - u - v])


def correctly_rounded(pts):
    return np.array([[float(q) for q in bernstein_value(FINN, 2, p)] for p in pts.tolist()])


@pytest.fixture
def rows():
    pts = points(300)
    vals = correctly_rounded(pts)
    # rows 7, 100 and 250 off by 1, 3 and 40 ulps in one coordinate
    for r, c, k in ((7, 0, 1), (100, 2, 3), (250, 1, 40)):
        for _ in range(k):
            vals[r, c] = math.nextafter(vals[r, c], math.inf)
    return pts, vals


def reference_ulps(pts, vals):
    return [max(ulps_error(y, q) for y, q in zip(v, bernstein_value(FINN, 2, p)))
            for p, v in zip(pts.tolist(), vals.tolist())]


def test_verdicts_and_figures_match_the_fractions_reference(finn, rows):
    pts, vals = rows
    errs = reference_ulps(pts, vals)
    for tol, limit in (("correctly_rounded", None), ("ulps=2", 2), ("ulps=50", 50)):
        report = tribez.check(finn, pts, vals, tolerance=tol)
        if limit is None:
            want_failed = sum(e > F(1, 2) for e in errs)  # correctly rounded <=> error <= 1/2 ulp here
        else:
            want_failed = sum(e > limit for e in errs)
        assert (report.passed, report.failed) == (300 - want_failed, want_failed), tol
        assert report.ok == (want_failed == 0)
        assert report.worst["row"] == 250
        assert report.max_ulps == pytest.approx(float(max(errs)), rel=1e-9)
    assert tribez.check(finn, pts, vals, tolerance="ulps=50").ok


def test_precision_follows_the_dtype(finn):
    pts = points(50).astype(np.float32)
    vals = finn.evaluate_float(pts, precision="f32")
    report = tribez.check(finn, pts, vals, tolerance="cond=9")
    assert report.precision == "f32" and report.ok
    assert "f32" in str(report)
    report64 = tribez.check(finn, pts.astype(np.float64), vals.astype(np.float64), tolerance="cond=9")
    assert report64.precision == "f64"
    # f32 results are 2^29 f64 ulps off: far beyond cond=9 in f64
    assert not report64.ok


def test_text_and_json_are_the_command_lines(finn, rows, tmp_path):
    pts, vals = rows
    report = tribez.check(finn, pts, vals, tolerance="ulps=2")
    text = str(report)
    assert "passed 298, failed 2" in text
    data = json.loads(report.to_json())
    assert data["summary"]["passed"] == 298 and data["summary"]["failed"] == 2
    cli = os.environ.get("TRIBEZ_CLI")
    if not cli:
        pytest.skip("TRIBEZ_CLI not set")
    patch = tmp_path / "finn.toml"
    patch.write_text(finn.to_toml())
    csv = tmp_path / "rows.csv"
    csv.write_text("".join(",".join(x.hex() for x in r) + "\n" for r in np.hstack([pts, vals]).tolist()))
    out = subprocess.run([cli, "check", "--patch", str(patch), "--results", str(csv), "--precision", "f64",
                          "--tolerance", "ulps=2"], capture_output=True, text=True)
    assert out.returncode == 1
    # the same report: counts, histogram and worst row; the CLI numbers file lines from 1
    assert out.stdout.strip().splitlines()[-1] == text.strip().splitlines()[-1]
    hist = lambda t: [l for l in t.splitlines() if " ulp " in l and "#" in l or l.strip().endswith(" 0")]
    assert hist(out.stdout) == hist(text)


def test_merge_equals_a_single_run(finn, rows):
    pts, vals = rows
    whole = tribez.check(finn, pts, vals, tolerance="ulps=2")
    parts = [(0, 120), (120, 240), (240, 300)]
    reports = [tribez.check(finn, pts[a:b], vals[a:b], tolerance="ulps=2", first_row=a) for a, b in parts]
    merged = reports[0].merge(reports[1]).merge(reports[2])
    assert (merged.passed, merged.failed, merged.fell_back) == (whole.passed, whole.failed, whole.fell_back)
    assert merged.histogram == whole.histogram
    assert merged.max_ulps == whole.max_ulps and merged.worst == whole.worst
    assert json.loads(merged.to_json()) == json.loads(whole.to_json())
    assert str(merged) == str(whole)
    for name in ("row", "passed", "ulps_seen", "ulps_intended", "correctly_rounded", "fell_back"):
        assert np.array_equal(merged.rows[name], whole.rows[name])
    # in another order too
    again = reports[2].merge(reports[0]).merge(reports[1])
    assert json.loads(again.to_json()) == json.loads(whole.to_json())


def test_rows_are_numpy_arrays(finn, rows):
    pts, vals = rows
    report = tribez.check(finn, pts, vals, tolerance="ulps=2")
    r = report.rows
    assert set(r) == {"row", "passed", "ulps_seen", "ulps_intended", "correctly_rounded", "fell_back"}
    assert r["passed"].dtype == bool and r["passed"].shape == (300,)
    assert r["ulps_seen"].dtype == np.float64 and r["row"].dtype == np.int64
    assert list(r["row"]) == list(range(300))
    assert list(np.flatnonzero(~r["passed"])) == [100, 250]
    errs = reference_ulps(pts, vals)
    assert np.allclose(r["ulps_seen"], [float(e) for e in errs], rtol=1e-6, atol=1e-6)
    # f64 floats in, integer control points: the inputs as intended are those as seen
    assert np.array_equal(r["ulps_intended"], r["ulps_seen"])
    # the values are correctly rounded (by the fractions reference) except rows 7, 100, 250
    assert list(np.flatnonzero(~r["correctly_rounded"])) == [7, 100, 250]
    assert r["fell_back"].sum() == report.fell_back
    with pytest.raises(ValueError):
        r["passed"][0] = False  # read-only


def ulps_f32(y, q):
    return abs(F(y) - q) / ulp(q, mant_bits=24, emin=-126)


def test_rows_f32_errors_at_the_inputs_as_seen_and_as_intended(finn):
    # a float32 kernel given float32(points): seen = the f32 points, intended = the f64 points
    pts = points(40, seed=21)
    vals = finn.evaluate_float(pts.astype(np.float32), precision="f32")
    report = tribez.check(finn, pts, vals, tolerance="ulps=4")
    assert report.precision == "f32"
    r = report.rows
    seen = [max(ulps_f32(y, q) for y, q in zip(v, bernstein_value(FINN, 2, p)))
            for p, v in zip(pts.astype(np.float32).tolist(), vals.tolist())]
    intended = [max(ulps_f32(y, q) for y, q in zip(v, bernstein_value(FINN, 2, p)))
                for p, v in zip(pts.tolist(), vals.tolist())]
    assert np.allclose(r["ulps_seen"], [float(e) for e in seen], rtol=1e-6, atol=1e-6)
    assert np.allclose(r["ulps_intended"], [float(e) for e in intended], rtol=1e-12, atol=0)
    assert intended != seen


def test_rows_errors_at_an_exact_control_net():
    # a control point 1/3 is not a float: seen, the net rounded to f64; intended, exactly 1/3
    nodes = [[0, F(1, 3), 1, F(2, 3), 1, 2]]
    exact_patch = tribez.Patch.from_nodes(nodes)
    rounded = [[F(float(x)) for x in nodes[0]]]
    pts = points(30, seed=8)
    vals = exact_patch.evaluate_float(pts)
    r = tribez.check(exact_patch, pts, vals, tolerance="cond=9").rows
    seen = [ulps_error(v[0], bernstein_value(rounded, 2, p)[0]) for p, v in zip(pts.tolist(), vals.tolist())]
    intended = [ulps_error(v[0], bernstein_value(nodes, 2, p)[0]) for p, v in zip(pts.tolist(), vals.tolist())]
    assert np.allclose(r["ulps_seen"], [float(e) for e in seen], rtol=1e-6, atol=1e-6)
    assert np.allclose(r["ulps_intended"], [float(e) for e in intended], rtol=1e-12, atol=0)
    assert intended != seen


def test_correctly_rounded_at_a_tie_is_ties_to_even():
    # a line from 1 to 1 + 2^-52 at (1/2, 1/2): exactly 1 + 2^-53, the midpoint of two doubles;
    # both are 1/2 ulp off, only 1.0 (even significand) is the correctly rounded one
    line = tribez.Patch.from_nodes([[1, 1 + 2.0**-52]], simplex=1)
    assert line.evaluate([["1/2", "1/2"]]) == [(1 + F(1, 2**53),)]
    pts = np.array([[0.5, 0.5]] * 3)
    vals = np.array([[1.0], [1 + 2.0**-52], [1 + 2.0**-51]])
    report = tribez.check(line, pts, vals, tolerance="correctly_rounded")
    r = report.rows
    assert list(r["ulps_seen"]) == [0.5, 0.5, 1.5]
    assert list(r["correctly_rounded"]) == [True, False, False]
    assert list(r["passed"]) == [True, False, False]


def test_rows_survive_merge_and_pickle(finn):
    import pickle

    pts = points(200, seed=31)
    vals = finn.evaluate_float(pts.astype(np.float32), precision="f32")
    whole = tribez.check(finn, pts, vals, tolerance="ulps=4")

    def parts(read_rows):
        a = tribez.check(finn, pts[:90], vals[:90], tolerance="ulps=4")
        b = tribez.check(finn, pts[90:], vals[90:], tolerance="ulps=4", first_row=90)
        if read_rows:  # the errors at the intended inputs computed where the rows are
            a.rows, b.rows
        return a, b

    for a, b in (parts(True),):
        for merged in (b.merge(a), pickle.loads(pickle.dumps(a)).merge(pickle.loads(pickle.dumps(b)))):
            for name, arr in whole.rows.items():
                assert np.array_equal(merged.rows[name], arr), name
    # merged or pickled before the rows were read: everything but the errors at intended inputs
    # that differ from those seen (here: points that are not floats of f32), which are unknown
    a, b = parts(False)
    differ = (pts.astype(np.float32).astype(np.float64) != pts).any(axis=1)
    assert differ.sum() > 100
    for merged in (b.merge(a), pickle.loads(pickle.dumps(a)).merge(pickle.loads(pickle.dumps(b)))):
        rows = merged.rows
        for name, arr in whole.rows.items():
            if name != "ulps_intended":
                assert np.array_equal(rows[name], arr), name
        assert np.isnan(rows["ulps_intended"][differ]).all()
        assert np.array_equal(rows["ulps_intended"][~differ], whole.rows["ulps_intended"][~differ])


def test_failures_raise(finn, rows):
    from tribez.testing import assert_certified

    pts, vals = rows
    assert_certified(finn, pts, vals, tolerance="ulps=50")
    with pytest.raises(AssertionError) as info:
        assert_certified(finn, pts, vals, tolerance="ulps=2")
    assert "failed 2" in str(info.value)


def test_nan_is_a_failed_row_not_an_error(finn):
    pts = points(10)
    vals = correctly_rounded(pts)
    vals[3, 1] = np.nan
    report = tribez.check(finn, pts, vals, tolerance="ulps=1")
    assert (report.passed, report.failed) == (9, 1)


def test_bad_check_input(finn):
    pts = points(10)
    vals = correctly_rounded(pts)

    def bad(fragment, *a, **k):
        with pytest.raises(tribez.InputError) as info:
            tribez.check(*a, **k)
        assert fragment in str(info.value), str(info.value)

    bad("unknown tolerance", finn, pts, vals, tolerance="ulp=1")
    bad("10 rows of points but 9 rows of values", finn, pts, vals[:9])
    bad("values: rows of 2 numbers, expected 3", finn, pts, vals[:, :2])
    bad("points: rows of 2 numbers, expected 3", finn, pts[:, :2], vals)
    bad("unknown precision", finn, pts, vals, precision="f16")
    bad("expected floats", finn, pts, vals.astype(object))
    bad("no rows", finn, pts[:0], vals[:0])
    bad("expected a tribez.Patch", "finn.toml", pts, vals)


def test_the_gil_is_released_while_judging(finn):
    pts = points(200_000, seed=9)
    vals = finn.evaluate_float(pts)
    done = threading.Event()
    result = []

    def work():
        result.append(tribez.check(finn, pts, vals, tolerance="cond=9"))
        done.set()

    t = threading.Thread(target=work)
    ticks = 0
    t.start()
    while not done.is_set():
        ticks += 1
    t.join()
    assert result[0].passed + result[0].failed == 200_000
    # with the GIL held for the whole judgement this loop could not have run meanwhile
    assert ticks > 1000


def test_cartesian_points(finn):
    # (x, y) in the reference triangle is the barycentric point (x, y, 1 - x - y), exactly
    pts = points(40, seed=17)[:, :2]
    vals = np.array([[float(q) for q in bernstein_value(FINN, 2, [F(x), F(y), 1 - F(x) - F(y)])]
                     for x, y in pts.tolist()])
    report = tribez.check(finn, pts, vals, tolerance="correctly_rounded", cartesian=True)
    assert (report.passed, report.failed) == (40, 0)
    assert report.rows["correctly_rounded"].all()
    vals[5, 2] = math.nextafter(vals[5, 2], -math.inf)
    report = tribez.check(finn, pts, vals, tolerance="correctly_rounded", cartesian=True)
    assert (report.passed, report.failed, report.worst["row"]) == (39, 1, 5)
