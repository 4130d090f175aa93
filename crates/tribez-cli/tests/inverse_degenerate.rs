//! `tribez locate`, `tribez ray` and their batch checkers where the two equations share a factor
//! (tribez issue 35 §4): a curve of solutions is clipped to the closed triangle (and τ ≥ 0)
//! before anything is called "infinitely many". The patches are fixtures/inverse/degenerate/;
//! each expected value is derived by hand in a comment (the library-level tests,
//! crates/tribez/tests/inverse_degenerate.rs, give the derivations in full).

mod common;

use common::{fixtures, tribez, write};

fn fx(name: &str) -> String {
    fixtures()
        .join("inverse/degenerate")
        .join(name)
        .display()
        .to_string()
}

/// Run tribez: (exit code, stdout).
fn run(args: &[&str]) -> (i32, String) {
    let out = tribez().args(args).output().expect("run tribez");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
    )
}

fn json(args: &[&str]) -> serde_json::Value {
    let (code, out) = run(&[args, &["--format", "json"]].concat());
    assert!(code == 0 || code == 1, "{out}");
    serde_json::from_str(&out).unwrap()
}

#[test]
fn locate_on_a_constant_patch() {
    // (1, 2) is not the constant (1, 1): no parameter point
    let (code, out) = run(&["locate", &fx("const.toml"), "--point", "1,2"]);
    assert_eq!(code, 0);
    assert!(
        out.contains("has 0 parameter points in the closed triangle"),
        "{out}"
    );
    let j = json(&["locate", &fx("const.toml"), "--point", "1,2"]);
    assert_eq!(
        (j["count"].as_u64(), j["infinite"].as_bool()),
        (Some(0), Some(false))
    );
    assert!(j["degenerate"].is_null());
    // (1, 1): every parameter point (dimension 2)
    let (_, out) = run(&["locate", &fx("const.toml"), "--point", "1,1"]);
    assert!(
        out.contains("is the image of every parameter point of the closed triangle"),
        "{out}"
    );
    let j = json(&["locate", &fx("const.toml"), "--point", "1,1"]);
    assert_eq!(j["infinite"], true);
    assert_eq!(j["degenerate"]["dimension"], 2);
}

#[test]
fn locate_on_a_collinear_patch() {
    // x = s + 2t: s + 2t = 5 misses the triangle (s + 2t ≤ 2 there)
    let (code, out) = run(&["locate", &fx("collinear.toml"), "--point", "5,0"]);
    assert_eq!(code, 0);
    assert!(out.contains("has 0 parameter points"), "{out}");
    // s + 2t = 1: the segment from (0, 1/2) to (1, 0)
    let (_, out) = run(&["locate", &fx("collinear.toml"), "--point", "1,0"]);
    assert!(out.contains("whole curve of parameters"), "{out}");
    assert!(out.contains("s + 2t - 1 = 0"), "{out}");
    assert!(out.contains("(s = 0, t = 1/2), (s = 1, t = 0)"), "{out}");
    let j = json(&["locate", &fx("collinear.toml"), "--point", "1,0"]);
    assert_eq!(j["degenerate"]["dimension"], 1);
    let b = j["degenerate"]["boundary"].as_array().unwrap();
    let st: Vec<(String, String)> = b
        .iter()
        .map(|p| {
            (
                p["s"]["rational"].as_str().unwrap().to_string(),
                p["t"]["rational"].as_str().unwrap().to_string(),
            )
        })
        .collect();
    assert_eq!(
        st,
        vec![("0".into(), "1/2".into()), ("1".into(), "0".into())]
    );
}

#[test]
fn rays_in_the_plane_of_a_flat_triangle() {
    // t = 2: never over the triangle
    let (code, out) = run(&[
        "ray",
        &fx("flat.toml"),
        "--origin",
        "-1,2,0",
        "--direction",
        "1,0,0",
    ]);
    assert_eq!(code, 0);
    assert!(out.ends_with(": 0 hits\n"), "{out}");
    // t = 1: the corner (0, 1) only, τ = s + 1 = 1
    let j = json(&[
        "ray",
        &fx("flat.toml"),
        "--origin",
        "-1,1,0",
        "--direction",
        "1,0,0",
    ]);
    assert_eq!(j["count"], 1);
    assert_eq!(j["infinite"], false);
    let h = &j["hits"][0];
    assert_eq!(
        [
            &h["tau"]["rational"],
            &h["s"]["rational"],
            &h["t"]["rational"]
        ],
        ["1", "0", "1"]
    );
    // t = 1/2, s = 1/4 − τ ≥ 0: the piece from τ = 0 to τ = 1/4
    let (_, out) = run(&[
        "ray",
        &fx("flat.toml"),
        "--origin",
        "1/4,1/2,0",
        "--direction",
        "-1,0,0",
    ]);
    assert!(out.contains("infinitely many hits"), "{out}");
    assert!(out.contains("2t - 1 = 0"), "{out}");
    assert!(
        out.contains("(τ = 1/4, s = 0, t = 1/2), (τ = 0, s = 1/4, t = 1/2)"),
        "{out}"
    );
}

#[test]
fn a_ray_on_the_parabolic_cylinder_outside_the_triangle() {
    // (s, t, s^2) and the line (2, −1 + τ, 4): on z = x^2 at s = 2, outside: no hit
    let (code, out) = run(&[
        "ray",
        &fx("parabolic.toml"),
        "--origin",
        "2,-1,4",
        "--direction",
        "0,1,0",
    ]);
    assert_eq!(code, 0);
    assert!(out.ends_with(": 0 hits\n"), "{out}");
}

#[test]
fn locate_rows_on_degenerate_queries_get_the_right_verdicts() {
    let dir = tempfile::tempdir().unwrap();
    // const.toml: (1, 2) has no parameter point, so `none` holds
    let rows = write(dir.path(), "c.csv", "1,2,none\n");
    let (code, out) = run(&[
        "check",
        "--patch",
        &fx("const.toml"),
        "--locate-results",
        rows.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{out}");
    // and a claimed point there is extra
    let rows = write(dir.path(), "c2.csv", "1,2,0.5,0.25\n");
    let (code, out) = run(&[
        "check",
        "--patch",
        &fx("const.toml"),
        "--locate-results",
        rows.to_str().unwrap(),
    ]);
    assert_eq!(code, 1, "{out}");
    assert!(out.contains("extra"), "{out}");
    // (1, 1): the whole triangle: a point claim fails, as for any infinite set
    let rows = write(dir.path(), "c3.csv", "1,1,0.5,0.25\n");
    let (code, out) = run(&[
        "check",
        "--patch",
        &fx("const.toml"),
        "--locate-results",
        rows.to_str().unwrap(),
    ]);
    assert_eq!(code, 1, "{out}");
    assert!(
        out.contains("every parameter point of the closed triangle"),
        "{out}"
    );
    // collinear.toml: (5, 0) none (holds); (2, 0) exactly the corner (0, 1) (holds; a wrong
    // point fails, `none` fails as missed); (1, 0) a segment (fails, said so)
    let rows = write(
        dir.path(),
        "coll.csv",
        "5,0,none\n2,0,0,1\n2,0,0.5,0.5\n2,0,none\n1,0,1,0\n",
    );
    let j = json(&[
        "check",
        "--patch",
        &fx("collinear.toml"),
        "--locate-results",
        rows.to_str().unwrap(),
    ]);
    assert_eq!(
        (
            j["checked"].as_u64(),
            j["passed"].as_u64(),
            j["failed"].as_u64()
        ),
        (Some(5), Some(2), Some(3))
    );
    let failed: Vec<u64> = j["failures"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| f["line"].as_u64().unwrap())
        .collect();
    assert_eq!(failed, vec![3, 4, 5]);
    assert_eq!(j["infinite"], 1);
}

#[test]
fn ray_rows_on_degenerate_queries_get_the_right_verdicts() {
    let dir = tempfile::tempdir().unwrap();
    // flat.toml: (−1, 2, 0) along x misses: `none` holds; (−1, 1, 0) first hit τ = 1 at
    // (0, 1): holds; `none` there fails; (1/4, 1/2, 0) along −x runs along: a claim fails
    let rows = write(
        dir.path(),
        "r.csv",
        "-1,2,0,1,0,0,none\n-1,1,0,1,0,0,1,0,1\n-1,1,0,1,0,0,none\n1/4,1/2,0,-1,0,0,0,0.25,0.5\n",
    );
    let j = json(&[
        "check",
        "--patch",
        &fx("flat.toml"),
        "--ray-results",
        rows.to_str().unwrap(),
    ]);
    assert_eq!(
        (j["passed"].as_u64(), j["failed"].as_u64()),
        (Some(2), Some(2))
    );
    let failed: Vec<u64> = j["failures"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| f["line"].as_u64().unwrap())
        .collect();
    assert_eq!(failed, vec![3, 4]);
    // the parabolic cylinder: the line at s = 2 misses
    let rows = write(dir.path(), "p.csv", "2,-1,4,0,1,0,none\n");
    let (code, out) = run(&[
        "check",
        "--patch",
        &fx("parabolic.toml"),
        "--ray-results",
        rows.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{out}");
}

#[test]
fn locate_three_preimages_that_share_their_lines() {
    // (x, y) = (s² + t² − s − t, s·t) (fixture comment): (0, 0) has the preimages (0, 0),
    // (0, 1), (1, 0) (s·t = 0, then t² − t = 0 or s² − s = 0). (0, 0) shares s = 0 with (0, 1)
    // and t = 0 with (1, 0); tribez once reported the other two alone. The Jacobian
    // [[2s − 1, 2t − 1], [t, s]] is singular at (0, 0) only (det = 2s² − s − 2t² + t: 0, −1,
    // 1), where the circle crosses both axes once: multiplicity 1 + 1 = 2 (Bézout: 2 + 1 + 1 =
    // 4 = 2·2).
    let f = fx("three_preimages.toml");
    let (code, out) = run(&["locate", &f, "--point", "0,0"]);
    assert_eq!(code, 0, "{out}");
    assert!(out.contains("has 3 parameter points"), "{out}");
    let j = json(&["locate", &f, "--point", "0,0"]);
    let got: Vec<(String, String, bool)> = j["parameters"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| {
            (
                p["s"]["rational"].as_str().unwrap().to_string(),
                p["t"]["rational"].as_str().unwrap().to_string(),
                p["jacobian_zero"].as_bool().unwrap(),
            )
        })
        .collect();
    let want = |s: &str, t: &str, z: bool| (s.to_string(), t.to_string(), z);
    assert_eq!(
        got,
        vec![
            want("0", "0", true),
            want("0", "1", false),
            want("1", "0", false)
        ]
    );
    assert_eq!(j["parameters"][0]["multiplicity"], 2);
}
