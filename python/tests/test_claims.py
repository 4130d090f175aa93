"""tribez.check_claims and tribez.certify: the library's claim-file and certification reports.

Expected counts come from reading the fixtures with Python's own TOML reader; expected errors
from plain Python fractions (tests/reference.py) and a float de Casteljau written here.
"""

import json
import os
import pathlib
import pickle
import subprocess

import numpy as np
import pytest

import tribez
from reference import bernstein_value, multi_indices, ulps_error

tomllib = pytest.importorskip("tomllib")  # Python >= 3.11 (the CI's); the package needs 3.9

CLI = os.environ.get("TRIBEZ_CLI")
ROOT = pathlib.Path(__file__).resolve().parents[2]
FIXTURES = ROOT / "fixtures"


def claim_files():
    return sorted(FIXTURES.rglob("*.claims.toml")) + sorted(FIXTURES.rglob("*.claims.json"))


def count_claims(files):
    """(claims, known errata) by reading the claim files, not by running tribez."""
    claims = errata = 0
    for f in files:
        data = tomllib.loads(f.read_text()) if f.suffix == ".toml" else json.loads(f.read_text())
        cs = data.get("claim", [])
        claims += len(cs)
        errata += sum(1 for c in cs if "erratum" in c)
    return claims, errata


def test_check_claims_on_the_fixtures():
    files = claim_files()
    claims, errata = count_claims(files)
    report = tribez.check_claims(FIXTURES)
    assert isinstance(report, tribez.Report)
    assert (report.claims, report.files) == (claims, len(files))
    # every claim is reproduced except the known errata of the sources
    assert (report.passed, report.errata, report.failed, report.ok) == (claims - errata, errata, 0, True)
    assert f"{claims} claims in {len(files)} files: {claims - errata} passed, {errata} known errata, 0 failed" in str(report)
    r = report.rows
    assert r["passed"].sum() == claims - errata and r["erratum"].sum() == errata
    assert len(report.results) == claims
    assert sum(report.histogram.values()) == sum(len(c["float"]) for c in report.results)
    report.raise_if_failed()
    again = pickle.loads(pickle.dumps(report))
    assert (again.to_json(), str(again)) == (report.to_json(), str(report))


@pytest.mark.skipif(not CLI, reason="TRIBEZ_CLI (the tribez binary) not set; .ci/run sets it")
def test_check_claims_is_the_command_lines_report(monkeypatch):
    monkeypatch.chdir(ROOT)  # the reports name the files as given
    report = tribez.check_claims("fixtures")
    text = subprocess.run([CLI, "check", "fixtures"], capture_output=True, text=True)
    assert text.returncode == 0
    assert text.stdout == str(report)
    out = subprocess.run([CLI, "check", "fixtures", "--format", "json"], capture_output=True, text=True)
    assert json.loads(out.stdout) == json.loads(report.to_json())


def test_the_python_guide_states_this_repositorys_claim_counts():
    claims, errata = count_claims(claim_files())
    text = (ROOT / "docs" / "python.md").read_text()
    assert f"# ({claims}, {claims - errata}, {errata}, 0) in this repository" in text


def test_worked_example_claims():
    report = tribez.check_claims(FIXTURES / "finn_day30.claims.toml")
    claims, errata = count_claims([FIXTURES / "finn_day30.claims.toml"])
    assert (report.claims, report.errata, report.passed, report.failed) == (claims, errata, claims - errata, 0)
    ids = list(report.rows["id"])
    assert "worked-example-a" in ids
    a = report.results[ids.index("worked-example-a")]
    assert a["verdict"] == "passed" and a["exact"] == ["4/9", "5/9", "29/36"]


def test_a_wrong_claim_fails(tmp_path):
    text = (FIXTURES / "finn_day30.claims.toml").read_text()
    assert '"29/36"' in text
    (tmp_path / "finn_day30.toml").write_text((FIXTURES / "finn_day30.toml").read_text())
    (tmp_path / "wrong.claims.toml").write_text(text.replace('"29/36"', '"29/37"', 1))
    report = tribez.check_claims(tmp_path)
    assert (report.failed, report.ok) == (1, False)
    with pytest.raises(tribez.CertificationError) as info:
        report.raise_if_failed()
    assert "FAILED" in str(info.value) and info.value.report is report


def test_bad_claim_paths(tmp_path):
    with pytest.raises(tribez.InputError, match="no such file or directory"):
        tribez.check_claims(tmp_path / "missing")
    with pytest.raises(tribez.InputError, match="no claim files"):
        tribez.check_claims(tmp_path)
    (tmp_path / "bad.claims.toml").write_text("source = \n")
    with pytest.raises(tribez.InputError) as info:
        tribez.check_claims(tmp_path / "bad.claims.toml")
    assert str(info.value).startswith(str(tmp_path / "bad.claims.toml"))
    if CLI:
        out = subprocess.run([CLI, "check", str(tmp_path / "bad.claims.toml")], capture_output=True, text=True)
        assert out.returncode == 2 and out.stderr.strip() == f"tribez: {info.value}"
    with pytest.raises(tribez.InputError, match="path: expected a str"):
        tribez.check_claims(None)
    report = tribez.check_claims(FIXTURES / "finn_day30.claims.toml")
    with pytest.raises(tribez.InputError, match="do not merge"):
        report.merge(report)


# --- certify


def casteljau_f64(nodes, degree, lam):
    """de Casteljau in Python floats, in the library's operation order (docs/theory.md §14)."""
    level = {a: [float(nodes[i][j]) for i in range(len(nodes))] for j, a in enumerate(multi_indices(2, degree))}
    for n in range(degree, 0, -1):
        level = {
            a: [(lam[0] * level[(a[0] + 1, a[1], a[2])][i] + lam[1] * level[(a[0], a[1] + 1, a[2])][i])
                + lam[2] * level[(a[0], a[1], a[2] + 1)][i] for i in range(len(nodes))]
            for a in multi_indices(2, n - 1)
        }
    return level[(0, 0, 0)]


def test_certify_the_worked_example_with_a_seed(finn):
    patch = tribez.Patch.from_file(FIXTURES / "finn_day30.toml")
    report = tribez.certify(patch, random=50, seed=7)
    assert isinstance(report, tribez.Report)
    assert (report.seed, report.points) == (7, 50)
    assert "--random 50 --seed 7" in report.reproduce and "seed 7" in str(report)
    r = report.rows
    assert sorted(zip(r["algorithm"], r["precision"])) == sorted(
        (a, p) for a in ("casteljau", "bernstein") for p in ("f64", "f32"))
    assert list(r["coordinates"]) == [50 * 3] * 4
    assert report.ok and report.failed == 0 and r["within_bound"].all()
    assert (r["max_error_over_bound"] <= 1).all()
    assert report.max_ulps == max(r["max_ulps"]) == report.worst["ulps"]
    # the same seed, the same run; another seed, other points
    assert tribez.certify(patch, random=50, seed=7).to_json() == report.to_json()
    assert tribez.certify(patch, random=50, seed=8).to_json() != report.to_json()
    assert pickle.loads(pickle.dumps(report)).to_json() == report.to_json()
    if CLI:
        out = subprocess.run([CLI, "certify", str(FIXTURES / "finn_day30.toml"), "--random", "50", "--seed", "7",
                              "--format", "json"], capture_output=True, text=True)
        assert json.loads(out.stdout) == json.loads(report.to_json())


def test_certify_at_given_points_against_an_independent_computation(finn):
    nodes = [[0, 1, 0, 0, 1, 0], [0, 0, 2, 1, 1, 2], [0, 2, 0, 0, 1, 1]]
    pts = [[0.25, 0.25, 0.5], [0.1, 0.7, 0.2], [0.6, 0.3, 0.1]]
    report = tribez.certify(finn, points=pts, precision="f64", algorithm="casteljau")
    (res,) = report.results
    assert (res["algorithm"], res["precision"], report.points, report.seed) == ("casteljau", "f64", 3, None)
    errs = [ulps_error(y, q) for p in pts for y, q in zip(casteljau_f64(nodes, 2, p), bernstein_value(nodes, 2, p))]
    assert res["max_ulps"] == pytest.approx(float(max(errs)), rel=1e-12)
    cr = sum(float(q) == y for p in pts for y, q in zip(casteljau_f64(nodes, 2, p), bernstein_value(nodes, 2, p)))
    assert res["correctly_rounded"] == cr
    assert report.worst["point"] == tuple(pts[[max(ulps_error(y, q) for y, q in zip(casteljau_f64(nodes, 2, p),
                                                bernstein_value(nodes, 2, p))) for p in pts].index(max(errs))])


def test_bad_certify_arguments(finn):
    def bad(fragment, **kw):
        with pytest.raises(tribez.InputError) as info:
            tribez.certify(finn, **kw)
        assert fragment in str(info.value), str(info.value)

    bad("random: 0: expected a whole number from 1 to 1000000", random=0)
    bad("random: 1000001: expected a whole number from 1 to 1000000", random=1_000_001)
    bad("random: -3 is negative", random=-3)
    bad("seed: -1 is negative", random=5, seed=-1)
    bad("seed: 18446744073709551616 is above the limit", random=5, seed=2**64)
    bad("not both", points=[[1, 0, 0]], random=5)
    bad("unknown precision `f16`", random=5, precision="f16")
    bad("unknown algorithm `horner`", random=5, algorithm="horner")
    bad("has 2 coordinates, expected 3", points=[[1, 0]])
    bad("points[0][1]: `x`: not a number", points=[["1", "x", "0"]])
    bad("points: no rows", points=[])
    with pytest.raises(tribez.InputError, match="expected a tribez.Patch"):
        tribez.certify("fixtures/finn_day30.toml")
