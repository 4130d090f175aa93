"""Every kind of bad input raises tribez.InputError (a ValueError) with a one-line message;
a Rust panic becomes tribez.InternalError, never a PanicException."""

import os
import pathlib
import subprocess
from fractions import Fraction as F

import numpy as np
import pytest

import tribez

FINN_TOML = """degree = 2
[control_points]
"2,0,0" = ["0", "0", "0"]
"1,1,0" = ["1", "0", "2"]
"0,2,0" = ["0", "2", "0"]
"1,0,1" = ["0", "1", "0"]
"0,1,1" = ["1", "1", "1"]
"0,0,2" = ["0", "2", "1"]
"""


def raises(fragment, f, *args, **kwargs):
    with pytest.raises(tribez.InputError) as info:
        f(*args, **kwargs)
    msg = str(info.value)
    assert fragment in msg, msg
    assert "\n" not in msg
    assert isinstance(info.value, ValueError)
    return msg


def test_input_error_is_a_value_error():
    assert issubclass(tribez.InputError, ValueError)
    assert issubclass(tribez.InputError, tribez.TribezError)


def test_bad_files(tmp_path):
    raises("cannot read", tribez.Patch.from_file, tmp_path / "missing.toml")
    (tmp_path / "p.txt").write_text(FINN_TOML)
    raises("unknown file type", tribez.Patch.from_file, tmp_path / "p.txt")
    (tmp_path / "bad.toml").write_text(FINN_TOML.replace('"1", "1", "1"', '"1", "x", "1"'))
    msg = raises('control_points."0,1,1"[1]', tribez.Patch.from_file, tmp_path / "bad.toml")
    assert msg.startswith(str(tmp_path / "bad.toml") + ":7:"), msg
    (tmp_path / "empty.json").write_text("")
    raises("the file is empty", tribez.Patch.from_file, tmp_path / "empty.json")
    raises("path: expected a str or os.PathLike, got int", tribez.Patch.from_file, 123)


def test_bad_text():
    raises("invalid TOML", tribez.Patch.from_toml, "degree = = 2")
    raises("missing key `degree`", tribez.Patch.from_toml, "[control_points]\n")
    raises("<toml>:", tribez.Patch.from_toml, FINN_TOML.replace("degree = 2", "degree = 3"))
    raises("above the limit of 200", tribez.Patch.from_toml, FINN_TOML.replace("degree = 2", "degree = 201"))
    raises("zero denominator", tribez.Patch.from_toml, FINN_TOML.replace('"2", "1"]', '"2", "1/0"]'))
    raises("<json>", tribez.Patch.from_json, "{")
    raises("expected a str", tribez.Patch.from_toml, b"degree = 2")


def test_bad_nodes():
    good = [[0, 1, 0, 0, 1, 0], [0, 0, 2, 1, 1, 2]]
    raises("1-dimensional", tribez.Patch.from_nodes, np.zeros(6))
    raises("rows of different lengths", tribez.Patch.from_nodes, [[0, 1, 2], [0, 1]])
    raises("nodes[1][2]: None is not a number", tribez.Patch.from_nodes, [[0, 1, 2], [0, 1, None]])
    raises("is a bool", tribez.Patch.from_nodes, [[True, 0, 0]])
    raises("NaN has no exact value", tribez.Patch.from_nodes, [[0, float("nan"), 0]])
    raises("infinity has no exact value", tribez.Patch.from_nodes, [[0, np.inf, 0]])
    raises("nodes[0, 1]: `abc`: not a number", tribez.Patch.from_nodes, [["0", "abc", "0"]])
    raises("zero denominator", tribez.Patch.from_nodes, [["0", "1/0", "0"]])
    raises("is the number of no degree", tribez.Patch.from_nodes, [[0, 1, 2, 3, 4]])
    raises("degree 3 on the 2-simplex has 10", tribez.Patch.from_nodes, good, degree=3)
    raises("above the limit of 200", tribez.Patch.from_nodes, good, degree=201)
    raises("degree: expected a non-negative int", tribez.Patch.from_nodes, good, degree=2.0)
    raises("degree: -1 is negative", tribez.Patch.from_nodes, good, degree=-1)
    raises("simplex: 0 is not a simplex dimension", tribez.Patch.from_nodes, good, simplex=0)
    raises("simplex: 17 is not a simplex dimension", tribez.Patch.from_nodes, good, simplex=17)
    raises("no control points", tribez.Patch.from_nodes, [[]])
    raises("no rows", tribez.Patch.from_nodes, [])
    raises("expected a 2-D numpy array or a list of lists", tribez.Patch.from_nodes, "0 1 2")
    raises("3 weights for 6 control points", tribez.Patch.from_nodes, good, weights=[1, 1, 1])
    raises("every weight is zero", tribez.Patch.from_nodes, good, weights=[0] * 6)
    raises("weights[2]: `w`: not a number", tribez.Patch.from_nodes, good, weights=[1, 1, "w", 1, 1, 1])
    # a size the input controls is capped before anything is allocated from it
    raises("above the limit of 250000", tribez.Patch.from_nodes, np.zeros((1, 250_001)))


def test_bad_points(finn, root):
    raises("sum to 3, not 1", finn.evaluate, [[1, 1, 1]])
    raises("has 2 coordinates, expected 3", finn.evaluate, [[1, 0]])
    raises("points[0][1]: `x`: not a number", finn.evaluate, [["1", "x", "0"]])
    raises("points[1]: a row of 2 numbers", finn.evaluate, [[1, 0, 0], [1, 0]])
    # 1/3 as a float is not exactly a third: the sum is not 1
    raises("not 1", finn.evaluate, [[1 / 3, 1 / 3, 1 / 3]])
    s = tribez.Patch.from_file(root / "fixtures" / "beyond" / "pentagon_depth2.toml")
    raises("Cartesian points", s.evaluate, [[0, 0, 0, 0, 1]])
    raises("rows of 2 numbers, expected 3", finn.evaluate_float, np.zeros((4, 2)))
    raises("unknown precision", finn.evaluate_float, np.zeros((4, 3)), precision="f16")
    raises("expected floats", finn.evaluate_float, np.array([["1", "0", "0"]]))
    if np.dtype(np.longdouble).itemsize > 8:
        raises("not f64 or f32", finn.evaluate_float, np.zeros((1, 3), dtype=np.longdouble))


def test_parse_number_errors():
    raises("not a number", tribez.parse_number, "1..2")
    raises("exponent magnitude above 100000", tribez.parse_number, "1e100001")
    raises("is not a number", tribez.parse_number, object())


def test_panics_become_exceptions():
    with pytest.raises(tribez.InternalError, match="boom"):
        tribez._native._panic_for_test("boom")
    # in a worker thread of the parallel engine, with the GIL released
    with pytest.raises(tribez.InternalError, match="worker 37"):
        tribez._native._panic_in_worker_for_test()
    assert issubclass(tribez.InternalError, Exception)


CLI = os.environ.get("TRIBEZ_CLI")


@pytest.mark.skipif(not CLI, reason="TRIBEZ_CLI (the tribez binary) not set; .ci/run sets it")
def test_same_message_as_the_command_line(tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text(FINN_TOML.replace('"1", "1", "1"', '"1", "x", "1"'))
    with pytest.raises(tribez.InputError) as info:
        tribez.Patch.from_file(bad)
    out = subprocess.run([CLI, "eval", str(bad), "--at", "1/2,1/3,1/6"], capture_output=True, text=True)
    assert out.returncode == 2
    assert out.stderr.strip() == f"tribez: {info.value}"


def finn_rows(n=4):
    finn = tribez.Patch.from_toml(FINN_TOML)
    pts = np.array([[0.5, 0.25, 0.25], [0.1, 0.2, 0.7], [0.3, 0.3, 0.4], [1.0, 0.0, 0.0]])[:n]
    return finn, pts, finn.evaluate_float(pts)


def test_bad_check_arguments():
    finn, pts, vals = finn_rows()
    raises("first_row: -1 is negative", tribez.check, finn, pts, vals, first_row=-1)
    raises("tolerance: expected a str", tribez.check, finn, pts, vals, tolerance=3)
    raises("tolerance: tolerance `cond=x`: `x`: not a number", tribez.check, finn, pts, vals, tolerance="cond=x")
    raises("must not be negative", tribez.check, finn, pts, vals, tolerance="ulps=-1")
    raises("unknown algorithm `horner`", tribez.check, finn, pts, vals, algorithm="horner")
    raises("points: rows of 3 numbers, expected 2", tribez.check, finn, pts, vals, cartesian=True)
    rational = tribez.Patch.from_nodes([[0, 1, 0, 0, 1, 0]], weights=[1, 2, 1, 1, 1, 1])
    raises("this is a rational patch; check judges polynomial", tribez.check, rational, pts, vals[:, :1])
    # a control point beyond the f32 range, with f32 results
    big = tribez.Patch.from_nodes([[0, 1e300, 0, 0, 1, 0]])
    raises("a control point of the patch overflows f32", tribez.check, big, pts.astype(np.float32),
           vals[:, :1].astype(np.float32))


def test_bad_merges():
    finn, pts, vals = finn_rows()
    a = tribez.check(finn, pts[:2], vals[:2], tolerance="ulps=1")
    b = tribez.check(finn, pts[2:], vals[2:], tolerance="ulps=1", first_row=2)
    assert a.merge(b).passed + a.merge(b).failed == 4
    raises("merge: reports judged with different tolerances (ulps=1 vs ulps=2)", a.merge,
           tribez.check(finn, pts[2:], vals[2:], tolerance="ulps=2", first_row=2))
    raises("merge: reports judged with different precisions (f64 vs f32)", a.merge,
           tribez.check(finn, pts[2:].astype(np.float32), vals[2:].astype(np.float32), tolerance="ulps=1",
                        first_row=2))
    # the same rows twice (a forgotten first_row)
    raises("merge: both reports have row 0", a.merge, a)
    raises("merge: both reports have row 0", a.merge, tribez.check(finn, pts[2:], vals[2:], tolerance="ulps=1"))
    # another patch of the same (missing) name, and another algorithm
    other = tribez.Patch.from_nodes([[0, 1, 0, 0, 1, 0], [0, 0, 2, 1, 1, 2], [0, 2, 0, 0, 1, 2]])
    raises("merge: reports judged differently", a.merge,
           tribez.check(other, pts[2:], vals[2:], tolerance="ulps=1", first_row=2))
    raises("merge: reports judged differently", a.merge,
           tribez.check(finn, pts[2:], vals[2:], tolerance="ulps=1", first_row=2, algorithm="bernstein"))
    raises("merge: expected a report of tribez.check, got str", a.merge, "report")
    # issue 35 §8: a claims report was a TypeError naming the native classes
    claims = tribez.check_claims(pathlib.Path(__file__).parents[2] / "fixtures" / "finn_day30.claims.toml")
    msg = raises("merge: expected a report of tribez.check, got ClaimsReport", a.merge, claims)
    assert "Native" not in msg
    raises("ClaimsReports do not merge", claims.merge, a)


def test_first_row_near_the_largest_row_index():
    # issue 35 §8: first_row = 2^64 - 10 wrapped the row indices (the worst row came out as
    # row 5); rows are int64 in the report, so the last row index is at most 2^63 - 1
    finn, pts, vals = finn_rows()
    raises("first_row: 18446744073709551606 + 4 rows passes the largest row index 2^63 - 1",
           tribez.check, finn, pts, vals, first_row=2**64 - 10)
    raises("passes the largest row index", tribez.check, finn, pts, vals, first_row=2**63 - 3)
    # the last allowed start: rows 2^63 - 4 ... 2^63 - 1
    r = tribez.check(finn, pts, vals, tolerance="ulps=1", first_row=2**63 - 4)
    assert r.passed == 4
    assert list(r.rows["row"]) == [2**63 - 4, 2**63 - 3, 2**63 - 2, 2**63 - 1]


def test_long_numbers_are_read_or_refused_with_tribez_message():
    # issue 35 §8: Fraction(1, 10**5000) hit Python's 4,300-digit limit of int -> str (a bare
    # ValueError); it is a valid number of 5,002 digits, far below tribez's 100,000
    tiny = F(1, 10**5000)
    p = tribez.Patch.from_nodes([[0, tiny, 0]], simplex=1)
    assert p.evaluate([F(1, 2), F(1, 2)]) == [(tiny / 2,)]
    assert p.nodes[0][1] == tiny
    # 10**5000 + 1 as an int too (a numerator alone)
    big = 10**5000 + 1
    q = tribez.Patch.from_nodes([[big, 0]], simplex=1)
    assert q.evaluate([F(1, 2), F(1, 2)]) == [(F(big, 2),)]
    # beyond tribez's own limit: an InputError with the library's wording
    raises("100001 digits, above the limit of 100000 digits for a number",
           tribez.Patch.from_nodes, [[0, 10**100000, 0]], simplex=1)
    raises("above the limit of 100000 digits for a number",
           tribez.Patch.from_nodes, [[0, F(1, 10**99999 * 7), 0]], simplex=1)
    raises("above the limit of 100000 digits for a number",
           tribez.Patch.from_nodes, [[0, 1 << 10**7, 0]], simplex=1)


def test_huge_ints_for_sizes_are_input_errors():
    # issue 35 §8: from_nodes(degree=10**30) was an OverflowError from the native layer
    nodes = [[0, 1, 0, 0, 1, 0]]
    raises("degree: 1000000000000000000000000000000 is above the limit of 200",
           tribez.Patch.from_nodes, nodes, degree=10**30)
    raises("simplex: 1000000000000000000000000000000 is not a simplex dimension from 1 to 16",
           tribez.Patch.from_nodes, nodes, simplex=10**30)
    finn = tribez.Patch.from_toml(FINN_TOML)
    raises("random: 1000000000000000000000000000000: expected a whole number from 1 to 1000000",
           tribez.certify, finn, random=10**30)
    raises("seed: 18446744073709551616 is above the limit of 2^64 - 1", tribez.certify, finn, seed=2**64)


def test_help_explains_the_tolerances():
    doc = tribez.check.__doc__
    for t in ("exact", "ulps=N", "abs=E", "rel=E", "correctly_rounded", "faithful", "cond=K", "bound"):
        assert t in doc, t
    import io
    import contextlib

    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        help(tribez.check)
    assert "correctly_rounded   y is the float nearest q" in out.getvalue()


def test_certify_random_points_of_a_huge_polygon():
    # issue 35 §3: the centroid of random points overflowed f64 and the library panicked
    huge = tribez.Patch.from_toml(
        'degree = 1\npolygon = [["0", "0"], ["1.7e308", "0"], ["1.7e308", "1.7e308"]]\n'
        '[control_points]\n"1,0,0" = ["0"]\n"0,1,0" = ["1"]\n"0,0,1" = ["2"]\n',
        name="huge_spatch.toml")
    raises("polygon: its coordinates are too large for random points", tribez.certify, huge, random=20)
