//! `tribez intersect` and `intersect` claims on curves that lie on one algebraic curve.
//! Expected values: fixtures/intersect/derive.py (SymPy) and the hand derivations in
//! crates/tribez/tests/common_curve.rs; never tribez's own output.

mod common;
use common::{fixtures, tribez};

fn fx(name: &str) -> String {
    fixtures()
        .join("intersect")
        .join(name)
        .display()
        .to_string()
}

fn text(a: &str, b: &str) -> String {
    let out = tribez()
        .args(["intersect", &fx(a), &fx(b)])
        .assert()
        .code(0)
        .get_output()
        .stdout
        .clone();
    String::from_utf8(out).unwrap()
}

#[test]
fn a_fold_gives_one_line_per_piece() {
    // s = 1/4 + t − t^2: t up from 0 to 1/2 and down from 1 to 1/2 as s goes 1/4 → 1/2
    let t = text("seg.toml", "fold2.toml");
    assert!(t.contains(": 0 intersection points, 2 overlaps"), "{t}");
    assert!(
        t.contains("overlap: s from 1/4 to 1/2, t from 0 to 1/2 (t increasing with s)"),
        "{t}"
    );
    assert!(
        t.contains("overlap: s from 1/4 to 1/2, t from 1 to 1/2 (t decreasing as s increases)"),
        "{t}"
    );
    // the relation, up to a constant factor: 4s − 1 − 4t + 4t^2
    assert!(
        t.contains("on each overlap: ") && t.contains("4·t^2") && t.contains("4·s"),
        "{t}"
    );
}

#[test]
fn overlaps_in_json_carry_ends_direction_and_relation() {
    let out = tribez()
        .args([
            "intersect",
            &fx("drop.toml"),
            &fx("loop.toml"),
            "--format",
            "json",
        ])
        .assert()
        .code(0)
        .get_output()
        .stdout
        .clone();
    let j: serde_json::Value = serde_json::from_slice(&out).unwrap();
    // t = 1/4 + s/2 on s ∈ [0, 1]; the node again at (0, 3/4) and (1, 1/4)
    assert_eq!(j["count"], 2);
    assert_eq!(j["intersections"][0]["s"]["rational"], "0");
    assert_eq!(j["intersections"][0]["t"]["rational"], "3/4");
    assert_eq!(j["intersections"][1]["s"]["rational"], "1");
    assert_eq!(j["intersections"][1]["t"]["rational"], "1/4");
    let o = &j["overlaps"];
    assert_eq!(o.as_array().unwrap().len(), 1);
    assert_eq!(o[0]["s"][0]["rational"], "0");
    assert_eq!(o[0]["s"][1]["rational"], "1");
    assert_eq!(o[0]["t"][0]["rational"], "1/4");
    assert_eq!(o[0]["t"][1]["rational"], "3/4");
    assert_eq!(o[0]["t_increasing"], true);
    // G ∝ 2s − 4t + 1: the terms c·s^i·t^j with c of one sign pattern
    let terms = j["relation"].as_array().unwrap();
    let c = |i: u64, k: u64| -> i64 {
        terms
            .iter()
            .find(|x| x["s"] == i && x["t"] == k)
            .map(|x| x["coefficient"].as_str().unwrap().parse().unwrap())
            .unwrap_or(0)
    };
    let (c00, c10, c01) = (c(0, 0), c(1, 0), c(0, 1));
    assert_eq!(terms.len(), 3);
    assert_eq!((c10, c01), (2 * c00, -4 * c00));
}

#[test]
fn a_point_hit_twice_by_each_curve_is_four_pairs() {
    let t = text("loop.toml", "loop_rot.toml");
    assert!(t.contains(": 4 intersection points\n"), "{t}");
}

#[test]
fn a_claim_of_no_points_fails_on_an_overlap() {
    let out = tribez()
        .args(["check", &fx("seg_fold2_false_claim.toml")])
        .assert()
        .code(1)
        .get_output()
        .stdout
        .clone();
    let t = String::from_utf8(out).unwrap();
    assert!(t.contains("share a piece"), "{t}");
}

#[test]
fn a_pair_above_the_work_limit_stops_at_once() {
    // two degree-11 curves with 40-bit coordinates: D = 121, L ≥ 22·40 = 880, so
    // D²·(D + L) ≥ 14641·1001 > 14 million, above the limit of 12 million (guide, intersect)
    let start = std::time::Instant::now();
    let out = tribez()
        .args(["intersect", &fx("big11_a.toml"), &fx("big11_b.toml")])
        .assert()
        .code(2)
        .get_output()
        .clone();
    assert!(out.stdout.is_empty());
    let err = String::from_utf8(out.stderr).unwrap();
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.contains("big11_a.toml") && err.contains("big11_b.toml"),
        "{err}"
    );
    assert!(err.contains("above the limit 12000000"), "{err}");
    assert!(start.elapsed().as_secs() < 10);
}
