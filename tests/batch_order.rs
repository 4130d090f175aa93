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
        .arg(Path::new(env!("CARGO_MANIFEST_DIR")).join("fixtures/finn_day30.toml"))
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
