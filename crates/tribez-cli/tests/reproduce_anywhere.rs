//! `tribez reproduce` needs no checkout (issue 10): its fixtures are built into the binary, so it
//! works from any directory, and leaves nothing behind (its temporary copy is removed). The
//! installed binary is exercised by `.ci/run` (`cargo install --path crates/tribez-cli` into a
//! temporary root, run from another directory).

use assert_cmd::Command;
use predicates::prelude::*;

#[test]
fn reproduce_runs_from_a_directory_without_fixtures_and_leaves_nothing_behind() {
    let cwd = tempfile::tempdir().unwrap();
    let tmp = tempfile::tempdir().unwrap();
    Command::cargo_bin("tribez")
        .unwrap()
        .arg("reproduce")
        .current_dir(cwd.path())
        .env("TMPDIR", tmp.path())
        .assert()
        .code(0)
        .stdout(predicate::str::contains("fixtures/finn_day30.claims.toml"))
        .stdout(predicate::str::contains("fixtures/joins/joins.claims.toml"))
        .stdout(predicate::str::contains("/tmp").not());
    assert_eq!(std::fs::read_dir(cwd.path()).unwrap().count(), 0);
    assert_eq!(std::fs::read_dir(tmp.path()).unwrap().count(), 0);
}

#[test]
fn reproduce_of_a_directory_that_is_not_one_is_exit_2() {
    let cwd = tempfile::tempdir().unwrap();
    Command::cargo_bin("tribez")
        .unwrap()
        .args(["reproduce", "no-such-dir"])
        .current_dir(cwd.path())
        .assert()
        .code(2)
        .stderr(predicate::str::contains("no-such-dir: not a directory"));
}

/// The summary line that README.md and the user guide show for `tribez reproduce` is the one the
/// program prints (the documents drift when a claim file is added).
#[test]
fn the_documented_reproduce_summary_is_the_printed_one() {
    let out = Command::cargo_bin("tribez")
        .unwrap()
        .arg("reproduce")
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    let stdout = String::from_utf8(out.stdout).unwrap();
    let summary = stdout
        .lines()
        .rev()
        .find(|l| l.contains(" claims in "))
        .expect("a summary line");
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    for doc in ["README.md", "docs/guide.md"] {
        let text = std::fs::read_to_string(root.join(doc)).unwrap();
        let shown: Vec<&str> = text.lines().filter(|l| l.contains(" claims in ")).collect();
        assert!(!shown.is_empty(), "{doc} shows no reproduce summary");
        for line in shown {
            if line.contains(" reproduced, ") {
                assert_eq!(
                    line, summary,
                    "{doc} shows a stale `tribez reproduce` summary"
                );
            }
        }
    }
}
