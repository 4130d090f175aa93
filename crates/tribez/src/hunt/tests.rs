//! The hunt: deterministic for a seed, the budget counted, consistent rows, and the planted
//! faults of the benchmark (bench/hunt/) found within a small budget. Expected verdicts come
//! from the faults' definitions (hand derivation next to each test), never from tribez's output.

use super::*;
use crate::patch_type::{Degree, SimplexDim};

/// A cubic Bézier triangle in R² with positive control points `(1 + r, 2 + r + s)` for the
/// `r`-th multi-index (canonical order) and `s = r mod 3`: its values are positive, so its
/// condition number is 1 (Σ|c_i|B_i = Σ c_i B_i) and `cond` allows `K · ε · |value|` with
/// `K = (m+1)·n = 9`.
fn cubic() -> Patch {
    let q = |k: i64| BigRational::from_integer(k.into());
    let points = (0..10)
        .map(|r: i64| vec![q(1 + r), q(2 + r + r % 3)])
        .collect();
    Patch::bezier(SimplexDim(2), Degree(3), points).unwrap()
}

/// The control points of [`cubic`] in `f64`, by multi-index `(i, j, k)` in the canonical order
/// (Finn's `200, 110, 020, 101, 011, 002` at degree 2: `k` ascending, then `j` ascending).
fn cubic_f64() -> Vec<([usize; 3], [f64; 2])> {
    let mut out = Vec::new();
    let mut r = 0;
    for k in 0..=3 {
        for j in 0..=3 - k {
            let i = 3 - k - j;
            out.push(([i, j, k], [1.0 + r as f64, 2.0 + (r + r % 3) as f64]));
            r += 1;
        }
    }
    out
}

/// de Casteljau in `f64` on [`cubic`] at `(u, v, w)`, written here independently of tribez.
fn casteljau(l: [f64; 3]) -> [f64; 2] {
    let n = 3;
    let mut pts: std::collections::HashMap<[usize; 3], [f64; 2]> =
        cubic_f64().into_iter().collect();
    for level in (1..=n).rev() {
        let mut next = std::collections::HashMap::new();
        for i in 0..level {
            for j in 0..level - i {
                let k = level - 1 - i - j;
                let a = pts[&[i + 1, j, k]];
                let b = pts[&[i, j + 1, k]];
                let c = pts[&[i, j, k + 1]];
                next.insert(
                    [i, j, k],
                    [
                        l[0] * a[0] + l[1] * b[0] + l[2] * c[0],
                        l[0] * a[1] + l[1] * b[1] + l[2] * c[1],
                    ],
                );
            }
        }
        pts = next;
    }
    pts[&[0, 0, 0]]
}

/// A target from a function of one row.
fn target(
    f: impl Fn([f64; 3]) -> [f64; 2],
) -> impl FnMut(&[f64]) -> Result<Vec<f64>, std::convert::Infallible> {
    move |rows: &[f64]| Ok(rows.chunks(3).flat_map(|r| f([r[0], r[1], r[2]])).collect())
}

fn cond_options(budget: u64, seed: u64) -> HuntOptions {
    let mut o = HuntOptions::new(Precision::F64, Tolerance::parse("cond").unwrap());
    o.budget = budget;
    o.seed = seed;
    o
}

#[test]
fn the_same_seed_gives_the_same_rows_and_report() {
    let run = |seed| {
        let mut given = Vec::new();
        let mut t = |rows: &[f64]| -> Result<Vec<f64>, std::convert::Infallible> {
            given.extend_from_slice(rows);
            Ok(rows
                .chunks(3)
                .flat_map(|r| casteljau([r[0], r[1], r[2]]))
                .collect())
        };
        let report = hunt(&cubic(), &cond_options(900, seed), &mut t).unwrap();
        let worst: Vec<(u64, f64)> = report.worst.iter().map(|r| (r.row, r.ulps)).collect();
        (given.iter().map(|x| x.to_bits()).collect::<Vec<_>>(), worst)
    };
    let (a, wa) = run(7);
    let (b, wb) = run(7);
    let (c, _) = run(8);
    assert_eq!(a, b);
    assert_eq!(wa, wb);
    assert_ne!(a, c);
}

#[test]
fn the_budget_counts_rows_given_and_batches_are_capped() {
    let mut calls = Vec::new();
    let mut t = |rows: &[f64]| -> Result<Vec<f64>, std::convert::Infallible> {
        calls.push(rows.len() / 3);
        Ok(rows
            .chunks(3)
            .flat_map(|r| casteljau([r[0], r[1], r[2]]))
            .collect())
    };
    let mut o = cond_options(1000, 1);
    o.batch = 100;
    let report = hunt(&cubic(), &o, &mut t).unwrap();
    assert_eq!(calls.iter().sum::<usize>(), 1000);
    assert!(calls.iter().all(|&n| n <= 100));
    assert_eq!(report.evaluated, 1000);
    assert_eq!(report.by_kind.iter().sum::<u64>(), 1000);
    // de Casteljau in f64 is backward stable: within `cond` everywhere (theory §14)
    assert_eq!(report.broke, 0);
    assert!(report.worst.iter().all(|r| r.passed));
}

#[test]
fn rows_are_consistent_floats_of_the_precision() {
    for (precision, cartesian) in [
        (Precision::F64, false),
        (Precision::F32, false),
        (Precision::F64, true),
        (Precision::F32, true),
    ] {
        let mut o = cond_options(2000, 3);
        o.precision = precision;
        o.cartesian = cartesian;
        let w = if cartesian { 2 } else { 3 };
        let mut rows_seen = Vec::new();
        let mut t = |rows: &[f64]| -> Result<Vec<f64>, std::convert::Infallible> {
            rows_seen.extend_from_slice(rows);
            Ok(rows
                .chunks(w)
                .flat_map(|r| {
                    let l = if cartesian {
                        [r[0], r[1], 1.0 - r[0] - r[1]]
                    } else {
                        [r[0], r[1], r[2]]
                    };
                    casteljau(l)
                })
                .collect())
        };
        hunt(&cubic(), &o, &mut t).unwrap();
        for r in rows_seen.chunks(w) {
            for &x in r {
                assert!(x.is_finite() && (0.0..=1.0).contains(&x), "{r:?}");
                if precision == Precision::F32 {
                    assert_eq!(f64::from(x as f32), x, "{r:?}");
                }
            }
            if cartesian {
                // the reference triangle (1,0), (0,1), (0,0): x + y ≤ 1 exactly (a sum that
                // rounds to 1 in f64 may exceed it)
                let exact = |x: f64| crate::number::exact_f64(x).unwrap();
                assert!(
                    exact(r[0]) + exact(r[1]) <= BigRational::from_integer(1.into()),
                    "{r:?}"
                );
            } else {
                // the sum is 1 up to the rounding of the largest coordinate: within 2 ulps of 1
                let s: f64 = r.iter().sum();
                let ulp = if precision == Precision::F32 {
                    2f64.powi(-23)
                } else {
                    2f64.powi(-52)
                };
                assert!((s - 1.0).abs() <= 2.0 * ulp, "{r:?}");
            }
        }
    }
}

/// Benchmark target (3): a correct de Casteljau except that when the smallest barycentric
/// coordinate lies in [1e-9, 2e-9] the result is multiplied by `1 + 2^-20`: a relative error of
/// about 2^-20, i.e. about 2^32 ulps, far over `cond`'s `9 · 2^-53` relative (the values are
/// positive, condition number 1). Only such rows break `cond`.
#[test]
fn finds_the_fault_in_a_narrow_band_of_the_smallest_coordinate() {
    let faulty = |l: [f64; 3]| {
        let p = casteljau(l);
        let min = l[0].min(l[1]).min(l[2]);
        if (1e-9..=2e-9).contains(&min) {
            p.map(|x| x * (1.0 + 2f64.powi(-20)))
        } else {
            p
        }
    };
    let mut found = 0;
    for seed in 0..10 {
        let report = hunt(&cubic(), &cond_options(3000, seed), &mut target(faulty)).unwrap();
        if report.broke > 0 {
            found += 1;
            let w = &report.worst[0];
            assert!(!w.passed);
            let min = w.input.iter().cloned().fold(f64::INFINITY, f64::min);
            assert!((1e-9..=2e-9).contains(&min), "{:?}", w.input);
            // ≈ 2^-20 relative to values between 1 and 12: over 2^29 ulps
            assert!(w.ulps > 2f64.powi(29));
        }
        // every failing row is in the band
        assert!(report.worst.iter().all(|r| r.passed
            || (1e-9..=2e-9).contains(&r.input.iter().cloned().fold(f64::INFINITY, f64::min))));
    }
    assert!(found >= 9, "found in {found} of 10 seeds");
}

/// Benchmark target (4): de Casteljau on the inputs rounded to `f32` when a coordinate is over
/// 0.999. Rounding moves a coordinate near 1 by up to 2^-25 absolute; the value changes by the
/// gradient (control points differ by 1 to 12) times that, ≥ 2^-29 or so, while `cond` allows
/// `9 · 2^-53 · |value|` ≤ 2^-45: such rows break `cond` unless the rounding is exact.
#[test]
fn finds_inputs_rounded_to_f32_near_a_corner() {
    let faulty = |l: [f64; 3]| {
        if l.iter().any(|&x| x > 0.999) {
            casteljau(l.map(|x| f64::from(x as f32)))
        } else {
            casteljau(l)
        }
    };
    let mut found = 0;
    for seed in 0..10 {
        let report = hunt(&cubic(), &cond_options(3000, seed), &mut target(faulty)).unwrap();
        if report.broke > 0 {
            found += 1;
            assert!(report.worst[0].input.iter().any(|&x| x > 0.999));
        }
    }
    assert!(found >= 9, "found in {found} of 10 seeds");
}

#[test]
fn the_targets_error_and_a_wrong_count_end_the_hunt() {
    let mut calls = 0;
    let mut failing = |_: &[f64]| -> Result<Vec<f64>, String> {
        calls += 1;
        Err("boom".into())
    };
    let e = hunt(&cubic(), &cond_options(500, 0), &mut failing).unwrap_err();
    assert!(matches!(e, HuntError::Target(ref s) if s == "boom"));
    assert_eq!(calls, 1);
    let mut short = |rows: &[f64]| -> Result<Vec<f64>, String> { Ok(vec![0.0; rows.len() / 3]) };
    let e = hunt(&cubic(), &cond_options(500, 0), &mut short).unwrap_err();
    assert!(
        matches!(
            e,
            HuntError::Answer {
                first: 1,
                dim: 2,
                ..
            }
        ),
        "{e}"
    );
}

#[test]
fn the_worst_rows_carry_the_exact_value_at_the_input_seen() {
    // a target that answers 0: its error is the exact value itself; at the corner (1, 0, 0)
    // the value is the first control point (1, 2)
    let mut zero = |rows: &[f64]| -> Result<Vec<f64>, String> { Ok(vec![0.0; rows.len() / 3 * 2]) };
    let mut o = cond_options(300, 0);
    o.top = 300;
    let report = hunt(&cubic(), &o, &mut zero).unwrap();
    assert_eq!(report.broke, 300);
    let q = |k: i64| BigRational::from_integer(k.into());
    let corner = report
        .worst
        .iter()
        .find(|r| r.input == [1.0, 0.0, 0.0])
        .expect("the corners are sampled");
    assert_eq!(corner.exact, [q(1), q(2)]);
}

#[test]
fn options_out_of_range_and_other_patches_are_refused() {
    let mut t = target(casteljau);
    let mut o = cond_options(0, 0);
    assert!(matches!(
        hunt(&cubic(), &o, &mut t),
        Err(HuntError::Options(_))
    ));
    o.budget = 10;
    o.batch = 0;
    assert!(matches!(
        hunt(&cubic(), &o, &mut t),
        Err(HuntError::Options(_))
    ));
}

#[test]
fn claimed_lines_are_read_as_results_rows_are() {
    use crate::batch::parse_claimed_line;
    let p = Precision::F64;
    assert_eq!(
        parse_claimed_line("0x1p-1, 0.25\n", 2, p),
        Ok(vec![0.5, 0.25])
    );
    assert_eq!(parse_claimed_line("[1, \"2\"]", 2, p), Ok(vec![1.0, 2.0]));
    // 0.1 to f32: the float nearest 1/10
    assert_eq!(
        parse_claimed_line("0.1,1/3", 2, Precision::F32),
        Ok(vec![f64::from(0.1f32), f64::from(1.0f32 / 3.0)])
    );
    assert!(parse_claimed_line("nan,1", 2, p).unwrap()[0].is_nan());
    assert!(parse_claimed_line(",1", 2, p).unwrap()[0].is_nan());
    // what the program said is kept: an infinity, or an overflow of the precision (round to
    // nearest gives ±∞ beyond MAX + ulp(MAX)/2), is ±∞, not NaN
    assert_eq!(
        parse_claimed_line("inf,-Infinity", 2, p),
        Ok(vec![f64::INFINITY, f64::NEG_INFINITY])
    );
    assert_eq!(
        parse_claimed_line("1e400,-1e999999", 2, p),
        Ok(vec![f64::INFINITY, f64::NEG_INFINITY])
    );
    assert_eq!(
        parse_claimed_line("-1e39,\"+inf\"", 2, Precision::F32),
        Ok(vec![f64::NEG_INFINITY, f64::INFINITY])
    );
    assert_eq!(
        parse_claimed_line("1,2,3", 2, p),
        Err("3 numbers, expected 2".into())
    );
    assert_eq!(
        parse_claimed_line("7", 2, p),
        Err("1 number, expected 2".into())
    );
    assert_eq!(parse_claimed_line("", 2, p), Err("an empty line".into()));
    assert!(
        parse_claimed_line("1,abc", 2, p)
            .unwrap_err()
            .starts_with("column 3")
    );
}

/// The exact value a report lists is the one the row was judged against: at the inputs as the
/// target saw them, with the control points rounded to the precision (guide §7). A linear
/// triangle with the control values 1/3, 1/3, 1/3 (a constant patch) has, in f64, the control
/// values fl(1/3) = 6004799503160661 / 2^54 (the double nearest 1/3: 2^54/3 = 6004799503160661.33…
/// rounds down), so its value at any barycentric floats λ is fl(1/3) · Σλ, not 1/3 · Σλ. At the
/// rows the hunt gives (whose sums may differ from 1 by a few ulps) the listed exact value must be
/// fl(1/3) · Σλ exactly; with the exact control values it would differ from that by
/// (1/3 − fl(1/3)) · Σλ ≠ 0.
#[test]
fn a_listed_exact_value_uses_the_control_points_as_the_target_saw_them() {
    let third = BigRational::new(1.into(), 3.into());
    let patch = Patch::bezier(SimplexDim(2), Degree(1), vec![vec![third.clone()]; 3]).unwrap();
    let fl_third = BigRational::new(6004799503160661i64.into(), (1i64 << 54).into());
    assert_ne!(fl_third, third);
    let mut options = cond_options(300, 7);
    options.top = 5;
    // a target that answers 0.5 everywhere: every row breaks `cond`, so rows are listed
    let mut t = |rows: &[f64]| -> Result<Vec<f64>, std::convert::Infallible> {
        Ok(vec![0.5; rows.len() / 3])
    };
    let report = hunt(&patch, &options, &mut t).unwrap();
    assert_eq!(report.worst.len(), 5);
    for row in &report.worst {
        let sum: BigRational = row
            .input
            .iter()
            .map(|&x| crate::number::exact_f64(x).unwrap())
            .sum();
        assert_eq!(row.exact, vec![&fl_third * &sum], "row {}", row.row);
        assert!(!row.passed);
    }
}

#[test]
fn the_samplers_value_and_scale_are_de_casteljau_on_the_net_and_its_absolute_values() {
    // the cubic's values are positive: Σ|c_i| B_i = Σ c_i B_i, and both are the test's own
    // de Casteljau (the same sums in the same order, so bit for bit)
    let bezier = |p: Patch| match p.as_any() {
        crate::any_patch::AnyPatch::Bezier(b) => b.clone(),
        _ => unreachable!("a Bézier patch"),
    };
    let b = bezier(cubic());
    let o = cond_options(10, 0);
    let space = super::space(&b, &Domain::reference(2), &o);
    for l in [
        [1.0, 0.0, 0.0],
        [0.25, 0.5, 0.25],
        [0.1, 0.2, 0.7],
        [1e-9, 0.3, 0.7 - 1e-9],
    ] {
        let (v, s) = space.value_and_scale(&l);
        assert_eq!(v, casteljau(l));
        assert_eq!(s, casteljau(l));
    }
    // a net of mixed signs: the scale is de Casteljau on |c| (here c = ±1 alternating in rank
    // at degree 1, value λ_0 − λ_1 + λ_2, scale λ_0 + λ_1 + λ_2)
    let q = |k: i64| vec![BigRational::from_integer(k.into())];
    let lin = Patch::bezier(SimplexDim(2), Degree(1), vec![q(1), q(-1), q(1)]).unwrap();
    let b = bezier(lin);
    let space = super::space(&b, &Domain::reference(2), &o);
    let (v, s) = space.value_and_scale(&[0.5, 0.25, 0.25]);
    assert_eq!((v, s), (vec![0.5], vec![1.0]));
}

/// The text report says how large an error too large for an `f64` in ULPs is (an answer
/// `1e-10` against an exact 0, whose ulp is `2^-1074`: about `2^1040` ulps), and keeps
/// `not finite` for an answer that is not finite.
#[test]
fn an_error_beyond_f64_in_ulps_reads_more_than_the_largest_float() {
    let row = |row, claimed: f64| HuntRow {
        row,
        input: vec![1.0, 0.0, 0.0],
        claimed: vec![claimed],
        exact: vec![BigRational::from_integer(0.into())],
        ulps: f64::INFINITY,
        passed: false,
        reason: None,
    };
    let report = HuntReport {
        precision: Precision::F64,
        tolerance: Tolerance::parse("abs=1e-12").unwrap(),
        seed: 1,
        budget: 2,
        cartesian: false,
        evaluated: 2,
        broke: 2,
        by_kind: [2, 0, 0],
        worst: vec![row(1, 1e-10), row(2, f64::INFINITY)],
    };
    let text = report.text(&HuntLabels {
        tool: "tribez hunt",
        patch: "p.toml",
        program: "prog",
        reproduce: "again",
    });
    assert!(
        text.contains("  1. row 1: more than 1.798e308 ulp, breaks the tolerance\n"),
        "{text}"
    );
    assert!(
        text.contains("  2. row 2: not finite ulp, breaks the tolerance\n"),
        "{text}"
    );
    assert!(text.contains("claimed  inf\n"), "{text}");
    assert!(text.contains("the 2 worst rows:\n"), "{text}");
}
