"""tribez.check_locate and tribez.check_ray: another implementation's answers to the inverse
problems, judged by the library's inverse batch checker.

Expected verdicts are derived by hand on patches whose inverse is known: the linear triangle with
nodes (0, 0), (1, 0), (0, 1) is the identity, so the only parameters of a point (x, y) of the
triangle are (s, t) = (x, y) and a point outside has none; the same triangle at z = 0 in R^3 is
hit by the ray from (x, y, h) along (0, 0, -1) at tau = h, (s, t) = (x, y). The peer fixture is
compared with the command line's report on the same rows (both computed when the test runs).
"""

import csv
import json
import math
import os
import pathlib
import pickle
import subprocess
from fractions import Fraction as F

import numpy as np
import pytest

import tribez

CLI = os.environ.get("TRIBEZ_CLI")
ROOT = pathlib.Path(__file__).resolve().parents[2]
PEER = ROOT / "fixtures" / "inverse" / "peer"


@pytest.fixture
def identity():
    return tribez.Patch.from_nodes([[0, 1, 0], [0, 0, 1]])


@pytest.fixture
def flat():
    return tribez.Patch.from_nodes([[0, 1, 0], [0, 0, 1], [0, 0, 0]])


def test_locate_on_the_identity_triangle(identity):
    points = [[F(1, 4), F(1, 2)], [F(1, 4), F(1, 2)], [2, 2], [F(1, 3), F(1, 3)], ["1/8", "0.5"]]
    claimed = [(F(1, 4), F(1, 2)),  # right
               [[F(1, 2), F(1, 4)]],  # swapped: extra, and the solution is missed
               None,  # outside the triangle: no solution, right
               [],  # inside: its solution is missed
               [["1/8", "1/2"], ["1/8", "1/2"]]]  # the solution twice: one is extra
    r = tribez.check_locate(identity, points, claimed)
    assert (r.kind, r.checked, r.passed, r.failed) == ("locate", 5, 2, 3)
    assert (r.missed, r.extra, r.out_of_tolerance) == (2, 2, 0)
    assert not r.ok
    assert [f["row"] for f in r.failures] == [1, 3, 4]
    assert list(r.rows["row"]) == [1, 3, 4]
    assert list(r.rows["missed"]) == [1, 1, 0] and list(r.rows["extra"]) == [1, 0, 1]
    assert r.failures[0]["query"] == ["1/4", "1/2"]
    assert (r.tolerance, r.precision) == ("exact", None)
    with pytest.raises(tribez.CertificationError):
        r.raise_if_failed()
    again = pickle.loads(pickle.dumps(r))
    assert (again.to_json(), str(again), type(again)) == (r.to_json(), str(r), tribez.InverseReport)


def test_locate_floats_are_their_exact_values(identity):
    x, y = 0.1, 0.2  # the identity's solution is the floats themselves, exactly
    up = math.nextafter(x, 1.0)
    pts = np.array([[x, y], [x, y]])
    claimed = np.array([[x, y], [up, y]])  # one pair per row
    r = tribez.check_locate(identity, pts, claimed)
    assert (r.passed, r.failed, r.out_of_tolerance) == (1, 1, 1)
    # one ulp off passes ulps=1 (the exact value is an f64, so the error is exactly 1 ulp)
    r = tribez.check_locate(identity, pts, claimed, tolerance="ulps=1", precision="f64")
    assert (r.passed, r.failed) == (2, 0) and r.ok
    r = tribez.check_locate(identity, pts, claimed, tolerance="ulps=1/2", precision="f64")
    assert (r.passed, r.failed) == (1, 1)
    assert r.max_ulps == 1.0


def test_ray_on_the_flat_triangle(flat):
    rays = [[F(1, 4), F(1, 4), 1, 0, 0, -1],
            [F(1, 4), F(1, 4), 1, 0, 0, -1],
            [5, 5, 1, 0, 0, 1],
            [F(1, 4), F(1, 4), 3, 0, 0, -2]]
    hits = [(1, F(1, 4), F(1, 4)),  # right
            (2, F(1, 4), F(1, 4)),  # wrong tau: extra, and the hit is missed
            None,  # misses, right
            None]  # hits at tau = 3/2: missed
    r = tribez.check_ray(flat, rays, hits)
    assert (r.kind, r.checked, r.passed, r.failed, r.missed, r.extra) == ("ray", 4, 2, 2, 2, 1)
    assert [f["row"] for f in r.failures] == [1, 3]
    assert "tau = 3/2" in str(r)


def test_bad_input_is_an_input_error(identity, flat):
    cases = [
        (lambda: tribez.check_locate(identity, [[0, 0, 0]], [None]), "points: rows of 3 numbers, expected 2"),
        (lambda: tribez.check_locate(identity, [[0, 0]], [None, None]), "1 rows of points but 2 entries of claimed"),
        (lambda: tribez.check_locate(identity, [[0, 0]], [[1, 2, 3]]), "claimed[0]: tuples of 3 numbers, expected 2"),
        (lambda: tribez.check_locate(identity, [[0, 0]], [["1,2", "0"]]), "rows[0][2]: `1,2` is not one number"),
        (lambda: tribez.check_locate(identity, [["#1", 0]], [None]), "rows[0][0]: `#1` is not a number"),
        (lambda: tribez.check_locate(identity, [], []), "points: no rows"),
        (lambda: tribez.check_locate(identity, [[0, 0]], [None], tolerance="cond"), "cond"),
        (lambda: tribez.check_locate(identity, [[0, 0]], [None], precision="f16"), "precision"),
        (lambda: tribez.check_locate(identity, [["x", 0]], [None]), "`x`"),
        (lambda: tribez.check_ray(flat, [[0, 0, 1, 0, 0, -1]], [[[1, 0, 0], [1, 0, 0]]]), "at most 1"),
        (lambda: tribez.check_ray(identity, [[0, 0, 1, 0, 0, -1]], [None]), "points in ℝ^3, not one with m = 2, d = 2"),
        (lambda: tribez.check_ray(flat, [[0, 0, 1, 0, 0, 0]], [None]), "direction"),
    ]
    for call, fragment in cases:
        with pytest.raises(tribez.InputError) as e:
            call()
        assert fragment in str(e.value), (fragment, str(e.value))
        assert "\n" not in str(e.value)


def peer_rows():
    """The peer fixture's rows (bezier's Triangle.locate), read with Python's csv module."""
    lines = [l for l in PEER.joinpath("locate.rows.csv").read_text().splitlines() if not l.startswith("#")]
    rows = list(csv.reader(lines))
    assert rows[0] == ["x", "y", "s", "t"]
    return rows[1:]


@pytest.mark.skipif(not CLI, reason="TRIBEZ_CLI (the tribez binary) not set; .ci/run sets it")
def test_the_peer_fixture_matches_the_command_line():
    rows = peer_rows()
    patch = tribez.Patch.from_file(PEER / "triangle.toml")
    points = [r[:2] for r in rows]
    claimed = [None if r[2:] in ([], ["none"]) else [r[2:]] for r in rows]
    r = tribez.check_locate(patch, points, claimed, tolerance="ulps=16", precision="f64")
    out = subprocess.run([CLI, "check", "--patch", str(PEER / "triangle.toml"), "--locate-results",
                          str(PEER / "locate.rows.csv"), "--precision", "f64", "--tolerance", "ulps=16",
                          "--format", "json"], capture_output=True, text=True)
    assert out.returncode == 1, out.stderr
    cli = json.loads(out.stdout)
    mine = json.loads(r.to_json())
    keys = ["checked", "passed", "failed", "missed", "extra", "out_of_tolerance", "infinite", "not_finite"]
    assert [mine[k] for k in keys] == [cli[k] for k in keys]
    assert (r.checked, r.failed) == (len(rows), 5)
    # the same failures: the file has a comment and a header line before its rows
    assert [f["line"] - 2 for f in cli["failures"]] == [f["line"] for f in mine["failures"]]
    strip = lambda fs: [{k: v for k, v in f.items() if k != "line"} for f in fs]
    assert strip(cli["failures"]) == strip(mine["failures"])


def test_locate_anywhere_takes_the_whole_plane(identity):
    # the identity's parameters of (2, 2) and (-1/2, 1/4) lie outside the triangle
    points = [[2, 2], [2, 2], [F(-1, 2), F(1, 4)]]
    claimed = [None, (2, 2), (F(-1, 2), F(1, 4))]
    r = tribez.check_locate(identity, points, claimed)
    assert (r.anywhere, r.passed, r.failed, r.extra) == (False, 1, 2, 2)
    r = tribez.check_locate(identity, points, claimed, anywhere=True)
    assert (r.anywhere, r.passed, r.failed, r.missed) == (True, 2, 1, 1)
    assert [f["row"] for f in r.failures] == [0]
    assert "parameters anywhere in the plane" in str(r)
    with pytest.raises(tribez.InputError, match="anywhere: expected a bool"):
        tribez.check_locate(identity, points, claimed, anywhere="yes")


def test_rows_are_counted_before_they_are_converted(identity):
    class Huge(list):
        """A list that says it holds more rows than a call takes (nothing is converted)."""

        def __len__(self):
            return tribez.MAX_INVERSE_ROWS + 1

    with pytest.raises(tribez.InputError, match=f"more than the {tribez.MAX_INVERSE_ROWS}"):
        tribez.check_locate(identity, Huge(), [])
