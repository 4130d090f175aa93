//! `tribez eval --points` evaluates in parallel (rayon) and must print the results in input
//! order, each from the shared per-patch precomputation.

use std::path::Path;

use assert_cmd::Command;
use num_bigint::BigInt;
use num_rational::BigRational;

#[test]
fn eval_points_keeps_input_order() {
    let dir = tempfile::tempdir().unwrap();
    // Points on the edge w = 0 of the worked example's patch (fixtures/finn_day30.toml), where
    // by hand p(u, v, 0) = u² c200 + 2uv c110 + v² c020 = (2uv, 2v², 4uv).
    let m = 300i64;
    let mut text = String::new();
    for k in 0..m {
        text += &format!("{k}/{},{}/{},0\n", m - 1, m - 1 - k, m - 1);
    }
    let pts = dir.path().join("pts.csv");
    std::fs::write(&pts, text).unwrap();
    let out = Command::cargo_bin("tribez")
        .unwrap()
        .args(["eval", "--format", "json", "--float", "f64", "--points"])
        .arg(&pts)
        .arg(Path::new(env!("CARGO_MANIFEST_DIR")).join("../../fixtures/finn_day30.toml"))
        .output()
        .unwrap();
    assert!(out.status.success());
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let results = v["results"].as_array().unwrap();
    assert_eq!(results.len(), m as usize);
    for (k, r) in results.iter().enumerate() {
        let u = BigRational::new(BigInt::from(k), BigInt::from(m - 1));
        let w = BigRational::from_integer(1.into()) - &u;
        let two = BigRational::from_integer(2.into());
        let expected =
            [&two * &u * &w, &two * &w * &w, &two * &two * &u * &w].map(|x| x.to_string());
        assert_eq!(
            r["point"],
            serde_json::json!(expected),
            "point {k} out of order or wrong"
        );
    }
}

/// Line numbers stay right across chunk boundaries (chunks are 65,536 lines): a wrong value and
/// a malformed number far into the file are reported at their own lines.
#[test]
fn line_numbers_across_chunks() {
    let dir = tempfile::tempdir().unwrap();
    let patch =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../fixtures/finn_day30.toml");
    // At the corner (1, 0, 0) the patch is c200 = (0, 0, 0) exactly (corner interpolation).
    let good = "1,0,0,0,0,0\n";
    let mut text = good.repeat(69_999);
    text.push_str("1,0,0,0,0,0.5\n"); // line 70,000: wrong
    text.push_str(good);
    let results = dir.path().join("r.csv");
    std::fs::write(&results, &text).unwrap();
    let out = assert_cmd::Command::cargo_bin("tribez")
        .unwrap()
        .args(["check", "--precision", "f64", "--patch"])
        .arg(&patch)
        .arg("--results")
        .arg(&results)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    let stdout = String::from_utf8(out.stdout).unwrap();
    assert!(stdout.contains("70001 rows"), "{stdout}");
    assert!(stdout.contains("line 70000"), "{stdout}");

    text.push_str("1,0,0,0,zz,0\n"); // line 70,002: malformed, field 5 at column 9
    std::fs::write(&results, &text).unwrap();
    let out = assert_cmd::Command::cargo_bin("tribez")
        .unwrap()
        .args(["check", "--precision", "f64", "--patch"])
        .arg(&patch)
        .arg("--results")
        .arg(&results)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let stderr = String::from_utf8(out.stderr).unwrap();
    assert!(stderr.contains("r.csv:70002:9"), "{stderr}");
}

/// A JSON array of rows across chunk boundaries: each row is reported at the line where it
/// starts (rows here take two lines each, so row k starts on line 2 + 2k).
#[test]
fn json_array_rows_across_chunks() {
    let dir = tempfile::tempdir().unwrap();
    let patch =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../fixtures/finn_day30.toml");
    // At the corner (1, 0, 0) the patch is c200 = (0, 0, 0) exactly (corner interpolation).
    let mut rows = vec!["  [1, 0, 0,\n   0, 0, 0]"; 70_001];
    rows[69_999] = "  [1, 0, 0,\n   0, 0, 0.5]"; // row 69,999 (0-based): line 2 + 2·69,999
    let text = format!("[\n{}\n]\n", rows.join(",\n"));
    let results = dir.path().join("r.json");
    std::fs::write(&results, &text).unwrap();
    let out = assert_cmd::Command::cargo_bin("tribez")
        .unwrap()
        .args(["check", "--precision", "f64", "--patch"])
        .arg(&patch)
        .arg("--results")
        .arg(&results)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    let stdout = String::from_utf8(out.stdout).unwrap();
    assert!(stdout.contains("70001 rows"), "{stdout}");
    assert!(stdout.contains("line 140000"), "{stdout}");
}
