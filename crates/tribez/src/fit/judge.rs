//! Judging a fit computed in floating point by other code against the exact least-squares
//! solution (docs/theory.md §18.5).
//!
//! The measure: with `x*` the exact (minimum-norm) least-squares ordinates, `r* = A x* − b` and
//! `x̂` the float fit's ordinates (the numbers of its mesh file, read exactly), the error is
//! `x̂ − x*`. What the conditioning allows is the first-order perturbation bound of least
//! squares (Wedin; Higham, "Accuracy and Stability of Numerical Algorithms", 2nd ed.,
//! Theorem 20.1) for relative perturbations of size `ε` (the unit roundoff of the precision)
//! in `A` and `b`:
//!
//! `‖Δx‖₂ ≤ κε/(1 − κε) · (2 ‖x*‖₂ + (κ + 1) ‖r*‖₂ / ‖A‖₂)`,  `κ = κ₂(A) = σ_max/σ_min`,
//!
//! the theorem's relative bound `‖Δx‖₂/‖x*‖₂ ≤ κε/(1 − κε) · (2 + (κ + 1) ‖r*‖₂/(‖A‖₂ ‖x*‖₂))`
//! multiplied by `‖x*‖₂`. This form also holds at `x* = 0` (the data orthogonal to the range
//! of `A`), where only the residual term is left: both sides are continuous in the data `b`,
//! and `b` with `x* ≠ 0` are dense.
//!
//! `κ` is not computed (the singular values are algebraic numbers) but bounded **rigorously**
//! from above: `σ_max² = λ_max(G) ≤ ‖G‖_∞` with `G = AᵀA`; and with `X` an approximate inverse
//! of `Ĝ = G + WWᵀ` (computed in `f64`; `W` an exact basis of the kernel of `G`, empty at full
//! rank) and `E = I − XĜ` computed **exactly**, `‖E‖_∞ < 1` gives
//! `σ_min² ≥ λ_min(Ĝ) ≥ (1 − ‖E‖_∞)/‖X‖_∞` (the smallest non-zero eigenvalue of `G` is at least
//! the smallest eigenvalue of `Ĝ`, which acts as `G` on the range of `G`). `‖A‖₂` in the
//! residual term is bounded from below by `max_i √G_ii`.
//!
//! The allowed error is evaluated **exactly** over the rationals, except for the square roots
//! (`κ̄ = √(bound of κ²)`, `‖x*‖₂ = √(x*ᵀx*)`, `‖r*‖₂ = √RSS`, `√max_i G_ii`), which are
//! replaced by dyadic bounds within a relative `2^-64` **in the direction that makes the
//! allowed error larger** (up for the first three, down for `‖A‖₂`). So the allowed error is a
//! rational upper bound of the theorem's bound, at any scale (no floating-point underflow or
//! overflow), and `cond=K` compares `‖x̂ − x*‖₂² ≤ (K · allowed)²` exactly. If `‖E‖_∞ ≥ 1`
//! (the matrix is too ill-conditioned for the `f64` inverse) or `κ̄ε ≥ 1`, no bound is given
//! and the `cond` tolerances accept any error. Rank-deficient problems use
//! `κ = σ_max/σ_min⁺` and the minimum-norm `x*` (which `numpy.linalg.lstsq` also returns),
//! valid for perturbations that keep the rank.

use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};
use serde::Serialize;

use super::{DataPoint, Design, ExactNumber, FitError, prepare};
use crate::certify::measures::Tolerance;
use crate::float::Precision;
use crate::linalg::lsq::{Regularize, solve_least_squares};
use crate::mesh::Mesh;
use crate::number::{exact_f64, ratio, round_f64};

/// How to judge a float fit.
#[derive(Debug, Clone, PartialEq)]
pub struct FloatFitOptions {
    /// The tolerance: `cond=K` (`‖x̂ − x*‖₂ ≤ K ×` the allowed error), `cond` (`K = 1`),
    /// `abs=E` (every `|x̂_k − x*_k| ≤ E`), `rel=E` (`‖x̂ − x*‖₂ ≤ E ‖x*‖₂`) or `exact`.
    pub tolerance: Tolerance,
    /// The precision the fit was computed in (its unit roundoff is `ε`).
    pub precision: Precision,
}

impl Default for FloatFitOptions {
    fn default() -> Self {
        FloatFitOptions {
            tolerance: Tolerance::CondDegree,
            precision: Precision::F64,
        }
    }
}

/// One ordinate of a judged float fit.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct OrdinateError {
    /// Where it sits.
    pub id: String,
    /// The float fit's value (as written in its file, exactly).
    pub claimed: ExactNumber,
    /// The exact least-squares value.
    pub exact: ExactNumber,
    /// `claimed − exact`.
    pub error: ExactNumber,
    /// `|error|` divided by the allowed error (`null` without a bound).
    pub ratio: Option<f64>,
}

/// The judgement of a float fit (`tribez check --mesh FITTED --fit DATA`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FloatFitReport {
    /// The fitted mesh file judged.
    pub mesh: String,
    /// The data file.
    pub data: String,
    /// Data rows.
    pub rows: usize,
    /// Ordinates.
    pub ordinates: usize,
    /// Rank of the normal matrix.
    pub rank: usize,
    /// The ordinates the data do not determine (then `x*` is the minimum-norm solution).
    pub undetermined: Vec<String>,
    /// `"f64"` or `"f32"`.
    pub precision: String,
    /// The unit roundoff `ε` (`2^-53` or `2^-24`).
    pub unit_roundoff: f64,
    /// The tolerance, as written.
    pub tolerance: String,
    /// Whether the fit passes the tolerance.
    pub passed: bool,
    /// A rigorous upper bound of `κ₂(A)` (`null` if none could be certified).
    pub condition_bound: Option<f64>,
    /// The error the conditioning allows, `‖Δx‖₂`, rounded to the nearest `f64` (`null`
    /// without a bound; `0` or `null` if it is beyond the range of `f64`: see
    /// `allowed_error_exact`).
    pub allowed_error: Option<f64>,
    /// The allowed error as computed (a rational: the verdict compares with it exactly).
    pub allowed_error_exact: Option<ExactNumber>,
    /// `‖x̂ − x*‖₂`.
    pub error_norm: f64,
    /// `‖x̂ − x*‖₂ / allowed_error`.
    pub error_ratio: Option<f64>,
    /// `‖x̂ − x*‖₂ / ‖x*‖₂` (`null` when `x* = 0`).
    pub relative_error: Option<f64>,
    /// `max_k |x̂_k − x*_k|`, exact.
    pub max_abs_error: ExactNumber,
    /// The residual sum of squares of the exact fit (the minimum).
    pub rss_exact: ExactNumber,
    /// The residual sum of squares of the float fit.
    pub rss_claimed: ExactNumber,
    /// `rss_claimed − rss_exact ≥ 0`.
    pub rss_excess: ExactNumber,
    /// `rss_excess / rss_exact` (`null` when the exact fit has no residual).
    pub rss_excess_relative: Option<f64>,
    /// Every ordinate.
    pub per_ordinate: Vec<OrdinateError>,
}

/// Judge the float fit `claimed` (the mesh file `mesh_file`, every ordinate given) of `data`
/// (from `data_file`) against the exact least-squares fit on the same mesh (module docs).
///
/// # Errors
/// As [`super::fit`] (outside points, an invalid mesh); [`FitError::MissingOrdinate`]; a
/// tolerance that does not apply to fits ([`FitError::Tolerance`]).
pub fn judge_float_fit(
    claimed: &Mesh,
    data: &[DataPoint],
    mesh_file: &str,
    data_file: &str,
    options: &FloatFitOptions,
) -> Result<FloatFitReport, FitError> {
    let mesh = prepare(claimed, None)?;
    let x_hat: Vec<BigRational> = mesh
        .ordinates()
        .iter()
        .enumerate()
        .map(|(g, q)| {
            q.clone().ok_or_else(|| FitError::MissingOrdinate {
                file: mesh_file.to_string(),
                id: mesh.ordinate_id(g),
            })
        })
        .collect::<Result<_, _>>()?;
    let k_factor = match &options.tolerance {
        Tolerance::Cond(k) => Some(k.clone()),
        Tolerance::CondDegree => Some(BigRational::one()),
        Tolerance::Exact | Tolerance::Abs(_) | Tolerance::Rel(_) => None,
        t => {
            return Err(FitError::Tolerance {
                tolerance: t.to_string(),
            });
        }
    };
    let design = Design::new(&mesh, data, data_file)?;
    let ne = design.normal();
    let sol = solve_least_squares(ne, &[], Regularize::MinimumNorm).map_err(FitError::Solver)?;
    let n = x_hat.len();
    let err: Vec<BigRational> = x_hat.iter().zip(&sol.x).map(|(a, b)| a - b).collect();
    let err_sq: BigRational = err.iter().map(|e| e * e).sum();
    let x_sq: BigRational = sol.x.iter().map(|e| e * e).sum();
    let rss_claimed = ne.residual_sum_of_squares(&x_hat);
    let excess = &rss_claimed - &sol.rss;
    let (eps, eps_f64) = match options.precision {
        Precision::F64 => (
            ratio(BigInt::one(), BigInt::one() << 53u32),
            f64::EPSILON / 2.0,
        ),
        Precision::F32 => (
            ratio(BigInt::one(), BigInt::one() << 24u32),
            f64::from(f32::EPSILON) / 2.0,
        ),
    };
    // κ̄ ≥ κ (certified), then the allowed error, every step exact or rounded upwards.
    let kappa = condition_bound(&ne.gram_rows(), &sol.kernel, n).map(|k2| sqrt_bound(&k2, true));
    let max_diag = (0..n)
        .map(|i| ne.gram(i, i))
        .max()
        .unwrap_or_else(BigRational::zero);
    let allowed = kappa.as_ref().and_then(|k| {
        allowed_error(
            k,
            &eps,
            &sqrt_bound(&x_sq, true),
            &sqrt_bound(&sol.rss, true),
            &sqrt_bound(&max_diag, false),
        )
    });
    // Ratios are taken of the exact figures (squared where a norm is involved), then rounded:
    // nothing underflows or overflows on the way.
    let ratio_of = |e_sq: &BigRational| -> Option<f64> {
        allowed.as_ref().map(|a| {
            if e_sq.is_zero() {
                0.0
            } else if a.is_zero() {
                f64::INFINITY
            } else {
                round_f64(&(e_sq / (a * a))).sqrt()
            }
        })
    };
    let max_abs = err
        .iter()
        .map(|e| e.abs())
        .max()
        .unwrap_or_else(BigRational::zero);
    let passed = match &options.tolerance {
        Tolerance::Exact => err.iter().all(Zero::is_zero),
        Tolerance::Abs(e) => max_abs <= *e,
        Tolerance::Rel(e) => err_sq <= e * e * &x_sq,
        _ => match (&allowed, &k_factor) {
            // ‖x̂ − x*‖₂ ≤ K·allowed ⟺ ‖x̂ − x*‖₂² ≤ (K·allowed)², both sides exact.
            (Some(a), Some(k)) => {
                let ka = k * a;
                err_sq <= &ka * &ka
            }
            _ => true,
        },
    };
    let per_ordinate = (0..n)
        .map(|g| OrdinateError {
            id: mesh.ordinate_id(g).to_string(),
            claimed: ExactNumber::of(&x_hat[g]),
            exact: ExactNumber::of(&sol.x[g]),
            error: ExactNumber::of(&err[g]),
            ratio: ratio_of(&(&err[g] * &err[g])),
        })
        .collect();
    Ok(FloatFitReport {
        mesh: mesh_file.to_string(),
        data: data_file.to_string(),
        rows: data.len(),
        ordinates: n,
        rank: sol.rank,
        undetermined: sol
            .undetermined
            .iter()
            .map(|&g| mesh.ordinate_id(g).to_string())
            .collect(),
        precision: options.precision.to_string(),
        unit_roundoff: eps_f64,
        tolerance: options.tolerance.to_string(),
        passed,
        condition_bound: kappa.as_ref().map(round_f64),
        allowed_error: allowed.as_ref().map(round_f64),
        allowed_error_exact: allowed.as_ref().map(ExactNumber::of),
        error_norm: round_f64(&sqrt_bound(&err_sq, true)),
        error_ratio: ratio_of(&err_sq),
        relative_error: (!x_sq.is_zero()).then(|| round_f64(&(&err_sq / &x_sq)).sqrt()),
        max_abs_error: ExactNumber::of(&max_abs),
        rss_exact: ExactNumber::of(&sol.rss),
        rss_claimed: ExactNumber::of(&rss_claimed),
        rss_excess_relative: (!sol.rss.is_zero()).then(|| round_f64(&(&excess / &sol.rss))),
        rss_excess: ExactNumber::of(&excess),
        per_ordinate,
    })
}

/// A rigorous upper bound of `κ₂(A)² = λ_max(G)/λ_min⁺(G)` (module docs), exact, or `None`.
fn condition_bound(
    gram: &[Vec<(usize, BigRational)>],
    kernel: &[Vec<BigRational>],
    n: usize,
) -> Option<BigRational> {
    if n == 0 {
        return None;
    }
    // Ĝ = G + W Wᵀ, dense, exact.
    let mut g: Vec<Vec<BigRational>> = vec![vec![BigRational::zero(); n]; n];
    for (i, row) in gram.iter().enumerate() {
        for (j, v) in row {
            g[i][*j] = v.clone();
        }
    }
    let lambda_max_bound = g
        .iter()
        .map(|row| row.iter().map(|v| v.abs()).sum::<BigRational>())
        .max()?;
    for w in kernel {
        for i in 0..n {
            if w[i].is_zero() {
                continue;
            }
            for j in 0..n {
                if !w[j].is_zero() {
                    g[i][j] = &g[i][j] + &w[i] * &w[j];
                }
            }
        }
    }
    // X ≈ Ĝ⁻¹ in f64.
    let gf: Vec<Vec<f64>> = g
        .iter()
        .map(|r| r.iter().map(round_f64).collect())
        .collect();
    let x = invert_f64(gf)?;
    // E = I − XĜ exactly, over integers: Ĝ = Gi / L, X = Xi · 2^-s.
    let l = g
        .iter()
        .flatten()
        .fold(BigInt::one(), |acc, q| acc.lcm(q.denom()));
    let gi: Vec<Vec<(usize, BigInt)>> = g
        .iter()
        .map(|r| {
            r.iter()
                .enumerate()
                .filter(|(_, v)| !v.is_zero())
                .map(|(j, v)| (j, v.numer() * (&l / v.denom())))
                .collect()
        })
        .collect();
    let xq: Vec<Vec<BigRational>> = x
        .iter()
        .map(|r| r.iter().map(|&v| exact_f64(v)).collect::<Option<Vec<_>>>())
        .collect::<Option<_>>()?;
    let s = xq
        .iter()
        .flatten()
        .fold(BigInt::one(), |acc, q| acc.lcm(q.denom()));
    let xi: Vec<Vec<BigInt>> = xq
        .iter()
        .map(|r| r.iter().map(|q| q.numer() * (&s / q.denom())).collect())
        .collect();
    let scale = &l * &s; // E = (scale·I − Xi·Gi) / scale
    let mut e_norm = BigRational::zero();
    let mut x_norm = BigRational::zero();
    for i in 0..n {
        let mut row = vec![BigInt::zero(); n];
        row[i] = scale.clone();
        for (k, xik) in xi[i].iter().enumerate() {
            if xik.is_zero() {
                continue;
            }
            for (j, gkj) in &gi[k] {
                row[*j] -= xik * gkj;
            }
        }
        let sum: BigInt = row.iter().map(|v| v.abs()).sum();
        let r = ratio(sum, scale.clone());
        if r > e_norm {
            e_norm = r;
        }
        let xr: BigRational = xq[i].iter().map(|v| v.abs()).sum();
        if xr > x_norm {
            x_norm = xr;
        }
    }
    if e_norm >= BigRational::one() || x_norm.is_zero() {
        return None;
    }
    // κ² ≤ ‖G‖_∞ · ‖X‖_∞ / (1 − ‖E‖_∞), exact.
    Some(lambda_max_bound * x_norm / (BigRational::one() - e_norm))
}

/// The allowed error `κ̄ε/(1 − κ̄ε) · (2 x̄ + (κ̄ + 1) r̄/ā)` (module docs), exactly, from
/// `κ̄ ≥ κ₂(A)`, `x̄ ≥ ‖x*‖₂`, `r̄ ≥ ‖r*‖₂` and `0 ≤ ā ≤ ‖A‖₂`; `None` when `κ̄ε ≥ 1`. The
/// residual term is left out when `ā = 0` (then `A = 0`: no perturbation `‖ΔA‖₂ ≤ ε‖A‖₂`
/// moves anything, and `κ̄ = 0`).
fn allowed_error(
    kappa: &BigRational,
    eps: &BigRational,
    x_up: &BigRational,
    r_up: &BigRational,
    a_low: &BigRational,
) -> Option<BigRational> {
    let ke = kappa * eps;
    let one = BigRational::one();
    if ke >= one {
        return None;
    }
    let two_x = x_up + x_up;
    let inner = if a_low.is_zero() {
        two_x
    } else {
        two_x + (kappa + &one) * r_up / a_low
    };
    Some(&ke / (&one - &ke) * inner)
}

/// Significant bits of the square roots in [`sqrt_bound`].
const SQRT_BITS: u64 = 64;

/// A dyadic bound of `√q` (`q ≥ 0`; `0` for `q ≤ 0`) within a relative `2^-64`: from above if
/// `up`, else from below. With `s` chosen so that `y = q·4^s ≥ 2^128`, `t = ⌊√⌊y⌋⌋ = ⌊√y⌋`,
/// so `t/2^s ≤ √q < (t + 1)/2^s`. The scale follows `q`: nothing underflows or overflows.
pub(crate) fn sqrt_bound(q: &BigRational, up: bool) -> BigRational {
    if !q.is_positive() {
        return BigRational::zero();
    }
    let (n, d) = (q.numer(), q.denom());
    // q ≥ 2^(bits(n) − 1 − bits(d)); make the exponent of y at least 2·SQRT_BITS.
    let e = n.bits() as i64 - 1 - d.bits() as i64;
    let s = (2 * SQRT_BITS as i64 - e + 1).div_euclid(2); // ⌈(128 − e)/2⌉
    let y = if s >= 0 {
        (n << (2 * s) as u64) / d
    } else {
        n / (d << (-2 * s) as u64)
    };
    let t = y.sqrt();
    let t = if up { t + 1u32 } else { t };
    if s >= 0 {
        ratio(t, BigInt::one() << s as u64)
    } else {
        BigRational::from_integer(t << (-s) as u64)
    }
}

/// The inverse of a square matrix in `f64` (Gauss–Jordan with partial pivoting), or `None` if
/// a pivot vanishes.
fn invert_f64(mut a: Vec<Vec<f64>>) -> Option<Vec<Vec<f64>>> {
    let n = a.len();
    let mut inv: Vec<Vec<f64>> = (0..n)
        .map(|i| (0..n).map(|j| if i == j { 1.0 } else { 0.0 }).collect())
        .collect();
    for c in 0..n {
        let p = (c..n).max_by(|&i, &j| a[i][c].abs().total_cmp(&a[j][c].abs()))?;
        if a[p][c] == 0.0 || !a[p][c].is_finite() {
            return None;
        }
        a.swap(c, p);
        inv.swap(c, p);
        let d = a[c][c];
        for j in 0..n {
            a[c][j] /= d;
            inv[c][j] /= d;
        }
        let (ac, ic) = (a[c].clone(), inv[c].clone());
        for i in 0..n {
            if i == c || a[i][c] == 0.0 {
                continue;
            }
            let f = a[i][c];
            for j in 0..n {
                a[i][j] -= f * ac[j];
                inv[i][j] -= f * ic[j];
            }
        }
    }
    inv.iter().flatten().all(|v| v.is_finite()).then_some(inv)
}

impl FloatFitReport {
    /// The text of `tribez check --mesh FITTED --fit DATA`.
    pub fn text(&self) -> String {
        use std::fmt::Write;
        let fmt = |x: Option<f64>| x.map_or_else(|| "none".to_string(), |v| format!("{v:.3e}"));
        let mut s = String::new();
        let _ = writeln!(
            s,
            "float fit {} of {} ({} rows, {} ordinates, rank {}), {}, tolerance {}: {}",
            self.mesh,
            self.data,
            self.rows,
            self.ordinates,
            self.rank,
            self.precision,
            self.tolerance,
            if self.passed { "PASS" } else { "FAIL" }
        );
        if !self.undetermined.is_empty() {
            let _ = writeln!(
                s,
                "  {} ordinates not determined by the data: compared with the minimum-norm fit",
                self.undetermined.len()
            );
        }
        let _ = writeln!(
            s,
            "  condition number κ₂(A) ≤ {}; the conditioning allows ‖Δx‖₂ ≤ {} (ε = {:e})",
            fmt(self.condition_bound),
            match (self.allowed_error, &self.allowed_error_exact) {
                // beyond the normal range of f64: the exact figure's decimal
                (Some(v), Some(q)) if !(v.is_normal() || q.exact == "0") => q.decimal.clone(),
                (v, _) => fmt(v),
            },
            self.unit_roundoff
        );
        let _ = writeln!(
            s,
            "  error ‖x̂ − x*‖₂ = {:.3e} = {} × allowed; relative {}; largest |x̂_k − x*_k| = {}",
            self.error_norm,
            fmt(self.error_ratio),
            fmt(self.relative_error),
            self.max_abs_error.decimal
        );
        let _ = writeln!(
            s,
            "  residual sum of squares: float fit {}, exact minimum {}, excess {} (relative {})",
            self.rss_claimed.decimal,
            self.rss_exact.decimal,
            self.rss_excess.decimal,
            fmt(self.rss_excess_relative)
        );
        let _ = writeln!(s, "  per ordinate (error, and error / allowed):");
        for o in &self.per_ordinate {
            let _ = writeln!(
                s,
                "    {}: claimed {}, exact {}, error {} ({})",
                o.id,
                o.claimed.decimal,
                o.exact.decimal,
                o.error.decimal,
                fmt(o.ratio)
            );
        }
        s
    }
}
