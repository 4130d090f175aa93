//! Cartesian inputs for the float filter (docs/theory.md §14.5).
//!
//! A Cartesian point `x ∈ R^m` of the domain simplex has the barycentric coordinates
//! `λ = M (x, 1)`: the map is affine, `λ_k = Σ_j M_kj x_j + M_k0'` with the exact rational
//! matrix of the domain ([`Domain::barycentric`] of the origin, [`Domain::direction`] of the unit
//! vectors). [`CartesianMap`] stores `M̂ = RN(M)` and computes `λ̂_k = fl(Σ_j M̂_kj x_j + M̂_k0')`
//! with a radius `d_k ≥ |λ_k − λ̂_k|`:
//!
//! `d_k = 2(m+2) ε T̂_k + 2(m + 3 + Σ_j |x_j|) η`, `T̂_k = fl(Σ_j |M̂_kj x_j| + |M̂_k0'|)`,
//!
//! (ε = 2^-53, η = 2^-1074). Why: rounding `M` to nearest moves each entry by at most
//! `ε/(1−ε)` of `|M̂_kj|` (or `η` if subnormal), which changes the sum by at most
//! `ε/(1−ε) T_k + η (Σ|x_j| + 1)`; the float dot product of `m + 1` terms errs by at most
//! `γ_{m+1} T_k + (m+1) η` (\[Higham02\] §3.1, plus an `η` per underflowing product). So
//! `|λ_k − λ̂_k| ≤ (γ_{m+1} + ε/(1−ε)) T_k + (m + 2 + Σ|x_j|) η ≤ (m+2) ε (1 + (m+2)ε) T_k + …`;
//! the computed `T̂_k` is within a factor `1 + γ_{2m+2}` of `T_k` and the computation of `d_k`
//! rounds a few more times, all covered by the factor 2 while `(2m + 8) ε < 1/2`.
//!
//! The filter then encloses `P(λ)` through `P(λ̂)`: for every coordinate,
//! `|P(λ̂ + δ) − P(λ̂)| ≤ S(|λ̂| + d) − S(|λ̂|)` with `S(μ) = Σ_α |c_α| B_α(μ)` whenever
//! `|δ_k| ≤ d_k` (expand each product `Π(a_i + δ_i)` of a Bernstein monomial: the terms with at
//! least one `δ_i` are bounded by `Π(|a_i| + d_i) − Π|a_i|`, and the weights `|c_α| n!/α!` are
//! non-negative). `S` is exactly the filter's condition number, so one more plain pass at
//! `|λ̂| + d` (rounded up) bounds the widening; it also bounds the condition number at the exact
//! `λ` from above (`S` is increasing in each `|λ_k|`), and `S(|λ̂|) − w` from below.
//!
//! That widening is about `n Σd S`, a few ulps. So the filter first evaluates at the
//! double-double `λ̂ + lo` (TwoSum gives `s + ê = λ̂ + lo` exactly, and the remaining radius
//! `fine` drops the `ε|λ̂|` term: it is of order `ε²`), where the widening is negligible
//! ([`CartesianPoint`]; `Filter::judge_cartesian`).

use num_rational::BigRational;
use num_traits::Zero;

use super::EPS;
use crate::domain::Domain;
use crate::number::round_f64;

/// The barycentric coordinates of one Cartesian float point, as the filter takes them: `λ̂`
/// with `|λ_k − λ̂_k| ≤ radius_k`, and the double-double `λ̂ + lo` with
/// `|λ_k − λ̂_k − lo_k| ≤ fine_k` (where the products of the map are exact, `fine` is of order
/// `ε²`; elsewhere `lo = 0` and `fine = radius`).
#[derive(Clone, Debug, Default)]
pub struct CartesianPoint {
    /// `λ̂` (`m + 1` entries).
    pub hi: Vec<f64>,
    /// The radii around `λ̂`.
    pub radius: Vec<f64>,
    /// The low parts.
    pub lo: Vec<f64>,
    /// The radii around `λ̂ + lo`.
    pub fine: Vec<f64>,
}

/// The barycentric map of a domain simplex in f64, with rigorous radii.
#[derive(Clone, Debug)]
pub struct CartesianMap {
    m: usize,
    /// Row `k`: `M_k1 … M_km`, then the constant `M_k0'`, each as a pair `(hi, lo)` with
    /// `hi = RN(M)`, `lo = RN(M − hi)`.
    rows: Vec<(f64, f64)>,
}

/// Non-zero factors of the error-free products stay in `[2^-450, 2^450]` (so TwoProduct is exact).
const SAFE_MIN: f64 = 2.409919865102884e-136; // 2^-450
const SAFE_MAX: f64 = 2.9073548971824276e135; // 2^450

fn safe(x: f64) -> bool {
    let a = x.abs();
    a == 0.0 || (SAFE_MIN..=SAFE_MAX).contains(&a)
}

impl CartesianMap {
    /// The map of `domain` (`None` if an entry of `M` overflows f64 or m is too large for the
    /// radius formula).
    pub fn new(domain: &Domain) -> Option<Self> {
        let m = domain.m();
        if (6 * m + 12) as f64 * EPS >= 0.5 {
            return None;
        }
        let origin = domain.barycentric(&vec![BigRational::zero(); m]).ok()?;
        let mut columns = Vec::with_capacity(m);
        for j in 0..m {
            let mut e = vec![BigRational::zero(); m];
            e[j] = BigRational::from_integer(1.into());
            columns.push(domain.direction(&e).ok()?);
        }
        let split = |q: &BigRational| {
            let hi = round_f64(q);
            let lo = crate::number::exact_f64(hi).map(|h| round_f64(&(q - h)));
            (hi, lo.unwrap_or(f64::NAN))
        };
        let mut rows = Vec::with_capacity((m + 1) * (m + 1));
        for k in 0..=m {
            for col in &columns {
                rows.push(split(&col[k]));
            }
            rows.push(split(&origin[k]));
        }
        rows.iter()
            .all(|(h, l)| h.is_finite() && l.is_finite())
            .then_some(CartesianMap { m, rows })
    }

    /// The barycentric coordinates of the Cartesian point `x` (`m` floats) into `out`;
    /// `false` when something is not finite (the row is then undecided).
    pub fn barycentric(&self, x: &[f64], out: &mut CartesianPoint) -> bool {
        let m = self.m;
        debug_assert_eq!(x.len(), m);
        let CartesianPoint {
            hi: lambda,
            radius,
            lo,
            fine,
        } = out;
        lambda.clear();
        radius.clear();
        lo.clear();
        fine.clear();
        let sum_x: f64 = x.iter().map(|v| v.abs()).sum();
        let absolute = super::tiny_times(4.0 * ((m + 3) as f64 + sum_x));
        let guarded = x.iter().all(|v| safe(*v));
        for row in self.rows.chunks_exact(m + 1) {
            // s + e ≈ Σ_j (hi_j + lo_j) x_j + hi_0 + lo_0: TwoProduct and TwoSum make the
            // leading part exact, e gathers the errors and the low parts in floats
            let (mut s, mut e, mut e_abs, mut t) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
            let mut exact_products = guarded;
            for ((hi, lo), v) in row[..m].iter().zip(x) {
                exact_products &= safe(*hi);
                let (p, pi) = super::two_product(*hi, *v);
                let (s2, sigma) = super::two_sum(s, p);
                s = s2;
                let small = lo * v;
                e += pi + sigma + small;
                e_abs += pi.abs() + sigma.abs() + small.abs() + e.abs();
                t += p.abs();
            }
            let (hi0, lo0) = row[m];
            let (s2, sigma) = super::two_sum(s, hi0);
            s = s2;
            e += sigma + lo0;
            e_abs += sigma.abs() + lo0.abs() + e.abs();
            t += hi0.abs();
            let (value, d, low, d_fine) = if exact_products {
                // λ = s + (the exact sum of e's terms) + Σ_j r_j x_j + r_0 with |r| ≤ ε|M − hi|
                // ≤ ε²|hi|(1 + ε) the low parts' own rounding (η if subnormal): ê errs by at
                // most ε per rounding of its ≤ 4(m+1) partial results, each at most e_abs; the
                // final l = fl(s + ê) by ε|l|, and TwoSum gives the exact s + ê = l + low.
                // Doubled for the roundings of d itself.
                let (l, low) = super::two_sum(s, e);
                let fine = (4 * m + 4) as f64 * EPS * e_abs + 2.0 * EPS * EPS * t + absolute;
                let d = EPS * l.abs() + fine;
                (l, 2.0 * d, low, 2.0 * fine)
            } else {
                // products near underflow or overflow: the plain dot product of the high parts,
                // |λ − λ̂| ≤ (γ_{m+1} + ε/(1−ε)) T + η's (module documentation), doubled
                let (mut acc, mut t) = (0.0f64, 0.0f64);
                for ((hi, _), v) in row[..m].iter().zip(x) {
                    let p = hi * v;
                    acc += p;
                    t += p.abs();
                }
                acc += hi0;
                t += hi0.abs();
                let d = 2.0 * (m + 2) as f64 * EPS * t + absolute;
                (acc, d, 0.0, d)
            };
            lambda.push(value);
            radius.push(d);
            lo.push(low);
            fine.push(d_fine);
        }
        [&*lambda, &*radius, &*lo, &*fine]
            .iter()
            .all(|v| v.iter().all(|x| x.is_finite()))
    }
}
