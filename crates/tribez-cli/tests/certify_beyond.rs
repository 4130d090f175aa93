//! Certifying rational patches and S-patches on the command line: tables, exit codes, and
//! every bad input (exit 2, one line). The certifiers' bounds themselves are tested in the
//! library (crates/tribez/tests/certify_beyond.rs).

use std::path::{Path, PathBuf};

use assert_cmd::Command;
use predicates::prelude::*;

fn tribez() -> Command {
    Command::cargo_bin("tribez").unwrap()
}

fn fixture(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../fixtures/beyond")
        .join(name)
}

#[test]
fn certify_rational_on_the_command_line() {
    tribez()
        .args(["certify", "--random", "300", "--seed", "3"])
        .arg(fixture("octant_quartic.toml"))
        .assert()
        .success()
        .stdout(predicate::str::contains("γ_12,÷"))
        .stdout(predicate::str::contains("within"))
        .stdout(predicate::str::contains("(e_N + |q| e_D)/|D̂|"))
        .stdout(predicate::str::contains("EXCEEDED").not());
    let out = tribez()
        .args(["certify", "--random", "50", "--format", "json"])
        .arg(fixture("octant_quartic.toml"))
        .assert()
        .success();
    let v: serde_json::Value = serde_json::from_slice(&out.get_output().stdout).unwrap();
    assert_eq!(v["results"].as_array().unwrap().len(), 2);
    assert_eq!(v["results"][0]["within_bound"], true);
    assert_eq!(v["results"][0]["coordinates"], 150);
}

#[test]
fn certify_s_patch_on_the_command_line() {
    tribez()
        .args(["certify", "--random", "200"])
        .arg(fixture("pentagon_depth2.toml"))
        .assert()
        .success()
        .stdout(predicate::str::contains("γ_10+θ"))
        .stdout(predicate::str::contains("within"))
        .stdout(predicate::str::contains("EXCEEDED").not())
        .stdout(predicate::str::contains(
            "Wachspress coordinates λ̂: max error",
        ));
    let dir = tempfile::tempdir().unwrap();
    let pts = dir.path().join("p.csv");
    std::fs::write(&pts, "2,2\n1/3,1/7\n4,0\n").unwrap();
    tribez()
        .arg("certify")
        .arg(fixture("pentagon_depth2.toml"))
        .arg("--points")
        .arg(&pts)
        .assert()
        .success()
        .stdout(predicate::str::contains(": 3 points"));
}

fn bad(args: &[&str], patch: &Path, fragment: &str) {
    let out = tribez()
        .arg("certify")
        .arg(patch)
        .args(args)
        .assert()
        .code(2)
        .stderr(predicate::str::contains(fragment));
    let err = String::from_utf8_lossy(&out.get_output().stderr).to_string();
    assert_eq!(err.trim_end().lines().count(), 1, "one line: {err}");
    assert!(out.get_output().stdout.is_empty());
}

#[test]
fn bad_inputs_of_certify_on_rational_and_s_patches() {
    let dir = tempfile::tempdir().unwrap();
    let octant = fixture("octant_quartic.toml");
    let pentagon = fixture("pentagon_depth2.toml");
    bad(
        &["--random", "5", "--algorithm", "bernstein"],
        &octant,
        "de Casteljau only",
    );
    bad(
        &["--random", "5", "--algorithm", "bernstein"],
        &pentagon,
        "de Casteljau only",
    );
    bad(&["--random", "0"], &octant, "at least one point");
    bad(&["--random", "0"], &pentagon, "at least one point");
    bad(&[], &pentagon, "--random N");
    // a point outside the polygon
    let pts = dir.path().join("out.csv");
    std::fs::write(&pts, "2,2\n10,10\n").unwrap();
    bad(
        &["--points", pts.to_str().unwrap()],
        &pentagon,
        "point 2: the point (10, 10) is outside the polygon",
    );
    // three coordinates for a Cartesian point
    let pts3 = dir.path().join("three.csv");
    std::fs::write(&pts3, "1,1,1\n").unwrap();
    bad(
        &["--points", pts3.to_str().unwrap()],
        &pentagon,
        "three.csv",
    );
    // a weighted control point overflowing f32
    let big = dir.path().join("big.toml");
    std::fs::write(
        &big,
        "degree = 1\n[control_points]\n\"1,0,0\" = [\"1e30\"]\n\"0,1,0\" = [\"0\"]\n\"0,0,1\" = [\"1\"]\n[weights]\n\"1,0,0\" = \"1e10\"\n\"0,1,0\" = 1\n\"0,0,1\" = 1\n",
    )
    .unwrap();
    bad(&["--random", "5"], &big, "overflows f32");
    // f64 alone is fine
    tribez()
        .arg("certify")
        .arg(&big)
        .args(["--random", "20", "--precision", "f64"])
        .assert()
        .success();
}

/// Issue 35 §3: random points of a polygon whose coordinates are near f64's largest (1.7e308)
/// are sums that overflow (the centroid's x is (0 + 1.7e308 + 1.7e308)/3, its sum 3.4e308 >
/// f64::MAX ≈ 1.798e308): one line naming the file and the polygon, exit 2, never a panic.
#[test]
fn random_points_of_a_polygon_too_large_for_f64_are_bad_input() {
    let dir = tempfile::tempdir().unwrap();
    let huge = dir.path().join("huge_spatch.toml");
    std::fs::write(
        &huge,
        "degree = 1\npolygon = [[\"0\", \"0\"], [\"1.7e308\", \"0\"], [\"1.7e308\", \"1.7e308\"]]\n[control_points]\n\"1,0,0\" = [\"0\"]\n\"0,1,0\" = [\"1\"]\n\"0,0,1\" = [\"2\"]\n",
    )
    .unwrap();
    for precision in ["f64", "f32", "all"] {
        bad(
            &["--random", "20", "--precision", precision],
            &huge,
            "huge_spatch.toml: polygon: its coordinates are too large for random points",
        );
    }
    // a polygon beyond f64 altogether (a vertex rounds to infinity): the same line
    let beyond = dir.path().join("beyond.toml");
    std::fs::write(
        &beyond,
        "degree = 1\npolygon = [[\"0\", \"0\"], [\"1e400\", \"0\"], [\"0\", \"1\"]]\n[control_points]\n\"1,0,0\" = [\"0\"]\n\"0,1,0\" = [\"1\"]\n\"0,0,1\" = [\"2\"]\n",
    )
    .unwrap();
    bad(
        &["--random", "5"],
        &beyond,
        "beyond.toml: polygon: its coordinates are too large for random points",
    );
    // given points need no sums: the f64 run judges them (exit 0 or 1, never 2)
    let pts = dir.path().join("p.csv");
    std::fs::write(&pts, "1e308,1\n").unwrap();
    let code = tribez()
        .arg("certify")
        .arg(&huge)
        .args(["--points", pts.to_str().unwrap(), "--precision", "f64"])
        .output()
        .unwrap()
        .status
        .code();
    assert!(matches!(code, Some(0 | 1)), "{code:?}");
}

fn claims(dir: &Path, patch: &str, body: &str) -> PathBuf {
    std::fs::copy(fixture(patch), dir.join(patch)).unwrap();
    let path = dir.join("c.claims.toml");
    std::fs::write(&path, format!("patch = \"{patch}\"\n{body}")).unwrap();
    path
}

#[test]
fn bound_and_cond_tolerances_on_rational_claims() {
    let dir = tempfile::tempdir().unwrap();
    // the f64 value Python computes (fixtures/beyond/float.claims.toml, octant-f64-python)
    let claim = |tol: &str, expect: &str| {
        format!(
            "[[claim]]\nid = \"b\"\nop = \"eval\"\nat = [\"1/3\", \"1/4\", \"5/12\"]\nprecision = \"f64\"\ntolerance = \"{tol}\"\nexpect = {expect}\n"
        )
    };
    let good = "[\"0.6067816775728732\", \"0.5764425936942295\", \"0.5472932778108268\"]";
    let wrong = "[\"0.60678167757298\", \"0.5764425936942295\", \"0.5472932778108268\"]";
    for tol in ["bound", "cond=12"] {
        tribez()
            .arg("check")
            .arg(claims(dir.path(), "octant_quartic.toml", &claim(tol, good)))
            .assert()
            .success();
        tribez()
            .arg("check")
            .arg(claims(
                dir.path(),
                "octant_quartic.toml",
                &claim(tol, wrong),
            ))
            .assert()
            .code(1);
    }
    // a rational patch has no Bernstein float path: exit 2
    let alg = claim("bound", good).replace("tolerance", "algorithm = \"bernstein\"\ntolerance");
    tribez()
        .arg("check")
        .arg(claims(dir.path(), "octant_quartic.toml", &alg))
        .assert()
        .code(2)
        .stderr(predicate::str::contains("homogeneous de Casteljau"));
    // S-patches: `bound` is the proven bound of the whole float path. Python's f64 values
    // (fixtures/beyond/derive.py) pass; moved by 1e-9 (millions of ulps) they fail (exit 1);
    // `cond=K` is refused (exit 2, one line); a point on an edge has no bound (exit 2).
    let sp = |tol: &str, x: &str| {
        format!(
            "[[claim]]\nid = \"s\"\nop = \"eval\"\ncartesian = [\"3\", \"5/2\"]\nprecision = \"f64\"\ntolerance = \"{tol}\"\nexpect = [\"{x}\", \"1.0272516124300894\", \"-0.6183382320586998\"]\n"
        )
    };
    tribez()
        .arg("check")
        .arg(claims(
            dir.path(),
            "pentagon_depth2.toml",
            &sp("bound", "-0.05684161838704246"),
        ))
        .assert()
        .success();
    tribez()
        .arg("check")
        .arg(claims(
            dir.path(),
            "pentagon_depth2.toml",
            &sp("bound", "-0.05684161938704246"),
        ))
        .assert()
        .code(1);
    let out = tribez()
        .arg("check")
        .arg(claims(
            dir.path(),
            "pentagon_depth2.toml",
            &sp("cond=9", "-0.05684161838704246"),
        ))
        .assert()
        .code(2)
        .stderr(predicate::str::contains("not defined for S-patches"));
    // (2, 0) lies on the edge from (0, 0) to (4, 0): a coordinate is 0 there, no relative bound
    let edge = sp("bound", "-0.05684161838704246").replace("[\"3\", \"5/2\"]", "[\"2\", \"0\"]");
    tribez()
        .arg("check")
        .arg(claims(dir.path(), "pentagon_depth2.toml", &edge))
        .assert()
        .code(2)
        .stderr(predicate::str::contains("too near an edge"));
    assert_eq!(
        String::from_utf8_lossy(&out.get_output().stderr)
            .trim_end()
            .lines()
            .count(),
        1
    );
}

#[test]
fn no_rational_bound_where_the_denominator_sign_is_uncertain() {
    // the line through 0 and 1 with weights 1 and −1: D = λ0 − λ1 vanishes at λ0 = λ1
    let dir = tempfile::tempdir().unwrap();
    let curve = "degree = 1\n[control_points]\n\"1,0\" = [\"0\"]\n\"0,1\" = [\"1\"]\n[weights]\n\"1,0\" = 1\n\"0,1\" = -1\n";
    std::fs::write(dir.path().join("c.toml"), curve).unwrap();
    // rounded λ = (1/2 + 2^-53, 1/2 − 2^-53): D = 2^-52 ≤ e_D = γ_2 (|λ0| + |λ1|) = 2^-52/(1 − 2^-52)
    let path = dir.path().join("c.claims.toml");
    std::fs::write(
        &path,
        "patch = \"c.toml\"\n[[claim]]\nid = \"d\"\nop = \"eval\"\nat = [\"0.5000000000000001\", \"0.4999999999999999\"]\nprecision = \"f64\"\ntolerance = \"bound\"\nexpect = [\"1\"]\n",
    )
    .unwrap();
    let out = tribez()
        .arg("check")
        .arg(&path)
        .assert()
        .code(2)
        .stderr(predicate::str::contains("its sign is not certain"));
    assert_eq!(
        String::from_utf8_lossy(&out.get_output().stderr)
            .trim_end()
            .lines()
            .count(),
        1
    );
    // certify skips such points (counted, not judged) and judges the rest
    tribez()
        .arg("certify")
        .arg(dir.path().join("c.toml"))
        .args(["--random", "400"])
        .assert()
        .success()
        .stdout(predicate::str::contains("within"));
}
