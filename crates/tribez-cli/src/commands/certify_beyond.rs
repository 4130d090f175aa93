//! `tribez certify` on rational patches and S-patches ([`tribez::certify::beyond`]).
//!
//! * Rational patch: homogeneous de Casteljau in f64/f32 on the rounded homogeneous net, one
//!   division; judged against the proven bound [`tribez::certify::bound::rational_a_posteriori`].
//! * S-patch: float Wachspress coordinates `λ̂`, then float de Casteljau. The total error
//!   (against the exact S-patch with rounded polygon and control points, at the rounded point) is
//!   judged against the proven bound of [`tribez::certify::beyond::SPatchCase::total_bound`]:
//!   de Casteljau at `λ̂` plus the coordinates' relative error `θ`.

use std::ops::Div;

use num_rational::BigRational;
use num_traits::{Signed, Zero};
use rayon::prelude::*;

use super::CliError;
use super::certify::{Acc, Args, RandomInfo, Row, points_of, reproduce};
use tribez::certify::beyond::{RationalCertifier, SPatchCertifier};
use tribez::certify::bound::roundings;
use tribez::certify::measures::sci;
use tribez::certify::sample::random_polygon_points;
use tribez::exact::Algorithm;
use tribez::float::{Float, Precision};
use tribez::rational::RationalPatch;
use tribez::spatch::SPatch;

/// The explanation line of a rational patch's table.
pub const RATIONAL_NOTE: &str = "bound (rational, homogeneous de Casteljau + one division): |fl(N̂/D̂) − q| ≤ (e_N + |q| e_D)/|D̂| + ε|fl(N̂/D̂)|/(1−ε) + η, e_N = γ_K Σ|w_i c_i| B_i(|λ|), e_D = γ_K Σ|w_i| B_i(|λ|), needs |D̂| > e_D; cond = (Σ|w c|B(|λ|) + |q| Σ|w|B(|λ|))/|D|, relcond = cond/|q|";

/// The explanation line of an S-patch's table.
pub const SPATCH_NOTE: &str = "S-patch: the TOTAL error against the exact S-patch (rounded polygon and control points) at the rounded point, judged against the proven bound |ŷ − S(p̂)| ≤ (γ_K + ((1+θ)^n − 1)/(1−θ)^n) Σ|P_α| B_α(|λ̂|): de Casteljau at the float coordinates λ̂ plus their relative error θ (float Wachspress, bound.rs wachspress_relative); cond = Σ|P_α| B_α(|λ̂|), relcond = cond/|S|";

fn algorithm_check(args: &Args, kind: &str) -> Result<(), CliError> {
    match args.algorithm.as_str() {
        "all" | "casteljau" => Ok(()),
        other => Err(CliError::Usage(format!(
            "--algorithm {other}: {kind} are certified with de Casteljau only (--algorithm casteljau or all)"
        ))),
    }
}

fn f(x: &BigRational) -> f64 {
    tribez::number::round_f64(x)
}

/// Judge `|y − exact| ≤ bound` per coordinate into `acc`.
fn judge<F: Float>(
    acc: &mut Acc,
    y: &[F],
    exact: &[BigRational],
    bound: &[BigRational],
    at: &[BigRational],
    what: &str,
) {
    for (c, ((v, q), b)) in y.iter().zip(exact).zip(bound).enumerate() {
        let err = (v.exact().unwrap_or_default() - q).abs();
        if !b.is_zero() {
            acc.ratio = acc.ratio.max(f(&(&err / b)));
        }
        if err > *b {
            acc.violation = Some(format!(
                "at {} coordinate {c}: {what}error {} exceeds the bound {}",
                crate::report::tuple(at),
                sci(&err),
                sci(b)
            ));
        }
    }
}

fn rational_row<F: Float + Div<Output = F>>(
    r: &RationalPatch,
    points: &[Vec<BigRational>],
) -> Result<Row, CliError> {
    let cert = RationalCertifier::<F>::new(r)
        .map_err(|e| CliError::Usage(format!("{}: {e}", F::PRECISION.name())))?;
    let (m, n) = (r.patch.net.m(), r.patch.net.degree());
    let k = roundings(Algorithm::Casteljau, m, n);
    let accs: Vec<Acc> = points
        .par_iter()
        .map(|point| {
            let lam: Vec<F> = point.iter().map(F::round).collect();
            let lam_q: Vec<BigRational> =
                lam.iter().map(|x| x.exact().unwrap_or_default()).collect();
            let case = cert.check(&lam);
            let mut acc = Acc {
                coords: case.y.len(),
                outside: case.outside,
                ..Acc::default()
            };
            if let Some(q) = &case.exact {
                acc.measure(&case.y, q);
                for (qc, kc) in q.iter().zip(case.condition.iter().flatten()) {
                    acc.cond = acc.cond.max(f(kc));
                    if !qc.is_zero() {
                        acc.rel_cond = acc.rel_cond.max(f(&(kc / qc.abs())));
                    }
                }
            }
            if let (Some(q), Some(b)) = (&case.exact, &case.bound) {
                judge(&mut acc, &case.y, q, b, &lam_q, "");
            } else if !case.outside {
                acc.violation = Some(format!(
                    "at {}: the exact denominator vanishes although |D̂| > e_D",
                    crate::report::tuple(&lam_q)
                ));
            }
            acc
        })
        .collect();
    let mut row = Row::new(
        Algorithm::Casteljau,
        F::PRECISION,
        k,
        Some(format!("γ_{k},÷")),
    );
    row.fold(accs, points);
    if row.outside_hypothesis > 0 {
        row.notes.push(format!(
            "{} points not judged: overflow, or |D̂| ≤ e_D (the denominator's sign is not certain, e.g. where it vanishes outside the simplex)",
            row.outside_hypothesis
        ));
    }
    Ok(row)
}

/// Certify a rational patch: rows per precision (de Casteljau only).
pub fn rational(
    args: &Args,
    r: &RationalPatch,
    precisions: &[Precision],
) -> Result<(Vec<Row>, usize, RandomInfo), CliError> {
    algorithm_check(args, "rational patches")?;
    let (points, random) = points_of(args, r.patch.net.m())?;
    let rows = precisions
        .iter()
        .map(|p| match p {
            Precision::F64 => rational_row::<f64>(r, &points),
            Precision::F32 => rational_row::<f32>(r, &points),
        })
        .collect::<Result<_, _>>()?;
    Ok((rows, points.len(), random))
}

fn spatch_row<F: Float + Div<Output = F>>(
    s: &SPatch,
    points: &[Vec<BigRational>],
) -> Result<Row, CliError> {
    let cert = SPatchCertifier::<F>::new(s)
        .map_err(|e| CliError::Usage(format!("{}: {e}", F::PRECISION.name())))?;
    let (m, n) = (s.net.m(), s.net.degree());
    let k = roundings(Algorithm::Casteljau, m, n);
    let accs: Vec<Acc> = points
        .par_iter()
        .map(|point| {
            let p = [F::round(&point[0]), F::round(&point[1])];
            let at: Vec<BigRational> = p.iter().map(|x| x.exact().unwrap_or_default()).collect();
            let case = cert.check(&p);
            let mut acc = Acc {
                coords: case.y.len(),
                outside: case.outside,
                ..Acc::default()
            };
            if case.outside {
                return acc;
            }
            match (&case.exact, &case.exact_lambda) {
                (Some(v), Some(l)) => {
                    acc.measure(&case.y, v);
                    let mut lacc = Acc::default();
                    lacc.measure(&case.lambda, l);
                    acc.lambda_ulps = lacc.ulps;
                    for (vc, kc) in v.iter().zip(&case.condition) {
                        acc.cond = acc.cond.max(f(kc));
                        if !vc.is_zero() {
                            acc.rel_cond = acc.rel_cond.max(f(&(kc / vc.abs())));
                        }
                    }
                    match &case.total_bound {
                        Some(b) => {
                            judge(&mut acc, &case.y, v, b, &at, "");
                            // the coordinates themselves, against θ (relative)
                            let theta = case.theta.as_ref().expect("a total bound has θ");
                            let bounds: Vec<BigRational> = l.iter().map(|e| theta * e).collect();
                            judge(
                                &mut acc,
                                &case.lambda,
                                l,
                                &bounds,
                                &at,
                                "Wachspress coordinate ",
                            );
                        }
                        // near an edge or underflow: outside the coordinates' bound
                        None => acc.outside = true,
                    }
                }
                // the rounded point is outside the rounded polygon: not measured
                _ => acc.outside = true,
            }
            acc
        })
        .collect();
    let mut row = Row::new(
        Algorithm::Casteljau,
        F::PRECISION,
        k,
        Some(format!("γ_{k}+θ")),
    );
    let lambda_ulps = row.fold(accs, points);
    row.notes.push(format!(
        "Wachspress coordinates λ̂: max error {} ulp (within the relative bound θ wherever judged)",
        super::certify::g(lambda_ulps)
    ));
    if row.outside_hypothesis > 0 {
        row.notes.push(format!(
            "{} points not judged: overflow, the rounded point outside the rounded polygon, or so near an edge (or so small) that the coordinates' bound does not apply",
            row.outside_hypothesis
        ));
    }
    Ok(row)
}

/// Certify an S-patch: rows per precision (de Casteljau only). Points are Cartesian
/// (`--points FILE` with two coordinates per point, or `--random N` inside the polygon).
pub fn spatch(
    args: &Args,
    s: &SPatch,
    precisions: &[Precision],
) -> Result<(Vec<Row>, usize, RandomInfo), CliError> {
    algorithm_check(args, "S-patches")?;
    let (points, random) = match (&args.points, args.random) {
        (Some(path), None) => (tribez::io::points::read_points(path, 2)?, None),
        (None, Some(count)) if count > 0 => {
            let verts: Vec<[f64; 2]> = s
                .polygon
                .vertices()
                .iter()
                .map(|v| [f(&v[0]), f(&v[1])])
                .collect();
            let pts = random_polygon_points(&verts, count, args.seed)
                .into_iter()
                .map(|p| {
                    p.iter()
                        .map(|x| BigRational::from_float(*x).unwrap_or_default())
                        .collect()
                })
                .collect();
            (pts, Some((count, args.seed, reproduce(args, count))))
        }
        _ => points_of(args, 1)?, // the usage errors of the barycentric path
    };
    let points = if let Some(path) = &args.points {
        for (i, p) in points.iter().enumerate() {
            if let Err(e) = s.polygon.wachspress(p) {
                return Err(CliError::Usage(format!(
                    "{}: point {}: {e}",
                    path.display(),
                    i + 1
                )));
            }
        }
        points
    } else {
        // a random point rounded onto the wrong side of an edge is dropped
        points
            .into_iter()
            .filter(|p| s.polygon.wachspress(p).is_ok())
            .collect()
    };
    let rows = precisions
        .iter()
        .map(|p| match p {
            Precision::F64 => spatch_row::<f64>(s, &points),
            Precision::F32 => spatch_row::<f32>(s, &points),
        })
        .collect::<Result<_, _>>()?;
    Ok((rows, points.len(), random))
}
