//! Certifying rational patches and S-patches (`src/certify/beyond.rs`), the library's part
//! (the command line's is crates/tribez-cli/tests/certify_beyond.rs):
//!
//! * rational patches: every error of homogeneous de Casteljau + one division lies within the
//!   proven bound `(e_N + |q| e_D)/|D̂| + ε|ŷ|/(1−ε) + η` (src/certify/bound.rs), and within its
//!   a-priori form (the one claims use), on more than
//!   20,000 random cases (the octant fixture, weights of mixed magnitude, signed control points,
//!   points near the edges and outside the triangle);
//! * S-patches: the de Casteljau part `|ŷ − P(λ̂)|` lies within `γ_K Σ|P|B(|λ̂|)` on the pentagon
//!   fixtures, the float Wachspress coordinates within their relative bound `θ`, and the total
//!   error within `(γ_K + ((1+θ)^n − 1)/(1−θ)^n) Σ|P|B(|λ̂|)`, f64 and f32.

use std::path::PathBuf;

use num_rational::BigRational;
use tribez::hazmat::any_patch::AnyPatch;
use tribez::hazmat::certify::beyond::{RationalCertifier, SPatchCertifier};
use tribez::hazmat::certify::sample::{SplitMix, random_points, random_polygon_points};
use tribez::hazmat::float::Float;
use tribez::hazmat::io::patch_file::read_any_patch;
use tribez::hazmat::patch::{BezierPatch, ControlNet};
use tribez::hazmat::rational::RationalPatch;
use tribez::hazmat::simplex::Simplex;

fn fixture(name: &str) -> PathBuf {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../fixtures/beyond")
        .join(name)
}

fn octant() -> RationalPatch {
    match read_any_patch(&fixture("octant_quartic.toml")).unwrap() {
        AnyPatch::Rational(r) => r,
        _ => panic!("the octant is a rational patch"),
    }
}

/// A random rational patch: control points in [−1, 1] (dim 2), weights `10^k`, k in [−6, 6]
/// (mixed magnitude, all positive).
fn mixed(n: usize, r: &mut SplitMix) -> RationalPatch {
    let s = Simplex::new(2, n);
    let mut coords = Vec::new();
    let mut weights = Vec::new();
    for _ in s.iter() {
        for _ in 0..2 {
            coords.push(BigRational::from_float(r.unit() * 2.0 - 1.0).unwrap());
        }
        let k = (r.next_u64() % 13) as i32 - 6;
        weights.push(BigRational::from_float(10f64.powi(k) * (0.5 + r.unit())).unwrap());
    }
    RationalPatch::new(BezierPatch::new(ControlNet::new(s, 2, coords)), weights)
}

fn run_rational<F: Float + std::ops::Div<Output = F>>(
    r: &RationalPatch,
    pts: &[Vec<f64>],
    name: &str,
) -> (usize, usize) {
    let cert = RationalCertifier::<F>::new(r).unwrap();
    let (mut judged, mut outside) = (0, 0);
    for (k, p) in pts.iter().enumerate() {
        let lam: Vec<F> = p
            .iter()
            .map(|x| F::round(&BigRational::from_float(*x).unwrap()))
            .collect();
        let case = cert.check(&lam);
        // the certifier runs exactly the code of `eval --float`
        let direct = r.evaluate_float(&lam);
        assert!(
            case.y
                .iter()
                .zip(&direct)
                .all(|(a, b)| a.exact() == b.exact()),
            "{name}: certifier and evaluate_float differ at {p:?}"
        );
        if case.outside {
            outside += 1;
            continue;
        }
        let (q, b) = (case.exact.as_ref().unwrap(), case.bound.as_ref().unwrap());
        // the a-priori form used by claims (no D̂) holds too, where |D| > e_D (every 4th point)
        if let Some(a) = (k % 4 == 0)
            .then(|| a_priori_form::<F>(&cert.exact_net, &lam, q))
            .flatten()
        {
            for ((y, qc), ac) in case.y.iter().zip(q).zip(&a) {
                let err = num_traits::Signed::abs(&(y.exact().unwrap() - qc));
                assert!(&err <= ac, "{name}: a-priori form exceeded at {p:?}");
            }
        }
        for ((y, qc), bc) in case.y.iter().zip(q).zip(b) {
            let err = num_traits::Signed::abs(&(y.exact().unwrap() - qc));
            assert!(
                &err <= bc,
                "{name} {:?}: error {err} beyond the bound {bc} at {p:?}",
                F::PRECISION
            );
            judged += 1;
        }
    }
    (judged, outside)
}

/// `rational_a_priori` at the float inputs: e_N, e_D from §14.1 and D exact.
fn a_priori_form<F: Float>(
    h: &ControlNet<BigRational>,
    lam: &[F],
    q: &[BigRational],
) -> Option<Vec<BigRational>> {
    use tribez::hazmat::certify::bound;
    use tribez::hazmat::exact::{Algorithm, ExactEvaluator};
    let lam: Vec<BigRational> = lam.iter().map(|x| x.exact().unwrap()).collect();
    let (m, n) = (h.m(), h.degree());
    let e: Vec<BigRational> = bound::condition(h, &lam)
        .iter()
        .map(|s| bound::a_priori(Algorithm::Casteljau, F::PRECISION, m, n, s, &lam))
        .collect::<Option<_>>()?;
    let d = ExactEvaluator::new(h)
        .evaluate(&lam, Algorithm::Casteljau)
        .pop()?;
    let (e_den, e_num) = e.split_last()?;
    bound::rational_a_priori(F::PRECISION, e_num, e_den, q, &d)
}

#[test]
fn every_rational_error_lies_within_its_bound() {
    let mut r = SplitMix(5);
    let mut patches = vec![("octant".to_string(), octant())];
    for n in [1, 2, 3, 5] {
        patches.push((format!("mixed weights n={n}"), mixed(n, &mut r)));
    }
    use rayon::prelude::*;
    let counts: Vec<(usize, usize, usize)> = patches
        .par_iter()
        .enumerate()
        .flat_map(|(i, (name, patch))| {
            let pts = random_points(2, 2200, 100 + i as u64);
            let (j, o) = run_rational::<f64>(patch, &pts, name);
            let (j32, o32) = run_rational::<f32>(patch, &pts, name);
            vec![(j, o, pts.len()), (j32, o32, pts.len())]
        })
        .collect();
    let judged: usize = counts.iter().map(|c| c.0).sum();
    let outside: usize = counts.iter().map(|c| c.1).sum();
    let cases: usize = counts.iter().map(|c| c.2).sum();
    assert!(cases >= 20_000, "{cases} cases");
    // positive weights: the denominator is far from zero inside; outside the triangle a few
    // points may have an uncertain denominator sign
    assert!(outside * 20 < cases, "{outside} of {cases} not judged");
    assert!(
        judged >= 2 * (cases - outside),
        "{judged} coordinates judged"
    );
}

#[test]
fn a_wrong_result_exceeds_the_rational_bound() {
    // the bound is not vacuous: a result moved by 2^20 ulps is outside it
    let r = octant();
    let cert = RationalCertifier::<f64>::new(&r).unwrap();
    let lam = [1.0 / 3.0, 0.25, 1.0 - 1.0 / 3.0 - 0.25];
    let case = cert.check(&lam);
    let y = case.y[0];
    let moved = y + y * 2f64.powi(-33);
    let err = num_traits::Signed::abs(
        &(BigRational::from_float(moved).unwrap() - &case.exact.as_ref().unwrap()[0]),
    );
    assert!(err > case.bound.as_ref().unwrap()[0]);
}

/// An S-patch fixture and its polygon's vertices as f64.
fn s_patch(name: &str) -> (tribez::hazmat::spatch::SPatch, Vec<[f64; 2]>) {
    let AnyPatch::SPatch(s) = read_any_patch(&fixture(name)).unwrap() else {
        panic!("{name} is an S-patch")
    };
    let verts = s
        .polygon
        .vertices()
        .iter()
        .map(|v| {
            [
                v[0].to_string().parse().unwrap(),
                v[1].to_string().parse().unwrap(),
            ]
        })
        .collect();
    (s, verts)
}

#[test]
fn s_patch_de_casteljau_part_within_its_bound() {
    for name in ["pentagon_depth2.toml", "pentagon_plane.toml"] {
        let (s, verts) = s_patch(name);
        let cert = SPatchCertifier::<f64>::new(&s).unwrap();
        let cert32 = SPatchCertifier::<f32>::new(&s).unwrap();
        let mut measured = 0;
        for p in random_polygon_points(&verts, 1500, 7) {
            let case = cert.check(&p);
            assert!(!case.outside);
            for ((y, q), b) in case
                .y
                .iter()
                .zip(&case.casteljau_exact)
                .zip(case.casteljau_bound.as_ref().unwrap())
            {
                assert!(&num_traits::Signed::abs(&(y.exact().unwrap() - q)) <= b);
            }
            measured += usize::from(case.exact.is_some());
            let p32 = [p[0] as f32, p[1] as f32];
            let c32 = cert32.check(&p32);
            for ((y, q), b) in c32
                .y
                .iter()
                .zip(&c32.casteljau_exact)
                .zip(c32.casteljau_bound.as_ref().unwrap())
            {
                assert!(&num_traits::Signed::abs(&(y.exact().unwrap() - q)) <= b);
            }
            // the float path is the one of `eval --float`
            assert_eq!(case.y, s.evaluate_float(&p));
        }
        assert!(measured > 1400, "{name}: {measured}");
    }
}

#[test]
fn s_patch_total_error_within_its_proven_bound() {
    // The whole float path (float Wachspress coordinates, then de Casteljau) against the exact
    // S-patch at the rounded point: within the de Casteljau bound plus the coordinates' term
    // ((1 + θ)^n − 1)/(1 − θ)^n Σ|P|B(λ̂) (src/certify/bound.rs, wachspress_relative).
    for name in ["pentagon_depth2.toml", "pentagon_plane.toml"] {
        let (s, verts) = s_patch(name);
        let cert = SPatchCertifier::<f64>::new(&s).unwrap();
        let cert32 = SPatchCertifier::<f32>::new(&s).unwrap();
        let (mut judged, mut judged32, mut total) = (0, 0, 0);
        let mut worst = 0f64;
        for p in random_polygon_points(&verts, 600, 11) {
            total += 1;
            let case = cert.check(&p);
            if let (Some(b), Some(q)) = (&case.total_bound, &case.exact) {
                judged += 1;
                // the coordinates themselves within θ (relative)
                let theta = case.theta.as_ref().unwrap();
                for (l, e) in case.lambda.iter().zip(case.exact_lambda.as_ref().unwrap()) {
                    let err = num_traits::Signed::abs(&(l.exact().unwrap() - e));
                    assert!(
                        err <= theta * e,
                        "{name} f64 λ at {p:?}: {err} > θ {theta} × {e}"
                    );
                }
                for ((y, q), b) in case.y.iter().zip(q).zip(b) {
                    let err = num_traits::Signed::abs(&(y.exact().unwrap() - q));
                    assert!(&err <= b, "{name} f64 at {p:?}: {err} > {b}");
                    if !num_traits::Zero::is_zero(b) {
                        worst = worst.max(tribez::hazmat::number::round_f64(&(err / b)));
                    }
                }
            }
            let c32 = cert32.check(&[p[0] as f32, p[1] as f32]);
            if let (Some(b), Some(q)) = (&c32.total_bound, &c32.exact) {
                judged32 += 1;
                for ((y, q), b) in c32.y.iter().zip(q).zip(b) {
                    let err = num_traits::Signed::abs(&(y.exact().unwrap() - q));
                    assert!(&err <= b, "{name} f32 at {p:?}: {err} > {b}");
                }
            }
        }
        eprintln!(
            "{name}: judged {judged} (f64) {judged32} (f32) of {total}, worst error/bound {worst}"
        );
        // interior points are judged; only the near-edge ones (3 in 20 of the sample, 1e-9 from
        // an edge) may fall outside the hypotheses
        assert!(
            judged * 20 >= total * 19,
            "{name}: {judged} of {total} judged (f64)"
        );
        assert!(
            judged32 * 20 >= total * 16,
            "{name}: {judged32} of {total} judged (f32)"
        );
        // the bound is not vacuous: some errors come within a factor 100 of it (about 20 measured)
        assert!(worst > 1e-2, "{name}: largest error/bound {worst}");
    }
}
