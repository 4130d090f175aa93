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
