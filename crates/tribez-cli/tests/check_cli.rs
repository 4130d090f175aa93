//! `tribez check`, `tribez certify`, baselines: behaviour and every kind of bad input.

use std::path::{Path, PathBuf};

use predicates::prelude::*;

mod common;
use common::{fixtures, tribez, write};

const QUAD: &str = "degree = 2\n[control_points]\n\"2,0,0\" = [0, 0, 0]\n\"1,1,0\" = [1, 0, 2]\n\"0,2,0\" = [0, 2, 0]\n\"1,0,1\" = [0, 1, 0]\n\"0,1,1\" = [1, 1, 1]\n\"0,0,2\" = [0, 2, 1]\n";

fn claim_dir(claims: &str) -> tempfile::TempDir {
    let d = tempfile::tempdir().unwrap();
    write(d.path(), "quad.toml", QUAD);
    write(
        d.path(),
        "c.claims.toml",
        format!("patch = \"quad.toml\"\n{claims}"),
    );
    d
}

#[test]
fn float_claims_of_an_independent_computation_pass() {
    tribez()
        .args(["check"])
        .arg(fixtures().join("certify"))
        .assert()
        .success()
        .stdout(
            predicate::str::contains("21 claims in 1 file: 21 passed")
                .and(predicate::str::contains("Errors of float claims in ULPs")),
        );
}

#[test]
fn exact_and_tolerance_claims() {
    // Finn's notes, worked example (a): [4/9, 5/9, 29/36] exactly.
    let d = claim_dir(
        "[[claim]]\nop = \"eval\"\nat = [\"1/2\", \"1/3\", \"1/6\"]\nexpect = [\"4/9\", \"5/9\", \"29/36\"]\n\
         [[claim]]\nop = \"eval\"\nat = [\"1/2\", \"1/3\", \"1/6\"]\nexpect = [\"0.4444\", \"0.5556\", \"0.8056\"]\ntolerance = \"abs=1e-4\"\n\
         [[claim]]\nop = \"eval\"\nat = [\"1/2\", \"1/3\", \"1/6\"]\nexpect = [\"0.4444\", \"0.5556\", \"0.8056\"]\ntolerance = \"rel=1e-4\"\n",
    );
    tribez()
        .arg("check")
        .arg(d.path())
        .assert()
        .success()
        .stdout(predicate::str::contains("3 claims in 1 file: 3 passed"));
}

#[test]
fn a_failing_float_claim_shows_decimal_hex_exact_ulps_and_tolerance() {
    // 4/9 rounded to f64 is 0.4444444444444444 (correctly rounded); one step up is ...46.
    let d = claim_dir(
        "[[claim]]\nid = \"off\"\nop = \"eval\"\nprecision = \"f64\"\ntolerance = \"correctly_rounded\"\nat = [\"0.5\", \"0.3333333333333333\", \"0.16666666666666666\"]\nexpect = [\"0.4444444444444445\", \"0.5555555555555555\", \"0.8055555555555556\"]\n",
    );
    tribez().arg("check").arg(d.path()).assert().code(1).stdout(
        predicate::str::contains("FAILED")
            .and(predicate::str::contains(
                "breaks tolerance `correctly_rounded`",
            ))
            .and(predicate::str::contains("0x1.c71c71c71c71dp-2"))
            .and(predicate::str::contains("ulp")),
    );
}

#[test]
fn json_and_junit_reports() {
    let d = claim_dir(
        "[[claim]]\nid = \"bad\"\nop = \"eval\"\nat = [\"1/2\", \"1/3\", \"1/6\"]\nexpect = [\"4/9\", \"5/9\", \"29/37\"]\n",
    );
    let junit = d.path().join("report.xml");
    let out = tribez()
        .arg("check")
        .arg(d.path())
        .args(["--format", "json", "--junit"])
        .arg(&junit)
        .assert()
        .code(1)
        .get_output()
        .stdout
        .clone();
    let v: serde_json::Value = serde_json::from_slice(&out).unwrap();
    assert_eq!(v["summary"]["failed"], 1);
    assert_eq!(v["claims"][0]["verdict"], "FAILED");
    let xml = std::fs::read_to_string(&junit).unwrap();
    assert!(
        xml.contains("<testsuite name=\"check\" tests=\"1\" failures=\"1\""),
        "{xml}"
    );
    assert!(
        xml.contains("<failure") && xml.contains("bad: claimed"),
        "{xml}"
    );
}

#[test]
fn bad_claims_are_located_errors() {
    let cases = [
        (
            "[[claim]]\nop = \"eval\"\nat = [\"1/2\", \"1/3\", \"1/6\"]\nexpect = [0, 0, 0]\ntolerance = \"ulp=3\"\n",
            "unknown tolerance `ulp=3`",
            ":6",
        ),
        (
            "[[claim]]\nop = \"evaluate\"\nat = [\"1/2\", \"1/3\", \"1/6\"]\nexpect = [0, 0, 0]\n",
            "unknown operation `evaluate`",
            ":3",
        ),
        (
            "[[claim]]\nop = \"eval\"\nat = [\"1/2\", \"1/3\", \"1/6\"]\nexpect = [0, 0, 0]\ntolerance = \"ulps=1\"\n",
            "needs `precision",
            ":6",
        ),
        (
            "[[claim]]\nop = \"eval\"\nat = [\"1/2\", \"1/3\", \"1/6\"]\nexpect = [0, 0, 0]\nprecision = \"f16\"\n",
            "unknown precision `f16`",
            ":6",
        ),
        (
            "[[claim]]\nop = \"symbolic\"\nexpect = [\"u\", \"v\", \"w\"]\nprecision = \"f64\"\ntolerance = \"cond=2\"\n",
            "applies to `eval` claims only",
            ":6",
        ),
        (
            "[[claim]]\nop = \"eval\"\nat = [\"1/2\", \"1/3\", \"1/6\"]\nexpect = [0, 0, 0]\nprecision = \"f64\"\nalgorithm = \"horner\"\n",
            "unknown algorithm `horner`",
            ":7",
        ),
        (
            "[[claim]]\nop = \"eval\"\nat = [\"1/2\", \"1/3\", \"1/6\"]\nexpect = [0, 0, 0]\ntolerance = \"abs=-1\"\n",
            "must not be negative",
            ":6",
        ),
    ];
    for (claims, message, line) in cases {
        let d = claim_dir(claims);
        tribez()
            .arg("check")
            .arg(d.path().join("c.claims.toml"))
            .assert()
            .code(2)
            .stdout("")
            .stderr(
                predicate::str::contains(message)
                    .and(predicate::str::contains(format!("c.claims.toml{line}"))),
            );
    }
}

#[test]
fn usage_errors() {
    tribez()
        .arg("check")
        .assert()
        .code(2)
        .stderr(predicate::str::contains("give claim files"));
    tribez()
        .args(["check", "/no/such/file.claims.toml"])
        .assert()
        .code(2)
        .stderr(predicate::str::contains("no such file"));
    let d = tempfile::tempdir().unwrap();
    tribez()
        .arg("check")
        .arg(d.path())
        .assert()
        .code(2)
        .stderr(predicate::str::contains("no claim files"));
    tribez()
        .arg("check")
        .arg(d.path())
        .args(["--tolerance", "ulps=1"])
        .assert()
        .code(2)
        .stderr(predicate::str::contains("applies to batches"));
}

// ---------------------------------------------------------------------------------------------
// Batches

fn batch_dir(rows: &str, ext: &str) -> (tempfile::TempDir, PathBuf, PathBuf) {
    let d = tempfile::tempdir().unwrap();
    let patch = write(d.path(), "quad.toml", QUAD);
    let results = write(d.path(), &format!("results.{ext}"), rows);
    (d, patch, results)
}

fn batch(patch: &Path, results: &Path, extra: &[&str]) -> assert_cmd::assert::Assert {
    tribez()
        .arg("check")
        .arg("--patch")
        .arg(patch)
        .arg("--results")
        .arg(results)
        .args(extra)
        .assert()
}

// f64 de Casteljau of Finn's quadratic at (0.5, 1/3, 1/6), as Python computes it
// (fixtures/certify/gen_float_claims.py, claim f64-0): within 2 ulps, not all correctly rounded.
const ROW: &str = "0.5,0.3333333333333333,0.16666666666666666,0.4444444444444444,0.5555555555555555,0.8055555555555556";

#[test]
fn batch_passes_and_reports_the_filter() {
    let (_d, p, r) = batch_dir(&format!("# a comment\n{ROW}\n\n{ROW}\n"), "csv");
    batch(&p, &r, &["--precision", "f64", "--tolerance", "ulps=4"])
        .success()
        .stdout(
            predicate::str::contains("2 claims: 2 passed, 0 failed")
                .and(predicate::str::contains("fell back to exact arithmetic")),
        );
    batch(
        &p,
        &r,
        &["--precision", "f64", "--tolerance", "correctly_rounded"],
    )
    .code(1);
    // claim f64-3 of the same script is correctly rounded in every coordinate (checked there with fractions)
    let (_d, p, r) = batch_dir(
        "0x1p-30,0.5,0.4999999990686774,0.5,1.4999999981373549,0.75\n",
        "csv",
    );
    batch(
        &p,
        &r,
        &["--precision", "f64", "--tolerance", "correctly_rounded"],
    )
    .success();
}

#[test]
fn batch_json_lines() {
    let row = format!(
        "[{}]\n",
        ROW.split(',')
            .map(|x| format!("\"{x}\""))
            .collect::<Vec<_>>()
            .join(", ")
    );
    let (_d, p, r) = batch_dir(&format!("{row}{}", row.replace('"', "")), "jsonl");
    batch(
        &p,
        &r,
        &[
            "--precision",
            "f64",
            "--tolerance",
            "ulps=1",
            "--format",
            "json",
        ],
    )
    .success()
    .stdout(predicate::str::contains("\"passed\": 2"));
}

/// `rows` as Python's `json.dump(rows, f, indent=2)` writes them (one entry per line).
fn json_indent2(rows: &[Vec<&str>]) -> String {
    let rows: Vec<String> = rows
        .iter()
        .map(|r| format!("  [\n    {}\n  ]", r.join(",\n    ")))
        .collect();
    format!("[\n{}\n]", rows.join(",\n"))
}

#[test]
fn batch_one_json_array_of_rows() {
    // Pretty-printed: row k starts on line 2 + 8k. The second row has strings (a hex float, kept
    // exact) and is the same point as the first.
    let fields: Vec<&str> = ROW.split(',').collect();
    let mut quoted: Vec<String> = fields.iter().map(|x| format!("\"{x}\"")).collect();
    quoted[0] = "\"0x1p-1\"".into();
    let quoted: Vec<&str> = quoted.iter().map(String::as_str).collect();
    let text = json_indent2(&[fields.clone(), quoted]);
    assert!(text.lines().nth(9).unwrap().trim_start().starts_with('['));
    let (_d, p, r) = batch_dir(&text, "json");
    batch(&p, &r, &["--precision", "f64", "--tolerance", "ulps=4"])
        .success()
        .stdout(predicate::str::contains("2 claims: 2 passed, 0 failed"));
    // All on one line, as `json.dump(rows, f)` writes it; `.jsonl` too (the rule is the content).
    let one_line = format!("[[{ROW}], [{ROW}]]\n");
    for ext in ["json", "jsonl"] {
        let (_d, p, r) = batch_dir(&one_line, ext);
        batch(&p, &r, &["--precision", "f64", "--tolerance", "ulps=4"])
            .success()
            .stdout(predicate::str::contains("2 claims: 2 passed, 0 failed"));
    }
}

/// Numbers keep their text: exact mode reads 0.1 as 1/10. On the edge w = 0 the patch is
/// p(u, v, 0) = u² c200 + 2uv c110 + v² c020 = (2uv, 2v², 4uv) (by hand), so at (1/10, 9/10, 0)
/// it is exactly (0.18, 1.62, 0.36); a failing row is reported at the line where it starts.
#[test]
fn batch_json_array_numbers_are_exact_text_and_rows_report_their_start_line() {
    let good = vec!["0.1", "0.9", "0", "0.18", "1.62", "0.36"];
    let off = vec!["0.1", "0.9", "0", "0.18", "1.62", "0.36000000000000001"];
    let text = json_indent2(&[good.clone(), good.clone(), off, good]);
    let (_d, p, r) = batch_dir(&text, "json");
    batch(&p, &r, &[]).code(1).stdout(
        predicate::str::contains("4 claims: 3 passed, 1 failed")
            .and(predicate::str::contains("line 18: coordinate [2]"))
            .and(predicate::str::contains(
                "worst row (the largest error, computed exactly): line 18",
            )),
    );
}

#[test]
fn json_lines_in_a_json_file_still_work() {
    let (_d, p, r) = batch_dir(&format!("[{ROW}]\n\n[{ROW}]\n"), "json");
    batch(&p, &r, &["--precision", "f64", "--tolerance", "ulps=4"])
        .success()
        .stdout(predicate::str::contains("2 claims: 2 passed, 0 failed"));
}

#[test]
fn json_array_errors_name_file_line_and_column() {
    let fields: Vec<&str> = ROW.split(',').collect();
    let full = json_indent2(&[fields.clone(), fields.clone()]);
    let cases: Vec<(String, &str)> = vec![
        // the top-level array never closed
        (
            format!("[[{ROW}],\n [{ROW}]\n"),
            "results.json:3:1: invalid JSON: unexpected end of file: the array opened at line 1, column 1 is never closed",
        ),
        // a row never closed (cut inside the second row, which opens at line 10, column 3)
        (
            full[..full.len() - 20].to_string(),
            "the row opened at line 10, column 3 is never closed",
        ),
        // a row that is not an array
        (
            format!("[\n  [{ROW}],\n  0.5\n]"),
            "results.json:3:3: invalid JSON: expected a row (an array `[…]`), found `0`",
        ),
        (
            format!("[[{ROW}], {{\"a\": 1}}]"),
            "expected a row (an array `[…]`), found `{`",
        ),
        // an entry that is an array
        (
            format!("[[{ROW}],\n [0.5, [0.5], 0, 1, 2, 3]]"),
            "results.json:2:8: a row's entries must be numbers, strings or null",
        ),
        // wrong column count: located at the row's `[`
        (
            json_indent2(&[fields.clone(), fields[..5].to_vec()]),
            "results.json:10:3: 5 columns, expected 6",
        ),
        // a malformed number on its own line: line 15 (the fifth entry of the second row)
        (
            {
                let at = full.rfind("0.5555555555555555").unwrap();
                format!("{}0.55x5{}", &full[..at], &full[at + 18..])
            },
            "results.json:15:9: invalid JSON: expected `,` or `]`",
        ),
        // the same text as a JSON string: valid JSON, a malformed number
        (
            {
                let at = full.rfind("0.5555555555555555").unwrap();
                format!("{}\"0.55x5\"{}", &full[..at], &full[at + 18..])
            },
            "results.json:15:5: malformed number: `0.55x5`",
        ),
        // missing entries, commas and text after the array
        (
            format!("[[{ROW}],\n]"),
            "results.json:2:1: invalid JSON: expected a row",
        ),
        (
            format!("[[{ROW}] [{ROW}]]"),
            "expected ',' or ']' after a row, found `[`",
        ),
        (
            "[[0.5,,0.5,0,1,2]]".to_string(),
            "results.json:1:7: invalid JSON: expected value",
        ),
        (
            format!("[[{ROW}]]\nx"),
            "results.json:2:1: invalid JSON: unexpected text after the array of rows",
        ),
    ];
    for (text, message) in cases {
        let (_d, p, r) = batch_dir(&text, "json");
        batch(&p, &r, &["--precision", "f64", "--tolerance", "ulps=4"])
            .code(2)
            .stdout("")
            .stderr(predicate::str::contains(message));
    }
    let (_d, p, r) = batch_dir("[ ]", "json");
    batch(&p, &r, &["--precision", "f64"])
        .code(2)
        .stderr(predicate::str::contains("results.json: no result rows"));
}

#[test]
fn nan_inf_and_empty_fields_are_failed_claims() {
    let rows = format!(
        "{ROW}\n0.5,0.3333333333333333,0.16666666666666666,nan,0.5,0.5\n0.5,0.3333333333333333,0.16666666666666666,inf,0.5,0.5\n0.5,,0.5,0.1,0.5,0.5\n"
    );
    let (_d, p, r) = batch_dir(&rows, "csv");
    batch(&p, &r, &["--precision", "f64", "--tolerance", "ulps=1"])
        .code(1)
        .stdout(
            predicate::str::contains("4 claims: 1 passed, 3 failed").and(predicate::str::contains(
                "line 2: claimed coordinate [0] is not a finite number",
            )),
        );
}

#[test]
fn malformed_number_names_file_line_and_column() {
    let mut rows = String::new();
    for _ in 0..122 {
        rows += ROW;
        rows += "\n";
    }
    rows +=
        "0.5,0.3333333333333333,0.16666666666666666,0.4444444444444444,0.55x5,0.8055555555555556\n";
    let (_d, p, r) = batch_dir(&rows, "csv");
    batch(&p, &r, &["--precision", "f64", "--tolerance", "ulps=1"])
        .code(2)
        .stdout("")
        .stderr(predicate::str::contains(
            "results.csv:123:63: malformed number",
        ));
    batch(&p, &r, &[])
        .code(2)
        .stderr(predicate::str::contains("results.csv:123:63"));
}

#[test]
fn column_count_must_match_the_patch() {
    let (_d, p, r) = batch_dir("0.5,0.5,0,1,2\n", "csv");
    batch(&p, &r, &["--precision", "f64"])
        .code(2)
        .stderr(predicate::str::contains(
            "results.csv:1: 5 columns, expected 6",
        ));
    let (_d, p, r) = batch_dir("0.5,0.5,0,1,2,3\n", "csv");
    batch(&p, &r, &["--precision", "f64", "--cartesian"])
        .code(2)
        .stderr(predicate::str::contains("6 columns, expected 5"));
    let (_d, p, r) = batch_dir("[0.5, [0.5], 0, 1, 2, 3]\n", "jsonl");
    batch(&p, &r, &["--precision", "f64"])
        .code(2)
        .stderr(predicate::str::contains("results.jsonl:1"));
}

#[test]
fn batch_usage_errors() {
    let (_d, p, r) = batch_dir(&format!("{ROW}\n"), "csv");
    batch(&p, &r, &["--tolerance", "ulps=1"])
        .code(2)
        .stderr(predicate::str::contains("needs --precision"));
    batch(&p, &r, &["--precision", "f64", "--tolerance", "nearly"])
        .code(2)
        .stderr(predicate::str::contains("unknown tolerance `nearly`"));
    batch(&p, &r, &["--precision", "f16"])
        .code(2)
        .stderr(predicate::str::contains("unknown precision"));
    let (_d, p, r) = batch_dir("# nothing\n", "csv");
    batch(&p, &r, &[])
        .code(2)
        .stderr(predicate::str::contains("no result rows"));
}

#[test]
fn exact_batch_without_precision() {
    let (_d, p, r) = batch_dir(
        "1/2,1/3,1/6,4/9,5/9,29/36\n1/2,1/3,1/6,4/9,5/9,29/37\n",
        "csv",
    );
    batch(&p, &r, &[]).code(1).stdout(
        predicate::str::contains("2 claims: 1 passed, 1 failed")
            .and(predicate::str::contains("line 2")),
    );
}

#[test]
fn cartesian_batch() {
    // reference triangle: vertices (1, 0), (0, 1), (0, 0), so (x, y) = (λ0, λ1); (1/2, 1/3) is λ = (1/2, 1/3, 1/6).
    let (_d, p, r) = batch_dir("1/2,1/3,4/9,5/9,29/36\n", "csv");
    batch(&p, &r, &["--cartesian"]).success();
}

#[test]
fn baselines_catch_regressions() {
    let (d, p, r) = batch_dir(
        &format!(
            "{ROW}\n0.5,0.3333333333333333,0.16666666666666666,0.4444444444444445,0.5555555555555555,0.8055555555555556\n"
        ),
        "csv",
    );
    let base = d.path().join("base.json");
    batch(
        &p,
        &r,
        &[
            "--precision",
            "f64",
            "--tolerance",
            "ulps=4",
            "--record-baseline",
            base.to_str().unwrap(),
        ],
    )
    .success();
    let text = std::fs::read_to_string(&base).unwrap();
    assert!(
        text.contains("\"op\": \"eval\"") && text.contains("\"precision\": \"f64\""),
        "{text}"
    );
    batch(
        &p,
        &r,
        &[
            "--precision",
            "f64",
            "--tolerance",
            "ulps=4",
            "--baseline",
            base.to_str().unwrap(),
        ],
    )
    .success();
    let tighter = write(
        d.path(),
        "tight.json",
        "{\"worst\": [{\"op\": \"eval\", \"algorithm\": \"claimed\", \"precision\": \"f64\", \"ulps\": 0.5}]}",
    );
    batch(
        &p,
        &r,
        &[
            "--precision",
            "f64",
            "--tolerance",
            "ulps=4",
            "--baseline",
            tighter.to_str().unwrap(),
        ],
    )
    .code(1)
    .stdout(predicate::str::contains("baseline regression"));
    let broken = write(d.path(), "broken.json", "{\"worst\": 3}");
    batch(
        &p,
        &r,
        &["--precision", "f64", "--baseline", broken.to_str().unwrap()],
    )
    .code(2)
    .stderr(predicate::str::contains("not a baseline file"));
}

/// A regression against a baseline is part of the report in every format: with `--format json`
/// the output stays one JSON document (the regression under `baseline_regressions`), and JUnit
/// gets a failed `baseline` case. [`ROW`] is not correctly rounded at its inputs as seen (its
/// worst error is above 0 ulp), so a baseline of 0 ulp regresses.
#[test]
fn a_baseline_regression_is_in_the_json_report_and_in_junit() {
    let (d, p, r) = batch_dir(&format!("{ROW}\n"), "csv");
    let zero = write(
        d.path(),
        "zero.json",
        "{\"worst\": [{\"op\": \"eval\", \"algorithm\": \"claimed\", \"precision\": \"f64\", \"ulps\": 0}]}",
    );
    let junit = d.path().join("j.xml");
    let out = batch(
        &p,
        &r,
        &[
            "--precision",
            "f64",
            "--tolerance",
            "ulps=4",
            "--format",
            "json",
            "--baseline",
            zero.to_str().unwrap(),
            "--junit",
            junit.to_str().unwrap(),
        ],
    )
    .code(1)
    .get_output()
    .stdout
    .clone();
    let v: serde_json::Value = serde_json::from_slice(&out).expect("one JSON document");
    let regressions = v["baseline_regressions"].as_array().expect("an array");
    assert_eq!(regressions.len(), 1, "{v}");
    assert!(
        regressions[0]
            .as_str()
            .unwrap()
            .starts_with("eval claimed f64: worst error"),
        "{v}"
    );
    let xml = std::fs::read_to_string(&junit).unwrap();
    assert!(
        xml.contains("name=\"baseline\"") && xml.contains("<failure"),
        "{xml}"
    );
}

/// A baseline that cannot be read ends the run with exit status 2 before any output file is
/// written (the JUnit report used to be committed first).
#[test]
fn a_bad_baseline_leaves_no_junit_file() {
    let (d, p, r) = batch_dir(&format!("{ROW}\n"), "csv");
    let broken = write(d.path(), "broken.json", "{\"worst\": 3}");
    let junit = d.path().join("j.xml");
    batch(
        &p,
        &r,
        &[
            "--precision",
            "f64",
            "--baseline",
            broken.to_str().unwrap(),
            "--junit",
            junit.to_str().unwrap(),
        ],
    )
    .code(2);
    assert!(!junit.exists());
}

/// issue 10: `--baseline` is read before `--record-baseline` is written, and a run with a
/// regression records nothing; with one file for both, a regression fails the run and leaves the
/// baseline as it was. At (1/2, 1/4, 1/4) Finn's patch is exactly (3/8, 5/8, 11/16) (Bernstein
/// weights 1/4, 1/4, 1/16, 1/4, 1/8, 1/16), three floats; two floats above 11/16 (in [1/2, 1),
/// ulp 2^-53) is an error of exactly 2 ulps.
#[test]
fn one_file_for_baseline_and_record_baseline_never_raises_it() {
    let exact = "0.5,0.25,0.25,0.375,0.625,0.6875\n";
    let (d, p, r) = batch_dir(exact, "csv");
    let base = d.path().join("base.json");
    let args = |base: &Path| {
        vec![
            "--precision".to_string(),
            "f64".into(),
            "--tolerance".into(),
            "ulps=4".into(),
            "--record-baseline".into(),
            base.display().to_string(),
        ]
    };
    let a = args(&base);
    let a: Vec<&str> = a.iter().map(String::as_str).collect();
    batch(&p, &r, &a).success();
    let recorded = std::fs::read_to_string(&base).unwrap();
    assert!(recorded.contains("\"ulps\": 0.0"), "{recorded}");
    let two_ulps = f64::from_bits(0.6875f64.to_bits() + 2);
    let worse = write(
        d.path(),
        "worse.csv",
        format!("{exact}0.5,0.25,0.25,0.375,0.625,{two_ulps:?}\n"),
    );
    let mut a = args(&base);
    a.extend(["--baseline".to_string(), base.display().to_string()]);
    let a: Vec<&str> = a.iter().map(String::as_str).collect();
    batch(&p, &worse, &a)
        .code(1)
        .stdout(predicate::str::contains(
            "baseline regression: eval claimed f64: worst error 2 ulp",
        ));
    assert_eq!(std::fs::read_to_string(&base).unwrap(), recorded);
    // no regression: the run passes and records again
    batch(&p, &r, &a).success();
    assert_eq!(std::fs::read_to_string(&base).unwrap(), recorded);
}

// ---------------------------------------------------------------------------------------------
// Peers

fn peers() -> PathBuf {
    fixtures().join("peers")
}

/// The Python package `bezier` (fixtures/peers/bezier_peer.py) passes at cond=9: 9 = 3n is the
/// constant of de Casteljau's own a-priori bound γ_{3n} (docs/theory.md §14.1) for n = 3, i.e. we accept
/// any algorithm as accurate as de Casteljau (bezier needs about 4: it fails at cond=3 on one row).
#[test]
fn bezier_passes_at_cond_9() {
    batch(
        &peers().join("peer_cubic.toml"),
        &peers().join("bezier_results.csv"),
        &["--precision", "f64", "--tolerance", "cond=9"],
    )
    .success()
    .stdout(predicate::str::contains(
        "2000 claims: 2000 passed, 0 failed",
    ));
}

/// The worst row is the row with the largest error, not the one with the loosest bound, and the
/// histogram counts the rows' errors: fixtures/peers/exact_errors.py (plain Python fractions)
/// finds line 417 at 320.7 ulp and the histogram [0, 630, 809, 492, 44, 23, 1, 1]; the same at
/// every tolerance.
#[test]
fn worst_row_is_the_largest_error() {
    let mut histograms = Vec::new();
    for tol in ["cond=9", "bound", "ulps=4", "correctly_rounded"] {
        let out = batch(
            &peers().join("peer_cubic.toml"),
            &peers().join("bezier_results.csv"),
            &["--precision", "f64", "--tolerance", tol, "--format", "json"],
        )
        .get_output()
        .stdout
        .clone();
        let v: serde_json::Value = serde_json::from_slice(&out).unwrap();
        assert_eq!(v["worst"]["line"], 417, "{tol}: {v}");
        let u = v["worst"]["ulps"].as_f64().unwrap();
        assert!((u - 320.7).abs() < 0.05, "{tol}: {u}");
        histograms.push(v["summary"]["ulp_histogram"].clone());
    }
    assert!(
        histograms.windows(2).all(|w| w[0] == w[1]),
        "{histograms:?}"
    );
}

/// Exactly right rows land in the "0 ulp" bucket (their filter enclosures straddle 0, so the
/// error is settled exactly), and a row one ulp off in (1/2, 1]. The quadratic QUAD at the
/// corners is its corner control points; at (1/2, 1/2, 0) it is (c200 + 2 c110 + c020)/4 =
/// (1/2, 1/2, 1) (hand derivation), all exact in f64.
#[test]
fn exactly_right_rows_are_counted_as_zero_ulp() {
    let one_up = format!("{:?}", 1f64.next_up());
    let rows = format!(
        "1,0,0,0,0,0\n0,1,0,0,2,0\n0,0,1,0,2,1\n0.5,0.5,0,0.5,0.5,1\n0.5,0.5,0,0.5,0.5,{one_up}\n"
    );
    let (_d, patch, results) = batch_dir(&rows, "csv");
    let out = batch(
        &patch,
        &results,
        &[
            "--precision",
            "f64",
            "--tolerance",
            "ulps=1",
            "--format",
            "json",
        ],
    )
    .success()
    .get_output()
    .stdout
    .clone();
    let v: serde_json::Value = serde_json::from_slice(&out).unwrap();
    let h = &v["summary"]["ulp_histogram"];
    assert_eq!(h["0"], 4, "{h}");
    assert_eq!(h["(1/2, 1]"], 1, "{h}");
    assert_eq!(v["worst"]["line"], 5);
}

fn next_up_text(t: &str) -> String {
    let x: f64 = t.parse().unwrap();
    format!("{:?}", x.next_up())
}

/// A one-ULP change to one correctly rounded value of bezier's output fails `correctly_rounded`.
#[test]
fn one_ulp_change_fails_correctly_rounded() {
    let text = std::fs::read_to_string(peers().join("bezier_results.csv")).unwrap();
    let d = tempfile::tempdir().unwrap();
    let patch = peers().join("peer_cubic.toml");
    let mut found = false;
    for line in text.lines().filter(|l| !l.starts_with('#')).take(40) {
        let r = write(d.path(), "one.csv", format!("{line}\n"));
        let ok = tribez()
            .arg("check")
            .arg("--patch")
            .arg(&patch)
            .arg("--results")
            .arg(&r)
            .args(["--precision", "f64", "--tolerance", "correctly_rounded"])
            .output()
            .unwrap();
        if ok.status.code() != Some(0) {
            continue;
        }
        let mut fields: Vec<String> = line.split(',').map(str::to_string).collect();
        fields[3] = next_up_text(&fields[3]);
        let r = write(d.path(), "one.csv", format!("{}\n", fields.join(",")));
        batch(
            &patch,
            &r,
            &["--precision", "f64", "--tolerance", "correctly_rounded"],
        )
        .code(1)
        .stdout(
            predicate::str::contains("breaks tolerance `correctly_rounded`")
                .and(predicate::str::contains("1 claim: 0 passed, 1 failed")),
        );
        found = true;
        break;
    }
    assert!(found, "no correctly rounded row among the first 40");
}

/// f32 results computed the way a shader does (tribez's glam `Vec3` kernel, same operation order
/// as the generic code) pass at `bound` and at `ulps=9`: with positive control points and points
/// inside the triangle, Σ|c_i|B_i = P, so the bound γ_9·P < 9·2^-24·2^(e+1) = 9 ulp(P).
#[test]
fn shader_f32_results_pass_at_ulps_and_bound() {
    use tribez::kernels::{casteljau, net_to};
    let d = tempfile::tempdir().unwrap();
    let text = "degree = 3\n[control_points]\n\"3,0,0\" = [1, 1.5, 2]\n\"2,1,0\" = [1.25, 1.75, 1.5]\n\"1,2,0\" = [1.5, 1.125, 1.875]\n\"0,3,0\" = [2, 1, 1]\n\"2,0,1\" = [1.1, 1.9, 1.3]\n\"1,1,1\" = [1.7, 1.2, 1.6]\n\"0,2,1\" = [1.3, 1.4, 1.8]\n\"1,0,2\" = [1.6, 1.8, 1.1]\n\"0,1,2\" = [1.2, 1.6, 1.4]\n\"0,0,3\" = [1.9, 1.05, 1.7]\n";
    let patch_path = write(d.path(), "cubic.toml", text);
    let patch = tribez::Patch::from_file(&patch_path).unwrap();
    // the net rounded to f32; `casteljau` runs the glam `Vec3` kernel on it (m = 2, d = 3)
    let net = net_to::<f32>(patch.control_net());
    let mut rows = String::new();
    let mut s = 12345u64;
    let mut unit = || {
        s = s
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((s >> 40) as f32) / (1u64 << 24) as f32
    };
    for _ in 0..3000 {
        let u = unit();
        let v = unit() * (1.0 - u);
        let w = 1.0 - u - v;
        let p = casteljau(&net, &[u, v, w]);
        rows += &format!("{u:?},{v:?},{w:?},{:?},{:?},{:?}\n", p[0], p[1], p[2]);
    }
    let r = write(d.path(), "shader.csv", &rows);
    for tol in ["ulps=9", "bound"] {
        batch(&patch_path, &r, &["--precision", "f32", "--tolerance", tol])
            .success()
            .stdout(predicate::str::contains("3000 claims: 3000 passed"));
    }
}

// ---------------------------------------------------------------------------------------------
// certify

#[test]
fn certify_random_prints_seed_and_command() {
    tribez()
        .arg("certify")
        .arg(peers().join("peer_cubic.toml"))
        .args(["--random", "300", "--seed", "42"])
        .assert()
        .success()
        .stdout(
            predicate::str::contains("seed 42")
                .and(predicate::str::contains("--random 300 --seed 42"))
                .and(predicate::str::contains("within"))
                .and(predicate::str::contains("EXCEEDED").not()),
        );
}

#[test]
fn certify_points_file_json_and_junit() {
    let d = tempfile::tempdir().unwrap();
    let pts = write(
        d.path(),
        "pts.csv",
        "1/2,1/3,1/6\n0.1,0.2,0.7\n-0.25,0.5,0.75\n",
    );
    let junit = d.path().join("j.xml");
    let out = tribez()
        .arg("certify")
        .arg(peers().join("peer_cubic.toml"))
        .arg("--points")
        .arg(&pts)
        .args([
            "--precision",
            "f32",
            "--algorithm",
            "bernstein",
            "--format",
            "json",
            "--junit",
        ])
        .arg(&junit)
        .assert()
        .success()
        .get_output()
        .stdout
        .clone();
    let v: serde_json::Value = serde_json::from_slice(&out).unwrap();
    assert_eq!(v["results"][0]["algorithm"], "bernstein");
    assert_eq!(v["results"][0]["within_bound"], true);
    assert!(
        std::fs::read_to_string(&junit)
            .unwrap()
            .contains("bernstein f32")
    );
}

#[test]
fn certify_usage_errors() {
    let p = peers().join("peer_cubic.toml");
    tribez()
        .arg("certify")
        .arg(&p)
        .assert()
        .code(2)
        .stderr(predicate::str::contains("--points FILE or --random N"));
    tribez()
        .arg("certify")
        .arg(&p)
        .args(["--random", "5", "--algorithm", "horner"])
        .assert()
        .code(2)
        .stderr(predicate::str::contains("unknown algorithm"));
    tribez()
        .arg("certify")
        .arg(&p)
        .args(["--random", "5", "--precision", "f16"])
        .assert()
        .code(2)
        .stderr(predicate::str::contains("unknown precision"));
    tribez()
        .arg("certify")
        .arg(&p)
        .args(["--random", "0"])
        .assert()
        .code(2);
    let d = tempfile::tempdir().unwrap();
    let pts = write(d.path(), "pts.csv", "1/2,1/2\n");
    tribez()
        .arg("certify")
        .arg(&p)
        .arg("--points")
        .arg(&pts)
        .assert()
        .code(2)
        .stderr(predicate::str::contains("pts.csv:1"));
}

#[test]
fn certify_baseline() {
    let d = tempfile::tempdir().unwrap();
    let p = peers().join("peer_cubic.toml");
    let base = d.path().join("b.json");
    tribez()
        .arg("certify")
        .arg(&p)
        .args(["--random", "50", "--record-baseline"])
        .arg(&base)
        .assert()
        .success();
    tribez()
        .arg("certify")
        .arg(&p)
        .args(["--random", "50", "--baseline"])
        .arg(&base)
        .assert()
        .success();
    let zero = write(
        d.path(),
        "z.json",
        "{\"worst\": [{\"op\": \"eval\", \"algorithm\": \"casteljau\", \"precision\": \"f32\", \"ulps\": 0}]}",
    );
    tribez()
        .arg("certify")
        .arg(&p)
        .args(["--random", "50", "--baseline"])
        .arg(&zero)
        .assert()
        .code(1)
        .stdout(predicate::str::contains("baseline regression"));
}

// ---------------------------------------------------------------------------------------------
// `cond` without K: K = (m+1)·n

/// QUAD (m = 2, n = 2) at the corner (0, 1, 0) is c_020 = (0, 2, 0); the condition number of the
/// second coordinate there is |c_020| B_020 = 2. A claim 3 ulps above 2 (ulp(2) = 2^-51 = 4ε, so
/// an error of 12ε) meets K·ε·2 exactly when K ≥ 6 = (m+1)·n: `cond` passes, `cond=5` fails
/// (hand derivation).
fn three_ulps_above_two() -> String {
    format!("{:?}", 2f64.next_up().next_up().next_up())
}

#[test]
fn batch_cond_without_k_is_the_degree_constant() {
    let y = three_ulps_above_two();
    let (_d, p, r) = batch_dir(&format!("0,1,0,0,{y},0\n"), "csv");
    batch(&p, &r, &["--precision", "f64", "--tolerance", "cond"])
        .success()
        .stdout(
            predicate::str::contains("tolerance cond=6")
                .and(predicate::str::contains("1 claim: 1 passed, 0 failed")),
        );
    batch(&p, &r, &["--precision", "f64", "--tolerance", "cond=5"])
        .code(1)
        .stdout(predicate::str::contains("0 passed, 1 failed"));
    // like cond=K, it needs a precision
    batch(&p, &r, &["--tolerance", "cond"])
        .code(2)
        .stderr(predicate::str::contains(
            "--tolerance cond needs --precision",
        ));
}

#[test]
fn claim_cond_without_k_is_the_degree_constant() {
    let y = three_ulps_above_two();
    let claim = |tol: &str| {
        format!(
            "[[claim]]\nop = \"eval\"\nat = [\"0\", \"1\", \"0\"]\nexpect = [\"0\", \"{y}\", \"0\"]\nprecision = \"f64\"\ntolerance = \"{tol}\"\n"
        )
    };
    let d = claim_dir(&claim("cond"));
    tribez()
        .arg("check")
        .arg(d.path())
        .assert()
        .success()
        .stdout(predicate::str::contains("1 passed"));
    let d = claim_dir(&claim("cond=5"));
    tribez().arg("check").arg(d.path()).assert().code(1);
    // only evaluation claims have a condition number
    let d = claim_dir(
        "[[claim]]\nop = \"elevate\"\nexpect = \"x\"\nprecision = \"f64\"\ntolerance = \"cond\"\n",
    );
    tribez()
        .arg("check")
        .arg(d.path())
        .assert()
        .code(2)
        .stderr(predicate::str::contains("applies to `eval` claims only"));
}
