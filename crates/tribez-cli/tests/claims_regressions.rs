//! Issue 10 regressions owned by the claims: the rational subpatch's `domain_in_parent`, size
//! caps of claim operations, the inputs as the float code saw them (`precision`), and located
//! one-line errors (exit status 2, nothing on stdout).

use std::path::{Path, PathBuf};

use assert_cmd::Command;
use predicates::prelude::*;

fn tribez() -> Command {
    Command::cargo_bin("tribez").expect("binary built")
}

fn fixtures() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../fixtures")
}

/// A temporary directory holding `c.claims.toml` with `claims` (after a quadratic patch).
fn claim_dir(claims: &str) -> tempfile::TempDir {
    let d = tempfile::tempdir().unwrap();
    std::fs::copy(fixtures().join("finn_day30.toml"), d.path().join("p.toml")).unwrap();
    std::fs::write(
        d.path().join("c.claims.toml"),
        format!("patch = \"p.toml\"\n{claims}"),
    )
    .unwrap();
    d
}

/// `check` on the claims: exit 2, nothing on stdout, one line on stderr with every fragment.
fn check_fails(claims: &str, fragments: &[&str]) {
    let d = claim_dir(claims);
    let out = tribez()
        .arg("check")
        .arg(d.path().join("c.claims.toml"))
        .assert()
        .code(2)
        .stdout("");
    let err = String::from_utf8(out.get_output().stderr.clone()).unwrap();
    assert_eq!(err.trim_end().lines().count(), 1, "one line: {err}");
    for f in fragments {
        assert!(err.contains(f), "{f:?} not in {err}");
    }
}

#[test]
fn claim_op_sizes_are_capped_before_allocating() {
    // n + m wrapped: the 1000-row limit was bypassed
    check_fails(
        "[[claim]]\nid = \"big\"\nop = \"matrix\"\nkind = \"halve\"\ndegree = \"18446744073709551615\"\nexpect = []\n",
        &["c.claims.toml:", "big.degree", "at most 1000 rows"],
    );
    check_fails(
        "[[claim]]\nid = \"big\"\nop = \"matrix\"\nkind = \"halve\"\ndegree = 44\nexpect = []\n",
        &["big.degree", "at most 1000 rows"],
    );
    // degree + by wrapped (an abort)
    check_fails(
        "[[claim]]\nid = \"up\"\nop = \"elevate\"\nby = \"18446744073709551615\"\nexpect = {}\n",
        &["up.by", "capped at 200"],
    );
    check_fails(
        "[[claim]]\nid = \"up\"\nop = \"elevate\"\nby = 199\nexpect = {}\n",
        &["up.by", "elevate by 1 to 198", "capped at 200"],
    );
    // a basis of a size whose control-point count is above the limit
    check_fails(
        "[[claim]]\nid = \"b\"\nop = \"basis\"\ndegree = 200\nsimplex = 16\nexpect = {}\n",
        &["b.degree", "above the limit of 250000"],
    );
}

/// The rational subpatch reports its simplex in the parent as the polynomial one does.
#[test]
fn rational_subpatch_has_domain_in_parent() {
    let octant = fixtures().join("beyond/octant_quartic.toml");
    let args = [
        "--vertex",
        "1,0,0",
        "--vertex",
        "1/2,1/2,0",
        "--vertex",
        "1/3,1/3,1/3",
    ];
    let out = tribez()
        .arg("subpatch")
        .arg(&octant)
        .args(args)
        .args(["--format", "json"])
        .assert()
        .success()
        .get_output()
        .stdout
        .clone();
    let j: serde_json::Value = serde_json::from_slice(&out).unwrap();
    assert_eq!(
        j["domain_in_parent"],
        serde_json::json!([["1", "0", "0"], ["1/2", "1/2", "0"], ["1/3", "1/3", "1/3"]])
    );
    assert!(j["weights"].is_object());
    let text = tribez()
        .arg("subpatch")
        .arg(&octant)
        .args(args)
        .assert()
        .success()
        .get_output()
        .stdout
        .clone();
    let text = String::from_utf8(text).unwrap();
    assert!(
        text.contains(
            "domain_in_parent = [[\"1\", \"0\", \"0\"], [\"1/2\", \"1/2\", \"0\"], [\"1/3\", \"1/3\", \"1/3\"]]\n"
        ),
        "{text}"
    );
    // the file is a patch file again: its corner 3 is the parent's centroid (80, 100, 59)/141
    let dir = tempfile::tempdir().unwrap();
    let sub = dir.path().join("sub.toml");
    std::fs::write(&sub, &text).unwrap();
    tribez()
        .arg("eval")
        .arg(&sub)
        .args(["--at", "0,0,1"])
        .assert()
        .success()
        .stdout(predicate::str::contains("(80/141, 100/141, 59/141)"));
}

/// `tribez check` on a claim file written into a temporary directory beside `files`; the exit
/// status and standard output.
fn check_in_dir(files: &[(&str, &str)], claims: &str) -> (i32, String) {
    let d = tempfile::tempdir().unwrap();
    for (name, text) in files {
        std::fs::write(d.path().join(name), text).unwrap();
    }
    std::fs::write(d.path().join("c.claims.toml"), claims).unwrap();
    let out = tribez()
        .arg("check")
        .arg(d.path().join("c.claims.toml"))
        .output()
        .unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8(out.stdout).unwrap(),
    )
}

/// Issue 35, section 1: an `eval` claim at a Cartesian point with a precision is judged at the
/// exact barycentric coordinates of the rounded point, never at those coordinates rounded.
///
/// By hand: the domain is (0,0), (3,0), (0,3), so (x, y) has barycentric coordinates
/// (1 − x/3 − y/3, x/3, y/3), and (1, 1) (floats already) is (1/3, 1/3, 1/3): not floats. The plane
/// 21 λ0 + 67 λ1 − 2 λ2 is 86/3 there. 16 ≤ 86/3 < 32, so its ULP is 2^(4−52) = 2^-48, and
/// 86·2^48 ≡ 2·1 (mod 3), so 86/3 = (k + 2/3)·2^-48: the float above, (k+1)·2^-48 =
/// 28.666666666666668, is 1/3 ulp away and correctly rounded; the float below, k·2^-48 =
/// 28.666666666666664, is 2/3 ulp away and is not. (Judged at the rounded coordinates, the value
/// was 28.666666666666665075…, and the verdicts came out the other way round.)
#[test]
fn eval_at_a_cartesian_point_uses_its_exact_barycentric_coordinates() {
    let plane = r#"{"degree": 1, "control_points": {"1,0,0": ["21"], "0,1,0": ["67"], "0,0,1": ["-2"]},
 "domain": [["0", "0"], ["3", "0"], ["0", "3"]]}"#;
    let claim = |expect: &str| {
        format!(
            "patch = \"p.json\"\nsource = \"t\"\n[[claim]]\nid = \"c\"\nop = \"eval\"\nprecision = \"f64\"\ntolerance = \"correctly_rounded\"\ncartesian = [\"1\", \"1\"]\nexpect = [\"{expect}\"]\nsource = \"t\"\n"
        )
    };
    let (code, out) = check_in_dir(&[("p.json", plane)], &claim("28.666666666666668"));
    assert_eq!(code, 0, "{out}");
    assert!(out.contains("passed"), "{out}");
    let (code, out) = check_in_dir(&[("p.json", plane)], &claim("28.666666666666664"));
    assert_eq!(code, 1, "{out}");
    assert!(out.contains("0.6667 ulp"), "{out}");
    assert!(out.contains("not correctly rounded"), "{out}");
    // `--format json`: the exact value and the ULP figures exactly
    let d = tempfile::tempdir().unwrap();
    std::fs::write(d.path().join("p.json"), plane).unwrap();
    std::fs::write(d.path().join("c.claims.toml"), claim("28.666666666666668")).unwrap();
    let out = tribez()
        .args(["check", "--format", "json"])
        .arg(d.path().join("c.claims.toml"))
        .output()
        .unwrap();
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let f = &json["claims"][0]["float"][0];
    assert_eq!(f["exact_at_inputs_as_seen"], "86/3");
    assert_eq!(f["error_at_inputs_as_seen"]["ulps"]["exact"], "1/3");
    assert_eq!(json["claims"][0]["verdict"], "passed");
}

/// Issue 35, section 6: claimed tuples are matched with exact ones (a perfect matching), not
/// paired greedily with the nearest.
///
/// By hand: A is the segment (0,0)–(1,0), A(s) = (s, 0). B is the quadratic with control points
/// (0, 1/4 + 1e-7), (1/2, −1/4), (1, 1/4 − 1e-7): x(t) = t, and y(t) has Bernstein coefficients
/// b0 = ab, b1 = ab − (a+b)/2, b2 = (1−a)(1−b) of (t − a)(t − b) for a = 1/2, b = 1/2 + 2e-7
/// (ab = 1/4 + 1e-7, (a+b)/2 = 1/2 + 1e-7, (1−a)(1−b) = 1/2·(1/2 − 2e-7)). So A(s) = B(t) iff
/// s = t and (t − a)(t − b) = 0: exactly (1/2, 1/2) and (b, b), b = 0.5000002.
///
/// The claim (0.50000011, 0.50000011), (0.5000003, 0.5000003) at abs=1.5e-7: the first tuple
/// lies 1.1e-7 from (a, a) and 0.9e-7 from (b, b), the second 3e-7 from (a, a) and 1e-7 from
/// (b, b). Both are nearest (b, b); pairing the nearest first gives (b, b) to the first tuple and
/// leaves (a, a), 3e-7 away, to the second: a false failure. The matching first ↔ (a, a),
/// second ↔ (b, b) is within 1.5e-7 everywhere: the claim holds. At abs=1e-7 only (b, b) accepts
/// either tuple, so no matching exists: it fails, and the message names the two tuples that only
/// the one solution accepts.
#[test]
fn claimed_tuples_are_matched_not_paired_greedily() {
    let seg = "degree = 1\n[control_points]\n\"1,0\" = [\"0\", \"0\"]\n\"0,1\" = [\"1\", \"0\"]\n";
    let quad = "degree = 2\n[control_points]\n\"2,0\" = [\"0\", \"0.2500001\"]\n\"1,1\" = [\"1/2\", \"-1/4\"]\n\"0,2\" = [\"1\", \"0.2499999\"]\n";
    let claim = |tol: &str, expect: &str| {
        format!(
            "source = \"t\"\n[patches]\na = \"a.toml\"\nb = \"b.toml\"\n[[claim]]\nid = \"x\"\nop = \"intersect\"\npatches = [\"a\", \"b\"]\ntolerance = \"{tol}\"\nexpect = {expect}\n"
        )
    };
    let files = [("a.toml", seg), ("b.toml", quad)];
    let both = r#"[["0.50000011", "0.50000011"], ["0.5000003", "0.5000003"]]"#;
    let swapped = r#"[["0.5000003", "0.5000003"], ["0.50000011", "0.50000011"]]"#;
    // the exact answer first: exactly these two points
    let (code, out) = check_in_dir(
        &files,
        &claim("exact", r#"[["1/2", "1/2"], ["0.5000002", "0.5000002"]]"#),
    );
    assert_eq!(code, 0, "{out}");
    for expect in [both, swapped] {
        let (code, out) = check_in_dir(&files, &claim("abs=1.5e-7", expect));
        assert_eq!(code, 0, "{expect}: {out}");
    }
    let (code, out) = check_in_dir(&files, &claim("abs=1e-7", both));
    assert_eq!(code, 1, "{out}");
    assert!(out.contains("breaks tolerance `abs=1/10000000`"), "{out}");
    assert!(
        out.contains("accepted (within `abs=1/10000000`) only by the exact solution 2"),
        "{out}"
    );
    // a third tuple: the count differs, one tuple is left over
    let three = r#"[["0.5", "0.5"], ["0.5000002", "0.5000002"], ["0.5000002", "0.5000002"]]"#;
    let (code, out) = check_in_dir(&files, &claim("abs=1e-7", three));
    assert_eq!(code, 1, "{out}");
    assert!(
        out.contains("extra: every exact solution within 2^-20 is paired"),
        "{out}"
    );
}
