//! Helpers shared by the command-line tests (`mod common;` in each test file): the binary, the
//! fixtures, temporary files, and the checks of a run on bad input (exit status 2, nothing on
//! standard output, one line on standard error, no file written).

// each test file uses some of the helpers
#![allow(dead_code)]

use std::path::{Path, PathBuf};

use assert_cmd::Command;

/// The `tribez` binary of this build.
pub fn tribez() -> Command {
    Command::cargo_bin("tribez").expect("binary built")
}

/// The repository's `fixtures/` folder.
pub fn fixtures() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../fixtures")
}

/// Write `bytes` to `dir/name` and return the path.
pub fn write(dir: &Path, name: &str, bytes: impl AsRef<[u8]>) -> PathBuf {
    let p = dir.join(name);
    std::fs::write(&p, bytes).expect("write temp file");
    p
}

/// The names in `dir`, sorted: compared before and after a failed run, it shows that the run
/// wrote no file (no output, no temporary left behind).
pub fn listing(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .expect("read the directory")
        .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

/// `stderr` as text, checked to be exactly one line.
pub fn one_line(stderr: &[u8]) -> String {
    let text = String::from_utf8_lossy(stderr).into_owned();
    assert_eq!(text.lines().count(), 1, "one line expected: {text:?}");
    text
}

/// Run `cmd` on bad input: exit status 2, nothing on standard output, one line on standard
/// error containing every fragment; returns that line.
pub fn fails(cmd: &mut Command, fragments: &[&str]) -> String {
    let out = cmd.output().expect("run tribez");
    let err = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(out.stdout.is_empty(), "nothing on stdout: {err}");
    assert_eq!(err.lines().count(), 1, "one line: {err}");
    for f in fragments {
        assert!(err.contains(f), "expected `{f}` in: {err}");
    }
    err
}
