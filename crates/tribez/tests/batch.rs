//! The batch checker's in-memory rows and `BatchReport::merge`.
//!
//! Hand-derived figures: Finn's worked example patch (degree 2; control points 200:(0,0,0)
//! 110:(1,0,2) 020:(0,2,0) 101:(0,1,0) 011:(1,1,1) 002:(0,2,1)) at (1/2, 1/4, 1/4), where the
//! Bernstein weights are u² = 1/4, 2uv = 1/4, v² = 1/16, 2uw = 1/4, 2vw = 1/8, w² = 1/16, so
//! the point is exactly (1/4 + 1/8, 2/16 + 1/4 + 1/8 + 2/16, 2/4 + 1/8 + 1/16) =
//! (3/8, 5/8, 11/16): three floats. The float after 11/16 = 0.6875 (in [1/2, 1), where the ulp
//! is 2^-53) is one ulp away.

use std::path::PathBuf;

use proptest::prelude::*;
use tribez::Precision;
use tribez::ResultsChecker;
use tribez::Tolerance;
use tribez::batch::{BatchChecker, BatchError, BatchOptions, BatchReport, Format};
use tribez::hazmat::io::patch_file::read_patch;

fn finn() -> tribez::hazmat::patch::BezierPatch {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../fixtures/finn_day30.toml");
    read_patch(&path).unwrap()
}

fn checker(tolerance: &str, detail: bool) -> BatchChecker {
    let options = BatchOptions {
        tolerance: Tolerance::parse(tolerance).unwrap(),
        precision: Some(Precision::F64),
        row_detail: detail,
        ..BatchOptions::default()
    };
    BatchChecker::new(finn(), &options).unwrap()
}

fn next_up(x: f64) -> f64 {
    f64::from_bits(x.to_bits() + 1)
}

#[test]
fn in_memory_rows_are_judged_with_hand_derived_figures() {
    let c = checker("ulps=1/2", true);
    let points = [0.5, 0.25, 0.25, 0.5, 0.25, 0.25, 0.5, 0.25, 0.25];
    let values = [
        0.375,
        0.625,
        0.6875,
        0.375,
        0.625,
        next_up(0.6875),
        0.375,
        f64::NAN,
        0.6875,
    ];
    let r = c
        .check_rows(&points, &values, 0, "<memory>", "finn")
        .map(|r| r.0)
        .unwrap();
    assert_eq!((r.checked, r.passed, r.failed), (3, 1, 2));
    assert_eq!(r.max_ulps, Some(1.0));
    let worst = r.worst.as_ref().unwrap();
    assert_eq!((worst.line, worst.ulps), (1, 1.0));
    // buckets: "0" (row 0), "(1/2, 1]" (row 1), "> 256" (row 2: not a number)
    assert_eq!(r.histogram.counts, [1, 0, 1, 0, 0, 0, 0, 1]);
    let lines: Vec<usize> = r.failures.iter().map(|f| f.line).collect();
    assert_eq!(lines, [1, 2]);
    let rows = r.rows.as_ref().unwrap();
    assert_eq!(rows.len(), 3);
    assert!(rows[0].passed && rows[0].correctly_rounded && rows[0].ulps_seen == 0.0);
    assert_eq!(rows[0].ulps_intended, Some(0.0));
    assert!(!rows[1].passed && !rows[1].correctly_rounded);
    assert_eq!((rows[1].ulps_seen, rows[1].ulps_intended), (1.0, Some(1.0)));
    assert!(!rows[2].passed && rows[2].ulps_seen.is_infinite());
}

/// Errors computed exactly are counted in their true bucket, also a hair above a bucket's
/// bound. The linear functional patch with control values 1, 1, 1 is `P(λ) = λ_0 + λ_1 + λ_2`
/// (any sum: the homogeneous form). At λ = (1, 2^-53, 2^-200), P = 1 + 2^-53 + 2^-200 lies just
/// above the midpoint of 1 and its successor (ulp 2^-52), so the claim 1 is off by
/// 1/2 + 2^-148 ulp: not correctly rounded, and in the bucket "(1/2, 1]" (rounding the exact
/// error to nearest, 0.5, would put it in "(0, 1/2]"). At (1, 2^-53, 0), P is the midpoint
/// itself, a tie that 1 wins (even): 1/2 ulp, correctly rounded. At (1, 2^-54, 2^-200) the
/// error is 1/4 + 2^-148 ulp.
#[test]
fn exact_errors_a_hair_above_a_bucket_bound_are_counted_above_it() {
    use tribez::hazmat::patch::{BezierPatch, ControlNet};
    use tribez::hazmat::simplex::Simplex;
    let one = tribez::Rational::from_integer(1.into());
    let patch = BezierPatch::new(ControlNet::new(Simplex::new(2, 1), 1, vec![one; 3]));
    let options = BatchOptions {
        tolerance: Tolerance::parse("correctly_rounded").unwrap(),
        precision: Some(Precision::F64),
        row_detail: true,
        ..BatchOptions::default()
    };
    let c = BatchChecker::new(patch, &options).unwrap();
    let (p53, p54, p200) = (2f64.powi(-53), 2f64.powi(-54), 2f64.powi(-200));
    let points = [1.0, p53, p200, 1.0, p53, 0.0, 1.0, p54, p200];
    let r = c
        .check_rows(&points, &[1.0; 3], 0, "<memory>", "sum")
        .unwrap()
        .0;
    assert_eq!((r.checked, r.passed, r.failed), (3, 2, 1));
    assert_eq!(r.histogram.counts, [0, 2, 1, 0, 0, 0, 0, 0]);
    let rows = r.rows.as_ref().unwrap();
    assert!(!rows[0].passed && !rows[0].correctly_rounded);
    // the least float not below 1/2 + 2^-148
    assert_eq!(rows[0].ulps_seen, 0.5f64.next_up());
    assert!(rows[1].passed && rows[1].correctly_rounded);
    assert_eq!(rows[1].ulps_seen, 0.5);
    assert!(rows[2].passed && rows[2].ulps_seen > 0.25 && rows[2].ulps_seen <= 0.25f64.next_up());
    // rows are numbered from the offset given (0)
    assert_eq!(r.worst.as_ref().unwrap().line, 0);
}

#[test]
fn in_memory_shapes_are_checked() {
    let c = checker("ulps=1", false);
    assert!(matches!(
        c.check_rows(&[0.5, 0.5], &[0.0, 0.0, 0.0], 0, "<memory>", "finn")
            .map(|r| r.0),
        Err(BatchError::Shape {
            what: "points",
            per_row: 3,
            len: 2
        })
    ));
    assert!(matches!(
        c.check_rows(&[0.5, 0.25, 0.25], &[0.0; 4], 0, "<memory>", "finn"),
        Err(BatchError::Shape {
            what: "values",
            per_row: 3,
            len: 4
        })
    ));
    assert!(matches!(
        c.check_rows(&[0.5, 0.25, 0.25], &[0.0; 6], 0, "<memory>", "finn"),
        Err(BatchError::RowCounts {
            points: 1,
            values: 2
        })
    ));
    let empty = c.check_rows(&[], &[], 0, "<memory>", "finn");
    assert_eq!(empty.unwrap_err().to_string(), "<memory>: no result rows");
}

/// Rows near Finn's patch's values: a float point, and each claimed coordinate the f64 de
/// Casteljau value moved by `shift` ulps (`None`: a NaN).
fn rows(spec: &[(f64, f64, [Option<i8>; 3])]) -> (Vec<f64>, Vec<f64>) {
    let net = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 2.0],
        [0.0, 2.0, 0.0],
        [0.0, 1.0, 0.0],
        [1.0, 1.0, 1.0],
        [0.0, 2.0, 1.0],
    ];
    let (mut points, mut values) = (Vec::new(), Vec::new());
    for &(a, b, shifts) in spec {
        let (u, v) = (a, b * (1.0 - a));
        let w = 1.0 - u - v;
        points.extend([u, v, w]);
        for (k, s) in shifts.iter().enumerate() {
            // f64 de Casteljau, degree 2
            let lerp = |p: f64, q: f64, r: f64| u * p + v * q + w * r;
            let (p200, p110, p020, p101, p011, p002) = (
                net[0][k], net[1][k], net[2][k], net[3][k], net[4][k], net[5][k],
            );
            let y = lerp(
                lerp(p200, p110, p101),
                lerp(p110, p020, p011),
                lerp(p101, p011, p002),
            );
            values.push(match s {
                None => f64::NAN,
                Some(s) if y != 0.0 => f64::from_bits((y.to_bits() as i64 + i64::from(*s)) as u64),
                Some(_) => y,
            });
        }
    }
    (points, values)
}

fn same(a: &BatchReport, b: &BatchReport) {
    assert_eq!(
        (
            a.checked,
            a.passed,
            a.failed,
            a.fell_back,
            a.histogram_exact
        ),
        (
            b.checked,
            b.passed,
            b.failed,
            b.fell_back,
            b.histogram_exact
        )
    );
    assert_eq!(a.histogram, b.histogram);
    assert_eq!(a.max_ulps, b.max_ulps);
    assert_eq!(
        a.worst.as_ref().map(|w| (w.line, w.ulps)),
        b.worst.as_ref().map(|w| (w.line, w.ulps))
    );
    let lines = |r: &BatchReport| {
        r.failures
            .iter()
            .map(|f| (f.line, f.reason.clone()))
            .collect::<Vec<_>>()
    };
    assert_eq!(lines(a), lines(b));
    assert_eq!(a.rows, b.rows);
}

fn row_spec() -> impl Strategy<Value = (f64, f64, [Option<i8>; 3])> {
    let shift = prop_oneof![8 => (-3i8..=3).prop_map(Some), 1 => Just(None)];
    // few distinct points, so that equal errors (ties for the worst row) are common
    (
        prop_oneof![Just(0.5), Just(0.25), 0.0f64..1.0],
        prop_oneof![Just(0.5), 0.0f64..1.0],
        [shift.clone(), shift.clone(), shift],
    )
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]
    #[test]
    fn merging_the_reports_of_slices_gives_the_report_of_the_whole(
        spec in prop::collection::vec(row_spec(), 1..40),
        cuts in prop::collection::vec(0usize..40, 0..4),
        reverse in any::<bool>(),
        detail in any::<bool>(),
    ) {
        let c = checker("ulps=1", detail);
        let (points, values) = rows(&spec);
        let whole = c.check_rows(&points, &values, 0, "<memory>", "finn").map(|r| r.0).unwrap();
        let n = spec.len();
        let mut bounds: Vec<usize> = cuts.into_iter().map(|k| k % (n + 1)).collect();
        bounds.extend([0, n]);
        bounds.sort_unstable();
        bounds.dedup(); // empty slices are not reports (no rows is an error)
        let mut parts: Vec<BatchReport> = bounds
            .windows(2)
            .map(|w| c.check_rows(&points[3 * w[0]..3 * w[1]], &values[3 * w[0]..3 * w[1]], w[0], "<memory>", "finn").map(|r| r.0).unwrap())
            .collect();
        if reverse {
            parts.reverse();
        }
        let mut merged = parts.remove(0);
        for p in &parts {
            merged.merge(p).unwrap();
        }
        same(&merged, &whole);
    }
}

#[test]
fn rows_in_memory_and_in_a_csv_file_agree() {
    let spec: Vec<_> = (0..50)
        .map(|i| {
            let t = f64::from(i) / 50.0;
            (
                t,
                1.0 - t,
                [Some((i % 5) as i8 - 2), Some(0), Some((i % 3) as i8 - 1)],
            )
        })
        .collect();
    let (points, values) = rows(&spec);
    let c = checker("ulps=1", false);
    let memory = c
        .check_rows(&points, &values, 1, "<memory>", "finn")
        .map(|r| r.0)
        .unwrap();
    let csv: String = points
        .chunks(3)
        .zip(values.chunks(3))
        .map(|(p, v)| {
            format!(
                "{:?},{:?},{:?},{:?},{:?},{:?}\n",
                p[0], p[1], p[2], v[0], v[1], v[2]
            )
        })
        .collect();
    let file = c
        .check_reader(
            csv.as_bytes(),
            Format::Csv,
            "<memory>",
            "finn",
            &mut |_, _| {},
        )
        .unwrap();
    same(&memory, &file);
    assert!(memory.failed > 0 && memory.passed > 0);
}

/// Many rows (several slabs between stop tests, each split over the threads): the in-memory
/// path, which judges rows the float filter decides from their floats alone, gives the report a
/// CSV file of the same rows gives, and every row the verdict the path without that shortcut
/// (with per-row detail, every row through its parsed numbers) gives. Errors from a few shifts,
/// so that ties for the worst row are common; more failures than are listed; NaN rows.
#[test]
fn many_rows_in_memory_agree_with_a_csv_file_and_with_the_detailed_path() {
    let spec: Vec<_> = (0..20_000u32)
        .map(|i| {
            let shift = |k: u32| match (i / 7 + k) % 23 {
                0 => None,
                r => Some((r % 3) as i8 - 1),
            };
            (
                f64::from(i % 101) / 101.0,
                f64::from(i % 37) / 37.0,
                [shift(0), Some(0), shift(2)],
            )
        })
        .collect();
    let (points, values) = rows(&spec);
    let c = checker("ulps=1", false);
    let (memory, verdicts) = c
        .check_rows(&points, &values, 0, "<memory>", "finn")
        .unwrap();
    assert!(memory.failed > 100 && memory.passed > 0);
    let csv: String = points
        .chunks(3)
        .zip(values.chunks(3))
        .map(|(p, v)| {
            format!(
                "{:?},{:?},{:?},{:?},{:?},{:?}\n",
                p[0], p[1], p[2], v[0], v[1], v[2]
            )
        })
        .collect();
    let file = c
        .check_reader(
            csv.as_bytes(),
            Format::Csv,
            "<memory>",
            "finn",
            &mut |_, _| {},
        )
        .unwrap();
    // CSV rows are numbered by line from 1, memory rows from first_row = 0
    let memory_1 = c
        .check_rows(&points, &values, 1, "<memory>", "finn")
        .unwrap()
        .0;
    // (`same` leaves out the errors at the intended inputs: those of the CSV are its decimal
    // texts', those of memory the f64s')
    same(&memory_1, &file);
    let (detailed, detailed_verdicts) = checker("ulps=1", true)
        .check_rows(&points, &values, 0, "<memory>", "finn")
        .unwrap();
    assert_eq!(verdicts.len(), spec.len());
    for (i, (a, b)) in verdicts.iter().zip(&detailed_verdicts).enumerate() {
        assert_eq!(a.row, i);
        assert_eq!((a.pass, a.fell_back), (b.pass, b.fell_back), "row {i}");
        assert_eq!(a.ulps.to_bits(), b.ulps.to_bits(), "row {i}");
    }
    assert_eq!(
        (memory.passed, memory.failed, memory.max_ulps),
        (detailed.passed, detailed.failed, detailed.max_ulps)
    );
    assert_eq!(memory.histogram, detailed.histogram);
}

/// A planar patch embedded in R^3: degree 4 on the triangle with c_α = (α_1/4, α_2/4, 0), so by
/// linear precision P(λ) = (λ_1, λ_2, 0) exactly (every control value a float). The third
/// coordinate is zero at every point: the float filter decides it without exact arithmetic, so
/// no row falls back; a claimed third coordinate of ±2^-1074 is exactly 1 ulp of 0 (hand
/// derivation: ulp_f64(0) is the smallest subnormal), failing `ulps=1/2` and `cond` (whose
/// threshold is K·ε·0 = 0 there) and passing `ulps=1`.
#[test]
fn an_identically_zero_coordinate_never_falls_back() {
    use tribez::hazmat::patch::{BezierPatch, ControlNet};
    use tribez::hazmat::simplex::Simplex;
    let simplex = Simplex::new(2, 4);
    let coords: Vec<tribez::Rational> = simplex
        .iter()
        .flat_map(|a| {
            [
                tribez::Rational::new(i64::from(a[1]).into(), 4.into()),
                tribez::Rational::new(i64::from(a[2]).into(), 4.into()),
                tribez::Rational::from_integer(0.into()),
            ]
        })
        .collect();
    let patch = BezierPatch::new(ControlNet::new(simplex, 3, coords));
    let tiny = f64::from_bits(1);
    let (mut points, mut values, mut off) = (Vec::new(), Vec::new(), 0);
    for i in 0..400u32 {
        // no coordinate but the third is zero at these points (a value that vanishes at a
        // point only is enclosed, not known, and may fall back)
        let l1 = f64::from(i % 20 + 1) / 32.0;
        let l2 = f64::from(i / 20 + 1) / 64.0;
        points.extend([1.0 - l1 - l2, l1, l2]);
        let z = match i % 40 {
            7 => tiny,
            13 => -tiny,
            _ => 0.0,
        };
        off += usize::from(z != 0.0);
        values.extend([l1, l2, z]);
    }
    for (tol, failed) in [("ulps=1/2", off), ("cond", off), ("ulps=1", 0)] {
        let options = BatchOptions {
            tolerance: Tolerance::parse(tol).unwrap(),
            precision: Some(Precision::F64),
            ..BatchOptions::default()
        };
        let c = BatchChecker::new(patch.clone(), &options).unwrap();
        let r = c
            .check_rows(&points, &values, 0, "<memory>", "plane")
            .unwrap()
            .0;
        assert_eq!((r.checked, r.failed as usize), (400, failed), "{tol}");
        assert_eq!(r.fell_back, 0, "{tol}");
    }
}

/// `--cartesian` rows go through the float filter (docs/theory.md §14.5). A cubic with control
/// values k/8 − 1 (floats, so the code sees them exactly) over a triangle (0,0), (3,0), (1, h);
/// at 300 float points the claimed values are the correctly rounded exact values (the generic
/// exact path: exact barycentric coordinates by Cramer's rule, rational de Casteljau), so every
/// row meets `ulps=1/2` and `ulps=64`; moved by a relative 2^-30 on one coordinate (about 2^22
/// ulps), every row fails `ulps=64`. For h = 2 the filter decides nearly every row, even at
/// `ulps=1/2`: it evaluates at the double-double barycentric coordinates, whose enclosure is as
/// tight as a barycentric row's, and every row's figure lands in its true bucket (`0` or
/// `(0, 1/2]`: correctly rounded claims). For the thin h = 2^-20 (barycentric coordinates known
/// in floats to about 2^20 ε) the verdicts are the same.
#[test]
fn cartesian_rows_are_decided_by_the_filter_and_agree_with_the_exact_path() {
    use tribez::Rational;
    use tribez::hazmat::domain::Domain;
    use tribez::hazmat::exact::{Algorithm, ExactEvaluator};
    use tribez::hazmat::number::{exact_f64, round_f64};
    use tribez::hazmat::patch::{BezierPatch, ControlNet};
    use tribez::hazmat::simplex::Simplex;
    let q = |x: f64| exact_f64(x).unwrap();
    let simplex = Simplex::new(2, 3);
    let coords: Vec<Rational> = (0..simplex.len() * 2)
        .map(|i| {
            Rational::new(((i * 7919) % 23).into(), 8.into()) - Rational::from_integer(1.into())
        })
        .collect();
    let net = ControlNet::new(simplex, 2, coords);
    let exact = ExactEvaluator::new(&net);
    for h in [2.0, 2f64.powi(-20)] {
        let domain = Domain::new(vec![
            vec![q(0.0), q(0.0)],
            vec![q(3.0), q(0.0)],
            vec![q(1.0), q(h)],
        ])
        .unwrap();
        let mut patch = BezierPatch::new(net.clone());
        patch.domain = Some(domain.clone());
        let (mut points, mut good, mut bad) = (Vec::new(), Vec::new(), Vec::new());
        for i in 0..300u32 {
            let s = f64::from(i % 17) / 17.0 + 0.01;
            let t = f64::from(i / 17) / 19.0 * (1.0 - s);
            let x = [3.0 * s + t, t * h + 1e-9 * f64::from(i % 3)];
            let lam = domain.barycentric(&[q(x[0]), q(x[1])]).unwrap();
            let p = exact.evaluate(&lam, Algorithm::Casteljau);
            let y = [round_f64(&p[0]), round_f64(&p[1])];
            points.extend(x);
            good.extend(y);
            bad.extend([y[0] + y[0].abs() * 2f64.powi(-30) + 1e-300, y[1]]);
        }
        let check = |tol: &str, values: &[f64]| {
            let options = BatchOptions {
                tolerance: Tolerance::parse(tol).unwrap(),
                precision: Some(Precision::F64),
                cartesian: true,
                ..BatchOptions::default()
            };
            BatchChecker::new(patch.clone(), &options)
                .unwrap()
                .check_rows(&points, values, 0, "<memory>", "triangle")
                .unwrap()
                .0
        };
        let r = check("ulps=1/2", &good);
        assert_eq!((r.checked, r.passed), (300, 300), "h={h}");
        if h == 2.0 {
            assert!(
                r.fell_back <= 3,
                "fell back {} (0 when written)",
                r.fell_back
            );
            let counts = r.histogram.counts;
            assert_eq!(counts[0] + counts[1], 300, "h={h}: {counts:?}");
            assert!(
                r.max_ulps.is_some_and(|u| u <= 0.5),
                "h={h}: {:?}",
                r.max_ulps
            );
        }
        let r = check("ulps=64", &good);
        assert_eq!((r.checked, r.passed), (300, 300), "h={h}");
        if h == 2.0 {
            assert!(
                r.fell_back <= 3,
                "fell back {} (0 when written)",
                r.fell_back
            );
        }
        let r = check("ulps=64", &bad);
        assert_eq!((r.checked, r.failed), (300, 300), "h={h}");
        if h == 2.0 {
            assert!(r.fell_back <= 60, "fell back {}", r.fell_back);
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    /// Soundness of `--cartesian` batches row by row: on a random cubic over a random triangle
    /// (vertices and control values small dyadic floats, so the code sees them exactly), at
    /// float points inside and around it, claimed values `k` ulps from the correctly rounded
    /// exact values (`k` random per coordinate, up to ±80), every row's verdict under
    /// `ulps=1/2`, `ulps=1`, `ulps=4` and `ulps=64` is the exact path's (exact barycentric
    /// coordinates of the float point by Cramer's rule, rational de Casteljau, the error in ulps
    /// computed exactly): the filter never passes a row the exact path fails, nor fails one it
    /// passes; and each row's error figure is an upper bound on the exact error (the exact error
    /// rounded to f64 for rows that fell back to exact arithmetic).
    #[test]
    fn cartesian_rows_agree_with_the_exact_path_row_by_row(
        verts in proptest::collection::vec(-64i32..64, 6),
        values in proptest::collection::vec(-512i32..512, 20),
        pts in proptest::collection::vec((-0.1f64..1.1, -0.1f64..1.1), 24),
        steps in proptest::collection::vec(-80i32..=80, 48),
    ) {
        use tribez::Rational;
        use tribez::hazmat::domain::Domain;
        use tribez::hazmat::exact::{Algorithm, ExactEvaluator};
        use tribez::hazmat::number::{exact_f64, round_f64, ulps_error_f64};
        use tribez::hazmat::patch::{BezierPatch, ControlNet};
        use tribez::hazmat::simplex::Simplex;
        let q = |x: f64| exact_f64(x).unwrap();
        let v: Vec<[f64; 2]> = (0..3).map(|k| [f64::from(verts[2 * k]) / 8.0, f64::from(verts[2 * k + 1]) / 8.0]).collect();
        let Ok(domain) = Domain::new(v.iter().map(|p| vec![q(p[0]), q(p[1])]).collect()) else {
            return Ok(());
        };
        let simplex = Simplex::new(2, 3);
        let coords: Vec<Rational> = (0..simplex.len() * 2).map(|i| q(f64::from(values[i]) / 16.0)).collect();
        let net = ControlNet::new(simplex, 2, coords);
        let exact = ExactEvaluator::new(&net);
        let mut patch = BezierPatch::new(net);
        patch.domain = Some(domain.clone());
        let (mut points, mut claimed, mut truth) = (Vec::new(), Vec::new(), Vec::new());
        for (i, (s, t)) in pts.iter().enumerate() {
            // the float point (1 − s − t)·v0 + s·v1 + t·v2, rounded as floats compute it
            let x: Vec<f64> = (0..2).map(|j| (1.0 - s - t) * v[0][j] + s * v[1][j] + t * v[2][j]).collect();
            let lam = domain.barycentric(&[q(x[0]), q(x[1])]).unwrap();
            let p = exact.evaluate(&lam, Algorithm::Casteljau);
            let mut worst = Rational::from_integer(0.into());
            for c in 0..2 {
                let mut y = round_f64(&p[c]);
                let k = steps[2 * i + c];
                for _ in 0..k.abs() {
                    y = if k > 0 { y.next_up() } else { y.next_down() };
                }
                let e = ulps_error_f64(&q(y), &p[c]);
                if e > worst {
                    worst = e;
                }
                claimed.push(y);
            }
            points.extend(x);
            truth.push(worst);
        }
        for tol in ["ulps=1/2", "ulps=1", "ulps=4", "ulps=64"] {
            let options = BatchOptions {
                tolerance: Tolerance::parse(tol).unwrap(),
                precision: Some(Precision::F64),
                cartesian: true,
                ..BatchOptions::default()
            };
            let k: Rational = tribez::hazmat::number::parse_rational(&tol[5..]).unwrap();
            let (_, verdicts) = BatchChecker::new(patch.clone(), &options)
                .unwrap()
                .check_rows(&points, &claimed, 0, "<memory>", "triangle")
                .unwrap();
            for (v, e) in verdicts.iter().zip(&truth) {
                prop_assert_eq!(v.pass, e <= &k, "{} row {} error {} fell back {}", tol, v.row, e, v.fell_back);
                // the filter's figure bounds the error; an exact row's is the error rounded to f64
                let figure = Rational::from_float(v.ulps).unwrap();
                prop_assert!(
                    figure >= *e || (v.fell_back && v.ulps == round_f64(e)),
                    "{} row {}: figure {} below {}", tol, v.row, v.ulps, e
                );
            }
        }
    }
}

/// A number as a results file may spell it (`style` picks the spelling): each spelling denotes
/// `x` exactly, except the decimal exponent form, which rounds to it.
fn spelled(x: f64, style: u8) -> String {
    use tribez::hazmat::number::hex_f64;
    match style % 6 {
        _ if !x.is_finite() => "NaN".into(),
        0 | 1 => format!("{x:?}"),
        2 => format!(" {x:?}\t"),
        3 => format!("\"{x:?}\""),
        4 => format!("{x:e}"),
        _ => hex_f64(x),
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(12))]
    /// The CSV path judges most rows from their floats alone (parsed straight from the text,
    /// decided by the float filter, the report's failures and worst row kept per slab of rows);
    /// JSON lines and rows in memory take the full path (every number parsed in full, every row
    /// noted in order). Over thousands of rows (several slabs), many ties for the worst row,
    /// failures, NaNs, blank and comment lines, quoted, spaced and hex numbers, the reports are
    /// the same, text and JSON, byte for byte.
    #[test]
    fn the_csv_fast_path_gives_the_reports_of_the_full_path(
        spec in prop::collection::vec(row_spec(), 1..3),
        repeat in 1usize..4000,
        styles in prop::collection::vec(any::<u8>(), 1..64),
        extra in prop::collection::vec((0usize..9000, any::<bool>()), 0..4),
        tolerance in prop::sample::select(vec!["ulps=1", "ulps=1/2", "cond=9", "exact", "correctly_rounded"]),
        f32 in proptest::bool::weighted(0.2),
        header in any::<bool>(),
    ) {
        // the spec's rows over and over, then a few rows of their own
        let mut all: Vec<_> = spec.iter().cycle().take(spec.len() * repeat).cloned().collect();
        all.extend((0..50).map(|i| (f64::from(i) / 50.0, 0.5, [Some((i % 7) as i8 - 3), Some(0), None])));
        let (points, values) = rows(&all);
        let options = BatchOptions {
            tolerance: Tolerance::parse(tolerance).unwrap(),
            precision: Some(if f32 { Precision::F32 } else { Precision::F64 }),
            ..BatchOptions::default()
        };
        let c = BatchChecker::new(finn(), &options).unwrap();
        let (mut csv, mut jsonl) = (String::new(), String::new());
        if header {
            csv.push_str("u,v,w,x,y,z\n");
            jsonl.push('\n');
        }
        let mut lines = 0;
        for (i, (p, v)) in points.chunks(3).zip(values.chunks(3)).enumerate() {
            for &(at, comment) in &extra {
                if at == i {
                    let line = if comment { "# a comment\n" } else { "\n" };
                    csv.push_str(line);
                    jsonl.push_str(line);
                    lines += 1;
                }
            }
            let texts: Vec<String> = p.iter().chain(v).enumerate()
                .map(|(k, &x)| spelled(x, styles[(i * 6 + k) % styles.len()]))
                .collect();
            csv.push_str(&texts.join(","));
            csv.push_str(if i % 2 == 0 { "\n" } else { "\r\n" });
            let quoted: Vec<String> = texts.iter().map(|t| format!("\"{}\"", t.trim().trim_matches('"'))).collect();
            jsonl.push_str(&format!("[{}]\n", quoted.join(", ")));
        }
        let check = |text: &str, format| {
            c.check_reader(text.as_bytes(), format, "<memory>", "finn", &mut |_, _| {}).unwrap()
        };
        let fast = check(&csv, Format::Csv);
        let full = check(&jsonl, Format::JsonLines);
        prop_assert_eq!(fast.text(), full.text());
        prop_assert_eq!(fast.json(), full.json());
        if lines == 0 && !header {
            let memory = c.check_rows(&points, &values, 1, "<memory>", "finn").unwrap().0;
            same(&fast, &memory);
        }
    }
}
