//! Float results at Cartesian points judged four ways must agree (issue 35, section 1): claim
//! files (`eval` with `cartesian` and `precision`), `check --results --cartesian` batches, the
//! library's judge ([`tribez::judge_input`] with [`tribez::JudgeInput::Cartesian`]) and the
//! library's batch engine on rows in memory (what the Python package's `check(…,
//! cartesian=True)` calls). The points' barycentric coordinates are NOT floats (domain (0,0),
//! (3,0), (0,3)), so that judging at rounded barycentric coordinates, the bug, would show.
//!
//! Expected verdicts and ULP figures: fixtures/judge/cartesian/expected.json, written by
//! fixtures/judge/cartesian/derive.py (Python fractions, from docs/guide.md §7 and theory §14,
//! independent of tribez).

use std::path::{Path, PathBuf};

use assert_cmd::Command;
use serde_json::Value as Json;
use tribez::batch::{BatchChecker, BatchOptions};
use tribez::format::{exact_f64, round_f64};
use tribez::{
    Algorithm, JudgeInput, Patch, PatchKind, Precision, Rational, Tolerance, parse_rational,
};

fn fixture_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../fixtures/judge/cartesian")
}

fn expected() -> Json {
    let text = std::fs::read_to_string(fixture_dir().join("expected.json")).unwrap();
    serde_json::from_str(&text).unwrap()
}

fn strs(v: &Json) -> Vec<String> {
    v.as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_str().unwrap().to_string())
        .collect()
}

fn q(s: &str) -> Rational {
    parse_rational(s).unwrap()
}

/// A hex float of the fixture as f64 (exact: a float of the precision is one of f64).
fn float(s: &str) -> f64 {
    let x = q(s);
    let f = round_f64(&x);
    assert_eq!(exact_f64(f), Some(x), "{s} is a float");
    f
}

fn precision(name: &str) -> Precision {
    match name {
        "f64" => Precision::F64,
        "f32" => Precision::F32,
        other => panic!("{other}"),
    }
}

struct Row {
    point: Vec<String>,
    claimed: Vec<String>,
    ulps: Vec<Rational>,
    verdicts: Json,
}

fn rows(case: &Json) -> Vec<Row> {
    case["rows"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| Row {
            point: strs(&r["point"]),
            claimed: strs(&r["claimed"]),
            ulps: strs(&r["ulps"]).iter().map(|s| q(s)).collect(),
            verdicts: r["verdicts"].clone(),
        })
        .collect()
}

fn max(xs: &[Rational]) -> Rational {
    xs.iter().max().cloned().unwrap()
}

fn tribez_json(args: &[&str], dir: &Path) -> Json {
    let out = Command::cargo_bin("tribez")
        .unwrap()
        .current_dir(dir)
        .args(args)
        .args(["--format", "json"])
        .output()
        .unwrap();
    let code = out.status.code();
    assert!(
        matches!(code, Some(0 | 1)),
        "{args:?}: {code:?} {}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).unwrap()
}

/// Claim files: verdicts and the ULP figures of every coordinate.
fn check_claims(case: &Json, rows: &[Row], tol: &str, dir: &Path) {
    let prec = case["precision"].as_str().unwrap();
    let mut text = format!(
        "patch = \"{}\"\nsource = \"derive.py\"\n",
        case["patch"].as_str().unwrap()
    );
    for (i, r) in rows.iter().enumerate() {
        let list = |xs: &[String]| {
            xs.iter()
                .map(|x| format!("\"{x}\""))
                .collect::<Vec<_>>()
                .join(", ")
        };
        text.push_str(&format!(
            "[[claim]]\nid = \"r{i}\"\nop = \"eval\"\nprecision = \"{prec}\"\ntolerance = \"{tol}\"\ncartesian = [{}]\nexpect = [{}]\n",
            list(&r.point),
            list(&r.claimed)
        ));
    }
    std::fs::write(dir.join("c.claims.toml"), text).unwrap();
    let report = tribez_json(&["check", "c.claims.toml"], dir);
    let claims = report["claims"].as_array().unwrap();
    assert_eq!(claims.len(), rows.len());
    for (i, (c, r)) in claims.iter().zip(rows).enumerate() {
        let want = r.verdicts[tol].as_bool().unwrap();
        assert_eq!(
            c["verdict"].as_str().unwrap() == "passed",
            want,
            "claim file, {} {prec} {tol}, row {i}: {c}",
            case["patch"]
        );
        let ulps: Vec<Rational> = c["float"]
            .as_array()
            .unwrap()
            .iter()
            .map(|f| {
                q(f["error_at_inputs_as_seen"]["ulps"]["exact"]
                    .as_str()
                    .unwrap())
            })
            .collect();
        assert_eq!(ulps, r.ulps, "claim file ULPs, {} row {i}", case["patch"]);
    }
}

/// `check --results --cartesian`: the failing lines at `tol`; with `ulps=0` every row with an
/// error fails and is listed with its exact ULP figures.
fn check_batch(case: &Json, rows: &[Row], tol: &str, dir: &Path) {
    let prec = case["precision"].as_str().unwrap();
    let csv: String = rows
        .iter()
        .map(|r| format!("{},{}\n", r.point.join(","), r.claimed.join(",")))
        .collect();
    std::fs::write(dir.join("rows.csv"), csv).unwrap();
    let patch = case["patch"].as_str().unwrap();
    let run = |tol: &str| {
        tribez_json(
            &[
                "check",
                "--patch",
                patch,
                "--results",
                "rows.csv",
                "--cartesian",
                "--precision",
                prec,
                "--tolerance",
                tol,
            ],
            dir,
        )
    };
    let report = run(tol);
    let failing: Vec<u64> = report["failures"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| f["line"].as_u64().unwrap())
        .collect();
    for (i, r) in rows.iter().enumerate() {
        let want = r.verdicts[tol].as_bool().unwrap();
        assert_eq!(
            !failing.contains(&(i as u64 + 1)),
            want,
            "--cartesian batch, {patch} {prec} {tol}, line {}",
            i + 1
        );
    }
    let report = run("ulps=0");
    let failures = report["failures"].as_array().unwrap();
    for (i, r) in rows.iter().enumerate() {
        let listed = failures
            .iter()
            .find(|f| f["line"].as_u64() == Some(i as u64 + 1));
        let ulps: Vec<Rational> = match listed {
            Some(f) => f["coordinates"]
                .as_array()
                .unwrap()
                .iter()
                .map(|c| {
                    q(c["error_at_inputs_as_seen"]["ulps"]["exact"]
                        .as_str()
                        .unwrap())
                })
                .collect(),
            None => vec![q("0"); r.ulps.len()],
        };
        assert_eq!(
            ulps,
            r.ulps,
            "--cartesian batch ULPs, {patch} line {}",
            i + 1
        );
    }
}

/// The library: the judge at a Cartesian point, and the batch engine on rows in memory.
fn check_library(case: &Json, rows: &[Row], tol: &str, patch: &Patch) {
    let p = precision(case["precision"].as_str().unwrap());
    let tolerance = Tolerance::parse(tol).unwrap();
    for (i, r) in rows.iter().enumerate() {
        let point: Vec<f64> = r.point.iter().map(|s| float(s)).collect();
        let claimed: Vec<f64> = r.claimed.iter().map(|s| float(s)).collect();
        let j = tribez::judge_input(
            patch,
            Algorithm::Casteljau,
            JudgeInput::Cartesian(&point),
            &claimed,
            &tolerance,
            p,
            None,
        )
        .unwrap();
        assert_eq!(
            j.passed,
            r.verdicts[tol].as_bool().unwrap(),
            "judge, {} {tol}, row {i}: {j}",
            case["patch"]
        );
        let ulps: Vec<Rational> = j
            .coordinates
            .iter()
            .map(|c| c.ulps.clone().unwrap())
            .collect();
        assert_eq!(ulps, r.ulps, "judge ULPs, {} row {i}", case["patch"]);
    }
    let (PatchKind::Bezier, Some(poly)) = (patch.kind(), patch.polynomial()) else {
        return; // batches judge polynomial patches only
    };
    let options = BatchOptions {
        tolerance: tolerance.clone(),
        precision: Some(p),
        algorithm: Algorithm::Casteljau,
        cartesian: true,
        row_detail: false,
    };
    let checker = BatchChecker::new(poly.clone(), &options).unwrap();
    let points: Vec<f64> = rows
        .iter()
        .flat_map(|r| r.point.iter().map(|s| float(s)))
        .collect();
    let values: Vec<f64> = rows
        .iter()
        .flat_map(|r| r.claimed.iter().map(|s| float(s)))
        .collect();
    let (_, verdicts) = checker
        .check_rows(&points, &values, 0, "<memory>", "patch")
        .unwrap();
    for (v, r) in verdicts.iter().zip(rows) {
        assert_eq!(
            v.pass,
            r.verdicts[tol].as_bool().unwrap(),
            "batch engine in memory, {} {tol}, row {}",
            case["patch"],
            v.row
        );
        // exact where computed exactly, else the upper end of a tight enclosure
        let exact: f64 = round_f64(&max(&r.ulps));
        assert!(
            v.ulps >= exact * (1.0 - 1e-12) && v.ulps <= exact + 1.0 / 64.0,
            "batch engine ULPs, {} row {}: {} against {exact}",
            case["patch"],
            v.row,
            v.ulps
        );
    }
}

#[test]
fn claim_files_batches_and_the_judge_agree_at_cartesian_points() {
    let all = expected();
    let mut judged = 0;
    for case in all["cases"].as_array().unwrap() {
        let name = case["patch"].as_str().unwrap();
        let dir = tempfile::tempdir().unwrap();
        std::fs::copy(fixture_dir().join(name), dir.path().join(name)).unwrap();
        let patch = Patch::from_file(fixture_dir().join(name)).unwrap();
        let rows = rows(case);
        let tolerances: Vec<String> = rows[0]
            .verdicts
            .as_object()
            .unwrap()
            .keys()
            .cloned()
            .collect();
        for tol in &tolerances {
            check_claims(case, &rows, tol, dir.path());
            check_library(case, &rows, tol, &patch);
            if case["kind"] == "bezier" {
                check_batch(case, &rows, tol, dir.path());
            }
            judged += rows.len();
        }
    }
    // 3 polynomial cases × 5 tolerances + a rational case × 3, 30 rows each
    assert_eq!(judged, 30 * (3 * 5 + 3));
}

/// An S-patch's input is Cartesian already: the Cartesian judge is the judge.
#[test]
fn an_s_patch_is_judged_alike_either_way() {
    let s = Patch::from_file(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../fixtures/beyond/pentagon_depth2.toml"),
    )
    .unwrap();
    let tol = Tolerance::parse("ulps=4").unwrap();
    let point = [2.0, 2.0];
    // the value at (2, 2), rounded: fixtures/judge/derive.py (pentagon.claims.toml's s-patch-at-2-2)
    let claimed = ["63147/128164", "100083/128164", "-15609/64082"].map(|s| round_f64(&q(s)));
    let a = tribez::judge(&s, &point, &claimed, &tol, Precision::F64);
    let b = tribez::judge_cartesian(&s, &point, &claimed, &tol, Precision::F64);
    let (a, b) = (a.unwrap(), b.unwrap());
    assert!(a.passed, "{a}");
    assert_eq!(a, b);
}
