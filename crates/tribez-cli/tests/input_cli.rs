//! Input at the edges (issue 10): files that are not regular files, too large, not UTF-8 or
//! with a byte-order mark, CSV header lines, and directory walks through symbolic links and
//! FIFOs. Bad input exits with status 2 and one line naming the file; nothing hangs.

#![cfg(unix)]

use std::os::unix::fs::symlink;
use std::path::Path;

use assert_cmd::Command;

mod common;
use common::{fails, write};

/// Finn's worked example (day 30); at (1/2, 1/3, 1/6) it is (4/9, 5/9, 29/36) (his notes).
const FINN: &str = "degree = 2\n[control_points]\n\"2,0,0\" = [\"0\", \"0\", \"0\"]\n\"1,1,0\" = [\"1\", \"0\", \"2\"]\n\"0,2,0\" = [\"0\", \"2\", \"0\"]\n\"1,0,1\" = [\"0\", \"1\", \"0\"]\n\"0,1,1\" = [\"1\", \"1\", \"1\"]\n\"0,0,2\" = [\"0\", \"2\", \"1\"]\n";
const AT: &str = "1/2,1/3,1/6";
const VALUE: &str = "(4/9, 5/9, 29/36)";

/// The binary, with a time limit (a hang on a FIFO or a device would be a failure).
fn tribez() -> Command {
    let mut c = common::tribez();
    c.timeout(std::time::Duration::from_secs(60));
    c
}

fn mkfifo(path: &Path) {
    let ok = std::process::Command::new("mkfifo").arg(path).status();
    assert!(ok.is_ok_and(|s| s.success()), "mkfifo {}", path.display());
}

fn eval(patch: &Path) -> Command {
    let mut c = tribez();
    c.args(["eval", "--at", AT]).arg(patch);
    c
}

#[test]
fn a_device_a_fifo_or_a_directory_is_not_read_as_a_patch() {
    let d = tempfile::tempdir().unwrap();
    let zero = d.path().join("zero.toml");
    symlink("/dev/zero", &zero).unwrap();
    fails(
        &mut eval(&zero),
        &["zero.toml: a device, not a regular file"],
    );
    let random = d.path().join("random.json");
    symlink("/dev/urandom", &random).unwrap();
    fails(
        &mut eval(&random),
        &["random.json: a device, not a regular file"],
    );
    let fifo = d.path().join("fifo.toml");
    mkfifo(&fifo);
    fails(
        &mut eval(&fifo),
        &["fifo.toml: a FIFO (named pipe), not a regular file"],
    );
    let dir = d.path().join("dir.toml");
    std::fs::create_dir(&dir).unwrap();
    fails(
        &mut eval(&dir),
        &["dir.toml: a directory, not a regular file"],
    );
}

#[test]
fn a_file_above_the_size_limit_is_refused_before_reading() {
    let d = tempfile::tempdir().unwrap();
    let big = d.path().join("big.toml");
    // a sparse file: no disk space, no time
    let f = std::fs::File::create(&big).unwrap();
    f.set_len((256 << 20) + 1).unwrap();
    fails(
        &mut eval(&big),
        &["big.toml: the file is larger than the limit of 256 MiB"],
    );
}

#[test]
fn a_byte_order_mark_is_ignored_in_toml_json_and_csv() {
    let d = tempfile::tempdir().unwrap();
    let toml = write(d.path(), "p.toml", format!("\u{feff}{FINN}"));
    let out = eval(&toml).output().unwrap();
    assert!(out.status.success(), "{out:?}");
    assert!(String::from_utf8_lossy(&out.stdout).contains(VALUE));
    let json = r#"{"degree": 2, "control_points": {"2,0,0": ["0","0","0"], "1,1,0": ["1","0","2"],
        "0,2,0": ["0","2","0"], "1,0,1": ["0","1","0"], "0,1,1": ["1","1","1"], "0,0,2": ["0","2","1"]}}"#;
    let json = write(d.path(), "p.json", format!("\u{feff}{json}"));
    let out = eval(&json).output().unwrap();
    assert!(out.status.success(), "{out:?}");
    assert!(String::from_utf8_lossy(&out.stdout).contains(VALUE));
    let pts = write(d.path(), "pts.csv", format!("\u{feff}{AT}\n"));
    let out = tribez()
        .args(["eval", "--points"])
        .arg(&pts)
        .arg(&toml)
        .output()
        .unwrap();
    assert!(out.status.success(), "{out:?}");
    assert!(String::from_utf8_lossy(&out.stdout).contains(VALUE));
}

#[test]
fn invalid_utf8_is_located_by_line() {
    let d = tempfile::tempdir().unwrap();
    let mut bytes = FINN.as_bytes().to_vec();
    // line 4 is `"1,1,0" = ...`: break its first byte
    let line4 = FINN.match_indices('\n').nth(2).unwrap().0 + 1;
    bytes[line4] = 0xff;
    let p = write(d.path(), "p.toml", &bytes);
    fails(
        &mut eval(&p),
        &["p.toml:4:1: the file is not UTF-8 text (invalid byte 0xff)"],
    );
    let pts = write(d.path(), "pts.csv", b"1,0,0\n1/2,\xc3\x28,0\n");
    let toml = write(d.path(), "finn.toml", FINN);
    fails(
        tribez().args(["eval", "--points"]).arg(&pts).arg(&toml),
        &["pts.csv:2:5: the file is not UTF-8 text (invalid byte 0xc3)"],
    );
}

#[test]
fn a_points_file_may_have_one_header_line() {
    let d = tempfile::tempdir().unwrap();
    let toml = write(d.path(), "p.toml", FINN);
    let pts = write(d.path(), "pts.csv", format!("u,v,w\n{AT}\n"));
    let out = tribez()
        .args(["eval", "--points"])
        .arg(&pts)
        .arg(&toml)
        .output()
        .unwrap();
    assert!(out.status.success(), "{out:?}");
    assert!(String::from_utf8_lossy(&out.stdout).contains(VALUE));
    let pts = write(d.path(), "two.csv", format!("u,v,w\nu,v,w\n{AT}\n"));
    fails(
        tribez().args(["eval", "--points"]).arg(&pts).arg(&toml),
        &["two.csv:2:1: field 1"],
    );
    let zero = d.path().join("zero.csv");
    symlink("/dev/zero", &zero).unwrap();
    fails(
        tribez().args(["eval", "--points"]).arg(&zero).arg(&toml),
        &["zero.csv: a device, not a regular file"],
    );
}

#[test]
fn a_claim_files_patch_that_is_a_device_is_refused() {
    let d = tempfile::tempdir().unwrap();
    symlink("/dev/zero", d.path().join("zero.toml")).unwrap();
    let c = write(
        d.path(),
        "c.claims.toml",
        "patch = \"zero.toml\"\n[[claim]]\nid = \"a\"\nop = \"eval\"\nat = [\"1\",\"0\",\"0\"]\nexpect = [\"0\",\"0\",\"0\"]\n",
    );
    fails(
        tribez().arg("check").arg(&c),
        &["zero.toml: a device, not a regular file"],
    );
    let fifo = d.path().join("f.claims.toml");
    mkfifo(&fifo);
    fails(
        tribez().arg("check").arg(&fifo),
        &["f.claims.toml: a FIFO (named pipe), not a regular file"],
    );
}

/// `check DIR` through links to `.`, `..` and `/`, a link to itself, a second name of a claim
/// file and a FIFO with a claim file's name: the one claim file is judged once, the rest noted.
#[test]
fn check_dir_walks_each_file_once_and_skips_what_is_not_a_file() {
    let d = tempfile::tempdir().unwrap();
    let root = d.path();
    write(root, "finn.toml", FINN);
    std::fs::create_dir(root.join("sub")).unwrap();
    write(
        root,
        "sub/a.claims.toml",
        "patch = \"../finn.toml\"\n[[claim]]\nid = \"worked\"\nop = \"eval\"\nat = [\"1/2\",\"1/3\",\"1/6\"]\nexpect = [\"4/9\",\"5/9\",\"29/36\"]\n",
    );
    symlink(".", root.join("dot1")).unwrap();
    symlink(".", root.join("sub/dot2")).unwrap();
    symlink("..", root.join("sub/up")).unwrap();
    symlink("/", root.join("slash")).unwrap();
    symlink("self.claims.toml", root.join("self.claims.toml")).unwrap();
    symlink("sub/a.claims.toml", root.join("b.claims.toml")).unwrap();
    mkfifo(&root.join("x.claims.toml"));
    let out = tribez()
        .args(["check", "--format", "json"])
        .arg(root)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{err}");
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert_eq!(
        stdout.matches("\"worked\"").count(),
        1,
        "judged once: {stdout}"
    );
    for note in [
        "dot1: skipped: a symbolic link to a directory is not followed",
        "slash: skipped: a symbolic link to a directory is not followed",
        "sub/dot2: skipped",
        "sub/up: skipped",
        "self.claims.toml: skipped: a symbolic link that cannot be followed",
        "x.claims.toml: skipped: a FIFO (named pipe), not a regular file",
        "b.claims.toml: skipped: the same file as",
    ] {
        assert!(err.contains(note), "expected `{note}` in:\n{err}");
    }
}

/// The plane patch P(u, v, w) = (v, w) (corners (0,0), (1,0), (0,1)): a results row
/// `u,v,w,x,y` is right when x = v and y = w.
const PLANE: &str = "degree = 1\n[control_points]\n\"1,0,0\" = [\"0\", \"0\"]\n\"0,1,0\" = [\"1\", \"0\"]\n\"0,0,1\" = [\"0\", \"1\"]\n";

fn batch(dir: &Path, results: &Path, extra: &[&str]) -> std::process::Output {
    let patch = write(dir, "plane.toml", PLANE);
    tribez()
        .arg("check")
        .arg("--patch")
        .arg(patch)
        .arg("--results")
        .arg(results)
        .args(extra)
        .output()
        .unwrap()
}

fn batch_fails(dir: &Path, results: &Path, extra: &[&str], fragments: &[&str]) {
    let out = batch(dir, results, extra);
    let err = String::from_utf8_lossy(&out.stderr).to_string();
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert_eq!(err.lines().count(), 1, "one line: {err}");
    for f in fragments {
        assert!(err.contains(f), "expected `{f}` in: {err}");
    }
}

fn batch_status(dir: &Path, results: &Path, extra: &[&str]) -> (i32, String) {
    let out = batch(dir, results, extra);
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).to_string() + &String::from_utf8_lossy(&out.stderr),
    )
}

#[test]
fn json_lines_are_parsed_as_json() {
    let d = tempfile::tempdir().unwrap();
    let ok = write(
        d.path(),
        "ok.jsonl",
        "[\"1/2\", 0.25, 0.25, 0.25, \"1/4\"]\n[1, 0, 0, 0, null]\n",
    );
    let (code, out) = batch_status(d.path(), &ok, &[]);
    assert_eq!(code, 1, "the null row fails, the first passes: {out}");
    assert!(
        out.contains("1 passed") || out.contains("passed: 1"),
        "{out}"
    );
    // a comma inside a string does not split it: one field, not a number
    let r = write(
        d.path(),
        "comma.jsonl",
        "[\"1/2\", \"1/4,1/4\", 0.25, 0.25, 0.25]\n",
    );
    batch_fails(d.path(), &r, &[], &["comma.jsonl:1:9: malformed number"]);
    // text after the array, a bare word, a missing bracket: not JSON
    for (name, text, at) in [
        (
            "after.jsonl",
            "[0.5, 0.25, 0.25, 0.25, 0.25] x\n",
            "after.jsonl:1:31: invalid JSON",
        ),
        (
            "word.jsonl",
            "[0.5, 0.25, 0.25, 0.25, abc]\n",
            "word.jsonl:1:25: invalid JSON",
        ),
        (
            "open.jsonl",
            "[0.5, 0.25, 0.25, 0.25, 0.25\n",
            "open.jsonl:1:28: invalid JSON: EOF while parsing a list",
        ),
    ] {
        let r = write(d.path(), name, text);
        batch_fails(d.path(), &r, &[], &[at, "invalid JSON"]);
    }
}

#[test]
fn results_may_start_with_a_byte_order_mark_or_a_csv_header() {
    let d = tempfile::tempdir().unwrap();
    for (name, text) in [
        ("bom.csv", "\u{feff}0.5,0.25,0.25,0.25,0.25\n"),
        ("bom.jsonl", "\u{feff}[0.5,0.25,0.25,0.25,0.25]\n"),
        ("bom.json", "\u{feff}[[0.5,0.25,0.25,0.25,0.25]]\n"),
        ("header.csv", "u,v,w,x,y\n0.5,0.25,0.25,0.25,0.25\n"),
        (
            "both.csv",
            "\u{feff}# from numpy\n\"u\",\"v\",\"w\",\"x\",\"y\"\n0.5,0.25,0.25,0.25,0.25\n",
        ),
    ] {
        let r = write(d.path(), name, text);
        let (code, out) = batch_status(d.path(), &r, &[]);
        assert_eq!(code, 0, "{name}: {out}");
    }
    let r = write(
        d.path(),
        "two.csv",
        "u,v,w,x,y\nu,v,w,x,y\n0.5,0.25,0.25,0.25,0.25\n",
    );
    batch_fails(d.path(), &r, &[], &["two.csv:2:1: malformed number"]);
    let r = write(d.path(), "short.csv", "u,v,w,x\n0.5,0.25,0.25,0.25,0.25\n");
    batch_fails(
        d.path(),
        &r,
        &[],
        &["short.csv:1: a header line of 4 names, expected 5"],
    );
}

#[test]
fn an_overflowing_number_is_a_failed_row_whatever_its_exponent() {
    let d = tempfile::tempdir().unwrap();
    for big in ["1e400", "1e999999", "-1e999999999999"] {
        let r = write(
            d.path(),
            "big.csv",
            format!("0.5,0.25,0.25,0.25,0.25\n0.5,0.25,0.25,{big},0.25\n"),
        );
        let (code, out) = batch_status(d.path(), &r, &["--precision", "f64"]);
        assert_eq!(code, 1, "{big}: a failed row, not an aborted run: {out}");
        assert!(out.contains("overflows f64"), "{big}: {out}");
    }
}

#[test]
fn results_that_never_end_a_line_or_are_not_utf8() {
    let d = tempfile::tempdir().unwrap();
    let zero = d.path().join("zero.csv");
    symlink("/dev/zero", &zero).unwrap();
    batch_fails(
        d.path(),
        &zero,
        &[],
        &["zero.csv:1: the line is longer than the limit of 16 MiB"],
    );
    let zero = d.path().join("zero.json");
    symlink("/dev/zero", &zero).unwrap();
    batch_fails(
        d.path(),
        &zero,
        &[],
        &["zero.json:1: the line is longer than the limit"],
    );
    let r = write(
        d.path(),
        "bad.csv",
        b"0.5,0.25,0.25,0.25,0.25\n0.5,\xff,0.25,0.25,0.25\n",
    );
    batch_fails(
        d.path(),
        &r,
        &[],
        &["bad.csv:2:5: the file is not UTF-8 text (invalid byte 0xff)"],
    );
}

#[test]
fn a_bad_point_is_reported_before_a_patch_the_float_program_refuses() {
    // The points are read while the evaluators are prepared; the bad point still comes first,
    // as when the points were read before the evaluators.
    let d = tempfile::tempdir().unwrap();
    let toml = write(
        d.path(),
        "big.toml",
        "degree = 1\n[control_points]\n\"1,0,0\" = [\"1e39\", \"0\"]\n\"0,1,0\" = [\"0\", \"0\"]\n\"0,0,1\" = [\"0\", \"0\"]\n",
    );
    let pts = write(d.path(), "pts.csv", "1/3,1/3,1/3\n1/2,x,1/2\n");
    fails(
        tribez()
            .args(["eval", "--float", "f32", "--points"])
            .arg(&pts)
            .arg(&toml),
        &["pts.csv:2:5: field 2: `x`: not a number"],
    );
    let good = write(d.path(), "good.csv", "1/3,1/3,1/3\n");
    fails(
        tribez()
            .args(["eval", "--float", "f32", "--points"])
            .arg(&good)
            .arg(&toml),
        &["big.toml: f32: a control point overflows f32"],
    );
}
