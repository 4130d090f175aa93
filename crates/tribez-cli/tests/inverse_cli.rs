//! `tribez intersect` as a user runs it. Expected values: fixtures/inverse/derive.py (SymPy) and
//! hand derivations in the comments.

use std::path::PathBuf;

mod common;
use common::{fails, fixtures, tribez};

fn fx(name: &str) -> String {
    let p: PathBuf = fixtures().join(name);
    p.display().to_string()
}

/// Exit status 2, nothing on standard output, one line on standard error containing `words`.
fn fails_with(args: &[&str], words: &[&str]) {
    fails(tribez().args(args), words);
}

#[test]
fn intersect_prints_algebraic_parameters_in_json() {
    // x = s, y = s^2 meets y = 1/2 at s = 1/√2 (a root of 2x^2 − 1), t = 1/√2
    let out = tribez()
        .args([
            "intersect",
            &fx("inverse/parabola.toml"),
            &fx("inverse/line_half.toml"),
            "--format",
            "json",
        ])
        .assert()
        .code(0)
        .get_output()
        .stdout
        .clone();
    let j: serde_json::Value = serde_json::from_slice(&out).unwrap();
    assert_eq!(j["count"], 1);
    let s = &j["intersections"][0]["s"];
    assert_eq!(s["polynomial"], serde_json::json!(["-1", "0", "2"]));
    // 1/√2 = 0.70710678118654752440…: f64 0x1.6a09e667f3bcdp-1
    assert_eq!(s["f64"], "0x1.6a09e667f3bcdp-1");
    assert_eq!(s["decimal"], "0.70710678118654752");
    assert_eq!(j["intersections"][0]["point"][1], "1/2");
    assert_eq!(j["intersections"][0]["tangential"], false);
}

#[test]
fn intersect_flags_a_tangency_and_reports_an_overlap() {
    // y = x − 1/4 touches y = x^2 at x = 1/2: s = t = 1/2, multiplicity 2
    let out = tribez()
        .args([
            "intersect",
            &fx("inverse/parabola.toml"),
            &fx("inverse/tangent_line.toml"),
        ])
        .assert()
        .code(0)
        .get_output()
        .stdout
        .clone();
    let text = String::from_utf8(out).unwrap();
    assert!(text.contains("s = 1/2"), "{text}");
    assert!(text.contains("tangential (multiplicity 2)"), "{text}");
    let out = tribez()
        .args([
            "intersect",
            &fx("inverse/cubic_a.toml"),
            &fx("inverse/cubic_a_reversed_shifted.toml"),
        ])
        .assert()
        .code(0)
        .get_output()
        .stdout
        .clone();
    let text = String::from_utf8(out).unwrap();
    assert!(
        text.contains("overlap: s from 1/4 to 3/4, t from 1 to 0"),
        "{text}"
    );
}

#[test]
fn intersect_rejects_what_is_not_a_planar_curve() {
    fails_with(
        &[
            "intersect",
            &fx("finn_day30.toml"),
            &fx("inverse/parabola.toml"),
        ],
        &["finn_day30.toml", "planar curve (m = 1, d = 2)"],
    );
    fails_with(
        &[
            "intersect",
            &fx("inverse/parabola.toml"),
            &fx("inverse/nope.toml"),
        ],
        &["nope.toml"],
    );
}

#[test]
fn intersect_caps_the_degree() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("deg13.toml");
    let mut text = String::from("degree = 13\n\n[control_points]\n");
    for i in 0..=13 {
        text += &format!("\"{},{i}\" = [{i}, 0]\n", 13 - i);
    }
    std::fs::write(&path, text).unwrap();
    fails_with(
        &[
            "intersect",
            path.to_str().unwrap(),
            &fx("inverse/parabola.toml"),
        ],
        &["degree 13, above the limit 12"],
    );
}

#[test]
fn locate_and_ray_print_exact_parameters() {
    // the dome z = 2(λ0λ1 + λ1λ2 + λ2λ0) at (1/4, 1/4): λ = (1/2, 1/4, 1/4), z = 5/8, so the
    // ray down from height 2 hits at τ = 11/8
    let out = tribez()
        .args([
            "ray",
            &fx("inverse/dome.toml"),
            "--origin",
            "1/4,1/4,2",
            "--direction",
            "0,0,-1",
            "--format",
            "json",
        ])
        .assert()
        .code(0)
        .get_output()
        .stdout
        .clone();
    let j: serde_json::Value = serde_json::from_slice(&out).unwrap();
    assert_eq!(j["count"], 1);
    assert_eq!(j["hits"][0]["tau"]["rational"], "11/8");
    assert_eq!(j["hits"][0]["first"], true);
    assert_eq!(j["hits"][0]["kind"], "cross");
    assert_eq!(j["hits"][0]["s"]["rational"], "1/4");
    // the hill's height at its centroid: 2·(3·1/9) = 2/3
    let out = tribez()
        .args(["ray", &fx("inverse/hill.toml"), "--height", "1/3,1/3"])
        .assert()
        .code(0)
        .get_output()
        .stdout
        .clone();
    assert!(String::from_utf8(out).unwrap().contains("= 2/3"));
    // locate on the quadratic triangle: x = y = 1/2 at s = t = (√5 − 1)/4, a root of 4x^2 + 2x − 1
    // (hand: on the diagonal s = t, λ0 = 1 − 2s, x = y = (1 − 2s)s + 4s² = s + 2s² = 1/2)
    let out = tribez()
        .args([
            "locate",
            &fx("inverse/quad_triangle.toml"),
            "--point",
            "1/2,1/2",
            "--format",
            "json",
        ])
        .assert()
        .code(0)
        .get_output()
        .stdout
        .clone();
    let j: serde_json::Value = serde_json::from_slice(&out).unwrap();
    assert_eq!(j["count"], 1);
    assert_eq!(
        j["parameters"][0]["s"]["polynomial"],
        serde_json::json!(["-1", "2", "4"])
    );
}

#[test]
fn locate_and_ray_reject_bad_input() {
    fails_with(
        &["locate", &fx("inverse/dome.toml"), "--point", "0,0"],
        &["dome.toml", "m = 2", "ℝ^2"],
    );
    fails_with(
        &[
            "locate",
            &fx("inverse/quad_triangle.toml"),
            "--point",
            "0,0,0",
        ],
        &["--point 0,0,0", "expected 2 coordinates, found 3"],
    );
    fails_with(
        &[
            "locate",
            &fx("inverse/quad_triangle.toml"),
            "--point",
            "1/0,2",
        ],
        &["--point"],
    );
    fails_with(
        &[
            "ray",
            &fx("inverse/dome.toml"),
            "--origin",
            "0,0,0",
            "--direction",
            "0,0,0",
        ],
        &["direction is zero"],
    );
    fails_with(
        &["ray", &fx("inverse/dome.toml"), "--height", "1/3,1/3"],
        &["--height takes a functional patch"],
    );
    fails_with(
        &["ray", &fx("inverse/hill.toml"), "--height", "2,2"],
        &["outside the patch's domain triangle"],
    );
}
