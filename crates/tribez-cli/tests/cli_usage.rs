//! The command line as a new user types it (issue 10): negative numbers and points outside the
//! triangle as option values, sizes capped before anything is allocated, each `--format` offered
//! only where it works, `subdivide`'s modes and its split at a point on an edge.
//!
//! Expected values are hand derivations on Finn's worked example (fixtures/finn_day30.toml):
//! P = u²·p200 + 2uv·p110 + v²·p020 + 2uw·p101 + 2vw·p011 + w²·p002 with p200 = (0,0,0),
//! p110 = (1,0,2), p020 = (0,2,0), p101 = (0,1,0), p011 = (1,1,1), p002 = (0,2,1).

use std::path::{Path, PathBuf};

use assert_cmd::Command;
use predicates::prelude::*;

fn tribez() -> Command {
    Command::cargo_bin("tribez").expect("binary built")
}

fn finn() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../fixtures/finn_day30.toml")
}

/// Exit status 2 with an error whose first line contains every word in `words`.
fn fails_with(args: &[&str], words: &[&str]) {
    let out = tribez().args(args).assert().code(2).get_output().clone();
    assert!(out.stdout.is_empty());
    let err = String::from_utf8_lossy(&out.stderr).into_owned();
    let first = err.lines().next().unwrap_or_default();
    for w in words {
        assert!(first.contains(w), "{args:?}: {w:?} not in {first:?}");
    }
}

fn finn_str() -> String {
    finn().display().to_string()
}

#[test]
fn eval_takes_a_point_with_a_negative_coordinate() {
    // u = -1/2, v = 1, w = 1/2: (-1,0,-2) + (0,2,0) + (0,-1/2,0) + (1,1,1) + (0,1/2,1/4)
    tribez()
        .args(["eval", &finn_str(), "--at", "-1/2,1,1/2"])
        .assert()
        .code(0)
        .stdout(predicate::str::contains("(0, 3, -3/4)"));
}

#[test]
fn eval_takes_a_negative_cartesian_point() {
    tribez()
        .args(["eval", &finn_str(), "--cartesian", "--at", "-1,2"])
        .assert()
        .code(0);
}

#[test]
fn constructions_take_points_outside_the_triangle() {
    for args in [
        vec!["subdivide", "--at", "-1,1,1"],
        vec![
            "subpatch", "--vertex", "-1,1,1", "--vertex", "1,0,0", "--vertex", "0,1,0",
        ],
    ] {
        tribez().args(&args).arg(finn()).assert().code(0);
    }
    tribez()
        .args(["matrix", "subpatch", "--degree", "1"])
        .args([
            "--vertex", "-1,1,1", "--vertex", "1,0,0", "--vertex", "0,1,0",
        ])
        .assert()
        .code(0)
        // degree 1: the rows are the vertices themselves
        .stdout(predicate::str::contains("-1"));
}

#[test]
fn a_negative_count_is_a_clear_error() {
    fails_with(
        &["certify", &finn_str(), "--random", "-5"],
        &["--random", "-5", "whole number from 1 to 1000000"],
    );
    fails_with(
        &["certify", &finn_str(), "--random", "10", "--seed", "-1"],
        &["--seed", "whole number"],
    );
    fails_with(
        &["elevate", &finn_str(), "--by", "-2"],
        &["--by", "whole number"],
    );
    fails_with(
        &["matrix", "halve", "--degree", "2", "--simplex", "-1"],
        &["--simplex", "from 1 to 16"],
    );
    fails_with(&["halve", &finn_str(), "--edge", "-1,2"], &["--edge -1,2"]);
}

#[test]
fn random_point_counts_are_capped_before_allocating() {
    for n in ["18446744073709551615", "1000000000", "1000001", "0", "-1"] {
        fails_with(
            &["certify", &finn_str(), "--random", n],
            &["--random", "from 1 to 1000000"],
        );
    }
}

#[test]
fn matrix_degree_is_capped_before_any_arithmetic() {
    // n + m used to wrap, bypassing the 1000-row limit
    for (degree, simplex) in [
        ("18446744073709551615", "1"),
        ("18446744073709551614", "2"),
        ("1000", "1"),
    ] {
        fails_with(
            &["matrix", "halve", "--degree", degree, "--simplex", simplex],
            &["--degree", "1000 rows"],
        );
    }
    // below the limit: degree 9 on a segment, 10 rows
    tribez()
        .args([
            "matrix",
            "halve",
            "--degree",
            "9",
            "--simplex",
            "1",
            "--format",
            "json",
        ])
        .assert()
        .code(0);
}

#[test]
fn elevation_beyond_the_degree_limit_is_refused_before_adding() {
    fails_with(
        &["elevate", &finn_str(), "--by", "18446744073709551615"],
        &["--by", "degree 18446744073709551615", "limits (degree 200"],
    );
    fails_with(
        &["elevate", &finn_str(), "--by", "199"],
        &["degree 201", "200"],
    );
}

#[test]
fn latex_is_offered_only_where_it_works() {
    let with_latex = ["symbolic", "matrix"];
    let all = [
        "reproduce",
        "eval",
        "symbolic",
        "graph",
        "check",
        "certify",
        "blossom",
        "subpatch",
        "subdivide",
        "halve",
        "elevate",
        "matrix",
        "derivative",
        "tangent",
        "join",
    ];
    for cmd in all {
        let out = tribez()
            .args([cmd, "--help"])
            .assert()
            .code(0)
            .get_output()
            .clone();
        let help = String::from_utf8_lossy(&out.stdout).into_owned();
        let format_line = help
            .lines()
            .skip_while(|l| !l.contains("--format"))
            .take_while(|l| !l.contains("--output"))
            .collect::<Vec<_>>()
            .join(" ");
        assert!(format_line.contains("json"), "{cmd}: {format_line}");
        assert_eq!(
            format_line.contains("latex"),
            with_latex.contains(&cmd),
            "{cmd}: {format_line}"
        );
    }
    fails_with(
        &[
            "eval",
            &finn_str(),
            "--at",
            "1/3,1/3,1/3",
            "--format",
            "latex",
        ],
        &["latex"],
    );
    tribez()
        .args(["symbolic", &finn_str(), "--format", "latex"])
        .assert()
        .code(0);
    // piece 1 of halving edge 1,2 at degree 1: rows e1, (e1 + e2)/2
    tribez()
        .args(["matrix", "halve", "--degree", "1", "--format", "latex"])
        .assert()
        .code(0)
        .stdout(predicate::str::contains("\\frac{1}{2}"));
}

#[test]
fn subdivide_without_a_mode_names_both_modes() {
    let out = tribez()
        .arg("subdivide")
        .arg(finn())
        .assert()
        .code(2)
        .get_output()
        .clone();
    let err = String::from_utf8_lossy(&out.stderr).into_owned();
    assert!(err.contains("--at") && err.contains("--midpoints"), "{err}");
    tribez()
        .args(["subdivide", "--at", "1/3,1/3,1/3", "--midpoints"])
        .arg(finn())
        .assert()
        .code(2);
}

#[test]
fn subdivide_at_a_point_on_an_edge_gives_the_two_pieces_and_names_the_degenerate_one() {
    let out = tribez()
        .args(["subdivide", "--at", "1/2,1/2,0", "--format", "json"])
        .arg(finn())
        .assert()
        .code(0)
        .get_output()
        .clone();
    let j: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let pieces = j["pieces"].as_array().unwrap();
    assert_eq!(pieces.len(), 2);
    assert!(
        j["note"]
            .as_str()
            .unwrap()
            .contains("piece 3 is degenerate")
    );
    // piece 1 replaces corner 1 by t = (1/2, 1/2, 0); its corner control point is P(t) =
    // 2·(1/4)·p110 + (1/4)·p020 = (1/2, 1/2, 1); piece 2's corner 2 is the same point
    let pt = |p: &serde_json::Value, key: &str| p["patch"]["control_points"][key].clone();
    assert_eq!(
        pt(&pieces[0], "2,0,0"),
        serde_json::json!(["1/2", "1/2", "1"])
    );
    assert_eq!(
        pt(&pieces[1], "0,2,0"),
        serde_json::json!(["1/2", "1/2", "1"])
    );
    assert_eq!(
        pieces[0]["domain_in_parent"],
        serde_json::json!([["1/2", "1/2", "0"], ["0", "1", "0"], ["0", "0", "1"]])
    );
    // text: a TOML document whose first line is the note as a comment
    let out = tribez()
        .args(["subdivide", "--at", "0,1/3,2/3"])
        .arg(finn())
        .assert()
        .code(0)
        .get_output()
        .clone();
    let text = String::from_utf8_lossy(&out.stdout).into_owned();
    assert!(
        text.starts_with("# ")
            && text
                .lines()
                .next()
                .unwrap()
                .contains("piece 1 is degenerate")
    );
    assert_eq!(text.matches("[[pieces]]").count(), 2);
    assert!(text.contains("piece 2 of 3") && text.contains("piece 3 of 3"));
}

#[test]
fn subdivide_at_a_corner_stays_an_error() {
    fails_with(
        &["subdivide", &finn_str(), "--at", "0,1,0"],
        &["--at 0,1,0", "corner 2"],
    );
}

#[test]
fn usage_errors_are_one_line() {
    for args in [
        vec!["eval", "--no-such-option"],
        vec!["subdivide"],
        vec!["matrix", "halve", "--degree", "x"],
        vec!["frobnicate"],
    ] {
        let out = tribez().args(&args).assert().code(2).get_output().clone();
        let err = String::from_utf8_lossy(&out.stderr).into_owned();
        assert_eq!(err.lines().count(), 1, "{args:?}: {err}");
        assert!(err.starts_with("tribez: "), "{err}");
    }
    // without a command: the help, on standard error
    let out = tribez().assert().code(2).get_output().clone();
    assert!(String::from_utf8_lossy(&out.stderr).contains("Commands:"));
}

/// `--algorithm` is one flag: `check` offers casteljau and bernstein (the bound of `--tolerance
/// bound`), `certify` also `all`; any other value is one line naming the flag and the values.
#[test]
fn algorithm_values_are_one_line_errors_naming_the_flag() {
    let f = finn_str();
    let peers = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../fixtures/peers");
    let (patch, results) = (
        peers.join("peer_cubic.toml").display().to_string(),
        peers.join("bezier_results.csv").display().to_string(),
    );
    for bad in ["all", "horner", "Casteljau"] {
        fails_with(
            &[
                "check",
                "--patch",
                &patch,
                "--results",
                &results,
                "--algorithm",
                bad,
            ],
            &[
                "--algorithm",
                &format!("`{bad}`"),
                "known: casteljau, bernstein)",
            ],
        );
    }
    fails_with(
        &["certify", &f, "--random", "5", "--algorithm", "horner"],
        &[
            "--algorithm",
            "`horner`",
            "known: casteljau, bernstein, all)",
        ],
    );
    for good in ["casteljau", "bernstein", "all"] {
        tribez()
            .args(["certify", &f, "--random", "5", "--algorithm", good])
            .assert()
            .code(0);
    }
    tribez()
        .args(["check", "--patch", &patch, "--results", &results])
        .args([
            "--precision",
            "f64",
            "--tolerance",
            "cond=9",
            "--algorithm",
            "bernstein",
        ])
        .assert()
        .code(0);
}
