//! Writing output safely (issue 10): a failed write to standard output is an error, a closed
//! pipe is not; `-o` writes only regular files, keeps their permissions and never follows or
//! replaces a link; a run that exits 2 leaves no output file at all.

use std::path::{Path, PathBuf};
use std::process::Stdio;

use assert_cmd::cargo::CommandCargoExt;

mod common;
use common::{fixtures, listing, one_line, tribez};

fn finn() -> PathBuf {
    fixtures().join("finn_day30.toml")
}

#[test]
fn a_full_disk_on_standard_output_is_exit_2_with_one_line() {
    if !Path::new("/dev/full").exists() {
        return; // only where the device exists (Linux)
    }
    let full = std::fs::OpenOptions::new()
        .write(true)
        .open("/dev/full")
        .unwrap();
    let out = std::process::Command::cargo_bin("tribez")
        .unwrap()
        .args(["eval", "--at", "1/2,1/3,1/6"])
        .arg(finn())
        .stdout(Stdio::from(full))
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = one_line(&out.stderr);
    assert!(
        err.contains("standard output") && err.contains("cannot write"),
        "{err}"
    );
}

#[test]
fn help_into_a_full_disk_is_an_error_too() {
    if !Path::new("/dev/full").exists() {
        return;
    }
    let full = std::fs::OpenOptions::new()
        .write(true)
        .open("/dev/full")
        .unwrap();
    let out = std::process::Command::cargo_bin("tribez")
        .unwrap()
        .args(["eval", "--help"])
        .stdout(Stdio::from(full))
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    one_line(&out.stderr);
}

#[test]
fn a_closed_pipe_is_quiet() {
    let mut child = std::process::Command::cargo_bin("tribez")
        .unwrap()
        .arg("reproduce")
        .arg(fixtures())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    drop(child.stdout.take()); // the reader goes away before anything is written
    let out = child.wait_with_output().unwrap();
    assert!(
        out.stderr.is_empty(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert_eq!(out.status.code(), Some(0));
}

#[test]
fn output_file_is_written_whole_and_no_temporary_stays() {
    let dir = tempfile::tempdir().unwrap();
    let target = dir.path().join("value.json");
    tribez()
        .args(["eval", "--at", "1/2,1/3,1/6", "--format", "json", "-o"])
        .arg(&target)
        .arg(finn())
        .assert()
        .code(0)
        .stdout("");
    let text = std::fs::read_to_string(&target).unwrap();
    // Finn's worked example at (1/2, 1/3, 1/6) is (4/9, 5/9, 29/36) (README, hand derivation)
    assert!(text.contains("4/9") && text.contains("29/36"), "{text}");
    assert_eq!(listing(dir.path()), ["value.json"]);
}

#[cfg(unix)]
#[test]
fn output_keeps_the_permissions_of_the_file_it_replaces() {
    use std::os::unix::fs::PermissionsExt;
    let dir = tempfile::tempdir().unwrap();
    let target = dir.path().join("private.txt");
    std::fs::write(&target, "old").unwrap();
    std::fs::set_permissions(&target, std::fs::Permissions::from_mode(0o600)).unwrap();
    tribez()
        .args(["eval", "--at", "1/2,1/3,1/6", "-o"])
        .arg(&target)
        .arg(finn())
        .assert()
        .code(0);
    let md = std::fs::metadata(&target).unwrap();
    assert_eq!(md.permissions().mode() & 0o7777, 0o600);
    assert_ne!(std::fs::read_to_string(&target).unwrap(), "old");
}

#[cfg(unix)]
#[test]
fn output_refuses_a_symlink_and_leaves_link_and_target_alone() {
    let dir = tempfile::tempdir().unwrap();
    let aim = dir.path().join("precious");
    std::fs::write(&aim, "keep me").unwrap();
    let link = dir.path().join("out.txt");
    std::os::unix::fs::symlink(&aim, &link).unwrap();
    let out = tribez()
        .args(["eval", "--at", "1/2,1/3,1/6", "-o"])
        .arg(&link)
        .arg(finn())
        .assert()
        .code(2)
        .get_output()
        .clone();
    let err = one_line(&out.stderr);
    assert!(err.contains("symbolic link"), "{err}");
    assert_eq!(std::fs::read_to_string(&aim).unwrap(), "keep me");
    assert!(
        std::fs::symlink_metadata(&link)
            .unwrap()
            .file_type()
            .is_symlink()
    );
    assert_eq!(listing(dir.path()), ["out.txt", "precious"]);
}

#[cfg(unix)]
#[test]
fn output_refuses_devices_and_directories() {
    let dir = tempfile::tempdir().unwrap();
    for (target, word) in [
        (PathBuf::from("/dev/null"), "not a regular file"),
        (dir.path().to_path_buf(), "directory"),
    ] {
        let out = tribez()
            .args(["eval", "--at", "1/2,1/3,1/6", "-o"])
            .arg(&target)
            .arg(finn())
            .assert()
            .code(2)
            .get_output()
            .clone();
        let err = one_line(&out.stderr);
        assert!(err.contains(word), "{err}");
    }
    assert!(listing(dir.path()).is_empty());
}

#[test]
fn a_run_that_exits_2_writes_no_junit_file() {
    // the JUnit report is ready before the format turns out to be unavailable
    let dir = tempfile::tempdir().unwrap();
    let junit = dir.path().join("junit.xml");
    tribez()
        .arg("check")
        .arg(fixtures().join("finn_day30.claims.toml"))
        .args(["--format", "latex", "--junit"])
        .arg(&junit)
        .assert()
        .code(2);
    assert!(listing(dir.path()).is_empty(), "{:?}", listing(dir.path()));
}

#[test]
fn a_run_that_exits_2_writes_no_baseline_file() {
    // the baseline to record is ready before the baseline to compare turns out to be missing
    let dir = tempfile::tempdir().unwrap();
    let record = dir.path().join("new.json");
    tribez()
        .arg("check")
        .arg(fixtures().join("finn_day30.claims.toml"))
        .arg("--record-baseline")
        .arg(&record)
        .arg("--baseline")
        .arg(dir.path().join("missing.json"))
        .assert()
        .code(2);
    assert!(listing(dir.path()).is_empty(), "{:?}", listing(dir.path()));
}

#[test]
fn one_file_for_two_outputs_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let same = dir.path().join("r.xml");
    tribez()
        .arg("check")
        .arg(fixtures().join("finn_day30.claims.toml"))
        .arg("--junit")
        .arg(&same)
        .arg("-o")
        .arg(&same)
        .assert()
        .code(2);
    assert!(listing(dir.path()).is_empty());
}

#[test]
fn a_successful_run_commits_every_output_file() {
    let dir = tempfile::tempdir().unwrap();
    let (junit, report) = (dir.path().join("j.xml"), dir.path().join("r.txt"));
    tribez()
        .arg("check")
        .arg(fixtures().join("finn_day30.claims.toml"))
        .arg("--junit")
        .arg(&junit)
        .arg("-o")
        .arg(&report)
        .assert()
        .code(0);
    assert!(
        std::fs::read_to_string(&junit)
            .unwrap()
            .contains("<testsuite")
    );
    assert!(!std::fs::read_to_string(&report).unwrap().is_empty());
    assert_eq!(listing(dir.path()), ["j.xml", "r.txt"]);
}
