//! The floating-point filter: decide most claims about `p(λ)` without big integers.
//!
//! [`Filter`] evaluates the patch (its control points as the claimed code saw them: floats) in
//! f64 by de Casteljau and carries, per node, the running error bound of docs/theory.md §14.2
//! (after \[Higham02\] §3.1, "running error analysis"), extended to any sign of `λ` and any m:
//!
//! `μ = Σ_k |λ_k| μ_k + ε (Σ_k |p_k| + Σ_{k≥1} |s_k|) + (m + 1) η`,
//!
//! with `p_k = fl(λ_k A_k)` the products, `s_k` the partial sums, `ε = 2^-53` and `η = 2^-1075`
//! (underflowing products; additions are exact in the subnormal range), `μ = 0` on the control
//! points. Then `|ŷ − P(λ)| ≤ μ_final`. We compute μ itself in f64: every term is non-negative,
//! so the computed `μ̂` satisfies `μ ≤ μ̂ (1 + γ_K)` with `K ≤ (3m + 5) n` roundings per path, and
//! we inflate by `1 + 4Kε` and add an absolute `2^-1074` per operation (underflow in computing
//! `μ̂`; those allowances reach the apex with weight at most `Σ_{j≤n} (Σ|λ_k|)^j`, by which we
//! scale them). The same pass computes `Σ|c_i| B_i(|λ|)` with a relative enclosure
//! `1 ± 4(m+1)nε`.
//!
//! A second, compensated stage ([`Filter::evaluate_compensated`]) carries every node's exact
//! local error (TwoProduct, TwoSum) and a running bound of order `ε² Σ|c_i|B_i`. For `m ≤ 3` and
//! `dim ≤ 4` both stages run in lean kernels (`filter/kernel.rs`: in place, fixed-width loops);
//! the compensated one yields the condition number too, so tight tolerances skip the plain stage
//! ([`Filter::judge`], [`Filter::compensated_first`]).
//!
//! Given the claimed float `y`, the true error `|y − P|` lies in `[|y − ŷ| − μ, |y − ŷ| + μ]`
//! (widened by tiny margins for the roundings of these very comparisons); a tolerance is
//! [`Decision::Pass`] when every value in the enclosure passes, [`Decision::Fail`] when every one
//! fails, and [`Decision::Undecided`] otherwise (the caller then computes exactly). Non-finite
//! intermediates are undecided.
//!
//! A coordinate whose control values are all zero is exactly 0 at every finite `λ`
//! (`Σ_α 0·B_α(λ) = 0`), with condition number 0: both stages give it
//! [`Enclosure::EXACT_ZERO`], against which the error of a claim `y` is exactly `|y|`, so it is
//! decided in floats (a planar patch embedded in R^3 never falls back for its zero coordinate).

use crate::certify::bound::roundings;
use crate::exact::Algorithm;
use crate::float::Precision;
use crate::number::round_f64;
use crate::patch::ControlNet;
use crate::simplex::Simplex;

use super::measures::Tolerance;

pub mod cartesian;
mod kernel;

/// Safety margin of the comparisons (relative).
const R: f64 = 1.0 / (1u64 << 45) as f64;
/// f64 unit roundoff.
const EPS: f64 = 1.0 / (1u64 << 53) as f64;
/// Half the smallest subnormal, as an upper bound `2^-1074`.
const TINY: f64 = f64::from_bits(1);

/// An upper bound of `k · 2^-1074` for `k ≥ 0` (NaN for NaN, `+∞` for `+∞`): `⌈k⌉ · 2^-1074`,
/// computed without a multiplication that has a subnormal operand or result.
///
/// The absolute underflow allowances are small multiples of `η = 2^-1074`; computing them as
/// `k · η` costs a microcode assist on x86-64 (about 30 ns per multiplication, measured here,
/// against under 1 ns for a normal one: it was a fifth of `tribez check --results`). An integer
/// `j < 2^53` has the bit pattern of `j · 2^-1074` (subnormal below `2^52`, and the least
/// binade's normals from there), so below `2^52` the bound is a bit cast; above, `k · 2^-1074`
/// is normal and the two scalings by powers of two are exact.
#[inline]
pub(crate) fn tiny_times(k: f64) -> f64 {
    const TWO52: f64 = 4_503_599_627_370_496.0;
    if k < TWO52 {
        // ⌈k⌉ ≤ 2^52 (and 0 for k ≤ 0): j · 2^-1074 exactly (the truncation and the
        // comparison rather than `ceil`, a library call on baseline x86-64)
        let j = k as u64;
        f64::from_bits(if (j as f64) < k { j + 1 } else { j })
    } else {
        (k * (1.0 / TWO52)) * f64::MIN_POSITIVE
    }
}

/// What the filter concluded about one claimed coordinate.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Decision {
    /// Every value the exact result can take passes.
    Pass,
    /// Every value fails.
    Fail,
    /// The enclosure is too wide: compute exactly.
    Undecided,
}

/// One coordinate of `p(λ)` enclosed: `|ŷ − P| ≤ mu`, and `Σ|c_i|B_i(|λ|) ∈ [s_lo, s_hi]`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Enclosure {
    /// The f64 de Casteljau value.
    pub value: f64,
    /// A correction (compensated evaluation; 0 otherwise): `value + corr` approximates `P`.
    pub corr: f64,
    /// A rigorous bound on `|value + corr − P(λ)|` (exact sum).
    pub mu: f64,
    /// Lower bound of the condition number.
    pub s_lo: f64,
    /// Upper bound of the condition number.
    pub s_hi: f64,
}

impl Enclosure {
    /// The enclosure of a coordinate that is exactly zero at every point (all its control values
    /// are zero, so `P(λ) = Σ_α 0·B_α(λ) = 0` and `Σ|c_α|B_α(|λ|) = 0` for every finite `λ`):
    /// value, correction, bound and condition number all exactly 0.
    pub const EXACT_ZERO: Enclosure = Enclosure {
        value: 0.0,
        corr: 0.0,
        mu: 0.0,
        s_lo: 0.0,
        s_hi: 0.0,
    };

    /// Is this [`Enclosure::EXACT_ZERO`]? (No computed enclosure is: their bounds and condition
    /// numbers carry a positive underflow allowance.)
    pub fn is_exact_zero(&self) -> bool {
        self.value == 0.0 && self.corr == 0.0 && self.mu == 0.0 && self.s_hi == 0.0
    }
}

/// A tolerance prepared as f64 thresholds (each exact threshold enclosed by two floats).
#[derive(Clone, Debug)]
pub struct Thresholds {
    tolerance: Tolerance,
    precision: Precision,
    /// `[lo, hi]` enclosing the tolerance's number (N, E or K·ε, or γ_K for `bound`).
    k_lo: f64,
    k_hi: f64,
    /// The bound's absolute underflow allowance factor (for `bound`), in units of `2^-1074`
    /// ([`tiny_times`]): `2(m+1)η` with `η = 2^-1074` (f64) or `2^-150` (f32).
    underflow: f64,
    sum_abs_powers: bool,
    n: usize,
}

fn enclose(q: &num_rational::BigRational) -> (f64, f64) {
    let x = round_f64(q);
    if !x.is_finite() {
        return (f64::MAX, f64::INFINITY);
    }
    // a number that is a float (ulps=1, abs=2^-30, …) is its own enclosure
    if crate::number::exact_f64(x).as_ref() == Some(q) {
        return (x, x);
    }
    (
        (x * (1.0 - 4.0 * EPS)).max(0.0),
        x * (1.0 + 4.0 * EPS) + TINY,
    )
}

impl Thresholds {
    /// Prepare `tolerance` for claims of precision `precision` about a degree-`n` patch on the
    /// m-simplex evaluated by `algorithm` (used by `bound`).
    pub fn new(
        tolerance: &Tolerance,
        precision: Precision,
        algorithm: Algorithm,
        m: usize,
        n: usize,
    ) -> Self {
        let tolerance = &tolerance.for_patch(m, n);
        let (k_lo, k_hi) = match tolerance {
            Tolerance::Exact | Tolerance::CorrectlyRounded | Tolerance::Faithful => (0.0, 0.0),
            Tolerance::Ulps(x) | Tolerance::Abs(x) | Tolerance::Rel(x) => enclose(x),
            Tolerance::Cond(k) => enclose(&(k * super::measures::unit_roundoff(precision))),
            // invariant: for_patch turns CondDegree into Cond(K) for this patch's m and n
            Tolerance::CondDegree => unreachable!("resolved by for_patch above"),
            Tolerance::Bound => match super::bound::gamma(roundings(algorithm, m, n), precision) {
                Some(g) => enclose(&g),
                None => (f64::INFINITY, f64::INFINITY),
            },
        };
        let underflow = match precision {
            Precision::F64 => 2.0 * (m + 1) as f64,
            Precision::F32 => 2.0 * (m + 1) as f64 * 2f64.powi(924),
        };
        Thresholds {
            tolerance: tolerance.clone(),
            precision,
            k_lo,
            k_hi,
            underflow,
            sum_abs_powers: algorithm == Algorithm::Casteljau,
            n,
        }
    }

    /// An upper bound on the error of `y` in ULPs of the claim's precision (at the smallest
    /// `|P|` the enclosure allows).
    #[inline]
    pub fn ulps_upper(&self, y: f64, e: &Enclosure) -> f64 {
        if !(e.value.is_finite() && e.corr.is_finite() && e.mu.is_finite()) {
            return f64::INFINITY;
        }
        if e.is_exact_zero() {
            // P = 0: the error is |y| and ulp_p(0) a power of two, so the quotient is exact
            // (or overflows to +inf, an upper bound)
            return y.abs() / ulp_of(0.0, self.precision);
        }
        // as in `decide`: the error |y − P| ≤ |y − value − corr| + μ, widened for the roundings
        let d1 = y - e.value;
        let d = d1 - e.corr;
        let mu_eff = e.mu + 2.0 * EPS * (d1.abs() + e.corr.abs()) + TINY;
        let e_hi = (d.abs() * (1.0 + R) + mu_eff * (1.0 + R)) * (1.0 + R);
        let center = (e.value + e.corr).abs();
        let w = mu_eff * (1.0 + R) + center * 2.0 * EPS + TINY;
        let lo = if center > w { center - w } else { 0.0 };
        // the ulp is a power of two: the quotient is exact barring overflow
        e_hi / ulp_of(lo * (1.0 - R), self.precision)
    }

    /// A lower bound on the error of `y` in ULPs of the claim's precision (at the largest `|P|`
    /// the enclosure allows, so with the largest ulp); 0 when the enclosure is not finite.
    #[inline]
    pub fn ulps_lower(&self, y: f64, e: &Enclosure) -> f64 {
        if !(e.value.is_finite() && e.corr.is_finite() && e.mu.is_finite()) {
            return 0.0;
        }
        if e.is_exact_zero() {
            // exact, as in `ulps_upper`; an overflowed quotient exceeds f64::MAX
            return (y.abs() / ulp_of(0.0, self.precision)).min(f64::MAX);
        }
        let d1 = y - e.value;
        let d = d1 - e.corr;
        let mu_eff = e.mu + 2.0 * EPS * (d1.abs() + e.corr.abs()) + TINY;
        let e_lo = ((d.abs() * (1.0 - R) - mu_eff * (1.0 + R)) * (1.0 - R)).max(0.0);
        let center = (e.value + e.corr).abs();
        let w = mu_eff * (1.0 + R) + center * 2.0 * EPS + TINY;
        e_lo / ulp_of((center + w) * (1.0 + R), self.precision)
    }

    /// Decide one claimed coordinate `y` (finite) against the enclosure `e`; `s` is
    /// `Σ|λ_k|` (for the underflow allowance of `bound`).
    #[inline]
    pub fn decide(&self, y: f64, e: &Enclosure, s: f64) -> Decision {
        if !(e.value.is_finite() && e.mu.is_finite() && e.s_hi.is_finite()) {
            return Decision::Undecided;
        }
        if e.is_exact_zero()
            && let Some(d) = self.decide_at_zero(y)
        {
            return d;
        }
        let d1 = y - e.value;
        let d = d1 - e.corr;
        let dabs = d.abs();
        // the two subtractions round by at most ε|d1| and ε|d|
        let mu_eff = e.mu + 2.0 * EPS * (d1.abs() + e.corr.abs()) + TINY;
        // enclosure of the error |y − P|
        let e_hi = (dabs * (1.0 + R) + mu_eff * (1.0 + R)) * (1.0 + R);
        let e_lo = ((dabs * (1.0 - R) - mu_eff * (1.0 + R)) * (1.0 - R)).max(0.0);
        // enclosure of P
        let center = e.value + e.corr;
        let w = mu_eff * (1.0 + R) + center.abs() * 2.0 * EPS + TINY;
        let p_lo = center - w;
        let p_hi = center + w;
        let (pabs_lo, pabs_hi) = if p_lo > 0.0 {
            (p_lo * (1.0 - R), p_hi.abs() * (1.0 + R))
        } else if p_hi < 0.0 {
            (p_hi.abs() * (1.0 - R), p_lo.abs() * (1.0 + R))
        } else {
            (0.0, p_lo.abs().max(p_hi.abs()) * (1.0 + R))
        };
        let by_threshold = |lo: f64, hi: f64| {
            if e_hi <= lo * (1.0 - R) {
                Decision::Pass
            } else if e_lo > hi * (1.0 + R) {
                Decision::Fail
            } else {
                Decision::Undecided
            }
        };
        match &self.tolerance {
            Tolerance::Exact => {
                if e_hi == 0.0 {
                    Decision::Pass
                } else if e_lo > 0.0 {
                    Decision::Fail
                } else {
                    Decision::Undecided
                }
            }
            Tolerance::Abs(_) => by_threshold(self.k_lo, self.k_hi),
            Tolerance::Rel(_) => by_threshold(self.k_lo * pabs_lo, self.k_hi * pabs_hi),
            Tolerance::Ulps(_) => by_threshold(
                self.k_lo * ulp_of(pabs_lo, self.precision),
                self.k_hi * ulp_of(pabs_hi, self.precision),
            ),
            // `cond` was resolved to `cond=(m+1)n` by `Thresholds::new`
            Tolerance::Cond(_) | Tolerance::CondDegree => {
                by_threshold(self.k_lo * e.s_lo, self.k_hi * e.s_hi)
            }
            Tolerance::Bound => {
                let extra = if self.sum_abs_powers {
                    let mut g = 0.0;
                    let mut p = 1.0;
                    for _ in 0..self.n {
                        g += p;
                        p *= s;
                    }
                    tiny_times(self.underflow * g * (1.0 + R))
                } else {
                    0.0
                };
                by_threshold(self.k_lo * e.s_lo, self.k_hi * e.s_hi + extra)
            }
            Tolerance::CorrectlyRounded | Tolerance::Faithful => {
                let (prev, next) = neighbours(y, self.precision);
                let (fail_lo, fail_hi) = match self.precision {
                    Precision::F64 => (p_lo, p_hi),
                    Precision::F32 => (
                        neighbours(p_lo as f32 as f64, Precision::F32).0,
                        neighbours(p_hi as f32 as f64, Precision::F32).1,
                    ),
                };
                if y < fail_lo || y > fail_hi {
                    return Decision::Fail;
                }
                let faithful = matches!(self.tolerance, Tolerance::Faithful);
                // distances from y to the edges of the set of P for which y is acceptable
                let (g_lo, g_hi) = if faithful {
                    (y - prev, next - y)
                } else {
                    // beyond ±MAX, round to nearest goes to ±inf from MAX + ulp(MAX)/2 on
                    let half_top = match self.precision {
                        Precision::F64 => pow2f(970),
                        Precision::F32 => pow2f(103),
                    };
                    let half = |gap: f64| if gap.is_finite() { gap * 0.5 } else { half_top };
                    (half(y - prev), half(next - y))
                };
                let d_hi = d + dabs * 4.0 * EPS;
                let d_lo = d - dabs * 4.0 * EPS;
                let mu = mu_eff * (1.0 + R) + TINY;
                // d ≈ y − P: y is acceptable iff P lies in (y − g_lo, y + g_hi), i.e.
                // −g_hi < y − P < g_lo (ties at the ends are left to the exact path).
                if d_hi + mu < g_lo * (1.0 - R) && d_lo - mu > -g_hi * (1.0 - R) {
                    Decision::Pass
                } else if d_lo - mu > g_lo * (1.0 + R) || d_hi + mu < -g_hi * (1.0 + R) {
                    Decision::Fail
                } else {
                    Decision::Undecided
                }
            }
        }
    }
}

impl Thresholds {
    /// Decide `y` against the exact value `P = 0` with condition number `Σ|c|B = 0`
    /// ([`Enclosure::EXACT_ZERO`]): the error is exactly `|y|`, a float. `None` leaves it to the
    /// general enclosure test (`bound`, whose underflow allowance is not zero).
    fn decide_at_zero(&self, y: f64) -> Option<Decision> {
        if !y.is_finite() {
            return Some(Decision::Undecided);
        }
        // no error meets every tolerance (every threshold is ≥ 0)
        if y == 0.0 {
            return Some(Decision::Pass);
        }
        let a = y.abs();
        let by_threshold = |x: f64| {
            if x <= self.k_lo {
                Decision::Pass
            } else if x > self.k_hi {
                Decision::Fail
            } else {
                Decision::Undecided
            }
        };
        Some(match self.tolerance {
            // the threshold is exactly 0: E·|P|, K·ε·Σ|c|B, and RN_p(0) = 0 is the only float
            // that rounds or faithfully represents 0
            Tolerance::Exact
            | Tolerance::Rel(_)
            | Tolerance::Cond(_)
            | Tolerance::CondDegree
            | Tolerance::CorrectlyRounded
            | Tolerance::Faithful => Decision::Fail,
            Tolerance::Abs(_) => by_threshold(a),
            // |y| / ulp_p(0): a division by a power of two, exact unless it overflows (+inf,
            // which fails every finite N and is left undecided against an infinite one)
            Tolerance::Ulps(_) => by_threshold(a / ulp_of(0.0, self.precision)),
            Tolerance::Bound => return None,
        })
    }
}

/// The floats of precision `p` just below and above `y` (a float of that precision).
fn neighbours(y: f64, p: Precision) -> (f64, f64) {
    match p {
        Precision::F64 => (y.next_down(), y.next_up()),
        Precision::F32 => {
            let f = y as f32;
            (f64::from(f.next_down()), f64::from(f.next_up()))
        }
    }
}

/// Binade ulp of `|x|` in precision `p` (monotone in `|x|`), as an f64 (exact power of two;
/// docs/theory.md §14.4), by bit manipulation only.
fn ulp_of(x: f64, p: Precision) -> f64 {
    if !x.is_finite() {
        return f64::INFINITY;
    }
    let (emin, digits) = match p {
        Precision::F64 => (-1022, 52),
        Precision::F32 => (-126, 23),
    };
    let e = if x == 0.0 {
        emin
    } else {
        floor_log2(x.abs()).max(emin)
    };
    pow2f(e - digits)
}

/// `floor(log2 x)` of a finite positive f64.
fn floor_log2(x: f64) -> i32 {
    let bits = x.to_bits();
    let biased = ((bits >> 52) & 0x7ff) as i32;
    if biased == 0 {
        let mant = bits & ((1u64 << 52) - 1);
        63 - mant.leading_zeros() as i32 - 1074
    } else {
        biased - 1023
    }
}

/// `2^k` as an f64 for `−1074 ≤ k ≤ 1023`.
fn pow2f(k: i32) -> f64 {
    if k >= -1022 {
        f64::from_bits(((k + 1023) as u64) << 52)
    } else {
        f64::from_bits(1u64 << (k + 1074))
    }
}

/// A control net prepared for fast enclosed evaluation.
#[derive(Clone, Debug)]
pub struct Filter {
    m: usize,
    n: usize,
    dim: usize,
    coords: Vec<f64>,
    /// per level q = n..1: the m+1 child ranks of each node of degree q − 1.
    stencils: Vec<Vec<usize>>,
    mu_inflate: f64,
    /// The absolute allowance per operation of the running bound, in units of `2^-1074`
    /// ([`tiny_times`]).
    mu_absolute: f64,
    /// The same for the lean kernel at a double-double point (more roundings per path).
    mu_inflate_dd: f64,
    mu_absolute_dd: f64,
    s_rel: f64,
    /// `γ_{(m+1)n}` for f64, rounded up.
    gamma: f64,
    /// The lean compensated kernel, when one is compiled for this `(m, dim)`.
    lean: Option<kernel::Lean>,
    /// The largest control coordinate in magnitude (the scale of `abs=E` tolerances).
    scale: f64,
    /// Per coordinate, the largest control value in magnitude.
    largest: Vec<f64>,
    /// Per coordinate: every control value is zero, so the coordinate is exactly 0 everywhere
    /// ([`Enclosure::EXACT_ZERO`]).
    zero: Vec<bool>,
}

/// Reusable buffers for [`Filter::evaluate`] (one per thread).
#[derive(Clone, Debug, Default)]
pub struct Scratch {
    v: Vec<f64>,
    mu: Vec<f64>,
    s: Vec<f64>,
    v2: Vec<f64>,
    mu2: Vec<f64>,
    s2: Vec<f64>,
    lean: kernel::LeanScratch,
    /// Cartesian rows: the outer point `|λ̂| + d` and its enclosures.
    outer: Vec<f64>,
    wide: Vec<Enclosure>,
}

impl Filter {
    /// Prepare a net of floats (its values are exact: the control points as the code saw them).
    pub fn new(net: &ControlNet<f64>) -> Self {
        let (m, n, dim) = (net.m(), net.degree(), net.dim());
        let stencils = (1..=n)
            .rev()
            .map(|q| Simplex::new(m, q).step_stencil())
            .collect();
        let k = ((3 * m + 5) * n.max(1)) as f64;
        let nodes = crate::simplex::count(m, n) as f64 * (n as f64 + 1.0);
        Filter {
            m,
            n,
            dim,
            coords: net.coords().to_vec(),
            stencils,
            mu_inflate: 1.0 + 4.0 * k * EPS,
            mu_absolute: nodes * (4 * m + 8) as f64,
            mu_inflate_dd: 1.0 + 4.0 * ((6 * m + 10) * n.max(1)) as f64 * EPS,
            mu_absolute_dd: nodes * (6 * m + 14) as f64,
            s_rel: 4.0 * ((m + 1) * n.max(1)) as f64 * EPS,
            gamma: {
                // γ_{(m+1)n} in f64, rounded up generously
                let ke = ((m + 1) * n) as f64 * EPS;
                if ke < 0.5 {
                    ke / (1.0 - ke) * (1.0 + 8.0 * EPS)
                } else {
                    f64::INFINITY
                }
            },
            lean: kernel::Lean::new(m, n, dim, net.coords()),
            scale: net.coords().iter().fold(0.0, |a: f64, x| a.max(x.abs())),
            largest: (0..dim)
                .map(|c| {
                    net.coords()
                        .iter()
                        .skip(c)
                        .step_by(dim)
                        .fold(0.0, |a: f64, x| a.max(x.abs()))
                })
                .collect(),
            zero: (0..dim)
                .map(|c| net.coords().iter().skip(c).step_by(dim).all(|x| *x == 0.0))
                .collect(),
        }
    }

    /// Replace the enclosures of the coordinates that are exactly zero everywhere by
    /// [`Enclosure::EXACT_ZERO`] (for a finite `λ`; non-finite inputs stay undecided).
    fn mark_zeros(&self, lambda: &[f64], out: &mut [Enclosure]) {
        if self.zero.iter().any(|z| *z) && lambda.iter().all(|x| x.is_finite()) {
            for (o, z) in out.iter_mut().zip(&self.zero) {
                if *z {
                    *o = Enclosure::EXACT_ZERO;
                }
            }
        }
    }

    /// The net's dimension (coordinates per point).
    pub fn dim(&self) -> usize {
        self.dim
    }

    /// Enclose every coordinate of `P(λ)` (`λ` has `m + 1` float coordinates, any sum).
    pub fn evaluate(&self, lambda: &[f64], scratch: &mut Scratch, out: &mut [Enclosure]) {
        debug_assert_eq!(lambda.len(), self.m + 1);
        if let Some(lean) = &self.lean {
            let apex = lean.run_plain(lambda, &mut scratch.lean);
            self.finish_plain(lambda, apex.value, apex.nu, apex.s, out);
        } else {
            self.evaluate_generic(lambda, scratch, out);
        }
        self.mark_zeros(lambda, out);
    }

    /// The plain stage for any m and dim (the lean kernel computes the same numbers).
    fn evaluate_generic(&self, lambda: &[f64], scratch: &mut Scratch, out: &mut [Enclosure]) {
        let (m, dim) = (self.m, self.dim);
        let Scratch {
            v,
            mu,
            s,
            v2,
            mu2,
            s2,
            ..
        } = scratch;
        v.clear();
        v.extend_from_slice(&self.coords);
        mu.clear();
        mu.resize(v.len(), 0.0);
        s.clear();
        s.extend(self.coords.iter().map(|x| x.abs()));
        for stencil in &self.stencils {
            let nodes = stencil.len() / (m + 1);
            v2.clear();
            mu2.clear();
            s2.clear();
            for children in stencil.chunks_exact(m + 1) {
                for c in 0..dim {
                    let r0 = children[0] * dim + c;
                    let p0 = lambda[0] * v[r0];
                    let mut acc = p0;
                    let mut rounding = p0.abs();
                    let mut carried = lambda[0].abs() * mu[r0];
                    let mut cond = lambda[0].abs() * s[r0];
                    for k in 1..=m {
                        let r = children[k] * dim + c;
                        let p = lambda[k] * v[r];
                        acc += p;
                        rounding += p.abs() + acc.abs();
                        carried += lambda[k].abs() * mu[r];
                        cond += lambda[k].abs() * s[r];
                    }
                    v2.push(acc);
                    mu2.push(carried + EPS * rounding + (m + 1) as f64 * TINY);
                    s2.push(cond);
                }
            }
            debug_assert_eq!(v2.len(), nodes * dim);
            std::mem::swap(v, v2);
            std::mem::swap(mu, mu2);
            std::mem::swap(s, s2);
        }
        self.finish_plain(lambda, &v[..dim], &mu[..dim], &s[..dim], out);
    }

    /// `Σ_{j≤n} (Σ|λ_k|)^j` (for the absolute allowances carried to the apex) and
    /// `Σ_{j<n} (Σ|λ_k|)^j` (for the a-priori bound's underflow term).
    fn geometric(&self, lambda: &[f64]) -> (f64, f64) {
        self.geometric_sum(lambda.iter().map(|x| x.abs()).sum())
    }

    /// [`Filter::geometric`] of a given `Σ|λ_k|`.
    fn geometric_sum(&self, sum_abs: f64) -> (f64, f64) {
        let mut below = 0.0;
        let mut power = 1.0;
        for _ in 0..self.n {
            below += power;
            power *= sum_abs;
        }
        (below + power, below)
    }

    /// The plain enclosures from the apex's value, running bound and condition number.
    ///
    /// The absolute allowance `mu_absolute` for underflow in computing `μ` and `s` themselves
    /// (per operation) is carried to the apex by the later steps with weight at most `Σ|λ_k|`
    /// per step, so it is scaled by `Σ_{j≤n} (Σ|λ_k|)^j ≥ 1`.
    fn finish_plain(
        &self,
        lambda: &[f64],
        v: &[f64],
        mu: &[f64],
        s: &[f64],
        out: &mut [Enclosure],
    ) {
        let m = self.m;
        // The filter's own evaluation is de Casteljau in f64, so its a-priori bound applies too
        // (bound.rs): |ŷ − P| ≤ γ_{(m+1)n} Σ|c_i|B_i(|λ|) + 2(m+1)η Σ_{j<n} s^j, s = Σ|λ_k|.
        // The running bound is sharper near cancellation, the a-priori one on well-conditioned
        // data; both hold, so we take the smaller.
        let (all, below) = self.geometric(lambda);
        let absolute = tiny_times(self.mu_absolute * all * (1.0 + R));
        let underflow = tiny_times(2.0 * (m + 1) as f64 * below * (1.0 + R)) + TINY;
        for c in 0..self.dim {
            let s_hi = s[c] * (1.0 + self.s_rel) + absolute;
            let running = mu[c] * self.mu_inflate + absolute;
            let a_priori = self.gamma * s_hi * (1.0 + R) + underflow;
            out[c] = Enclosure {
                value: v[c],
                corr: 0.0,
                mu: if a_priori.is_finite() {
                    running.min(a_priori)
                } else {
                    running
                },
                s_lo: (s[c] * (1.0 - self.s_rel) - absolute).max(0.0),
                s_hi,
            };
        }
    }
}

/// The filter's conclusion about one row of claimed coordinates ([`Filter::judge`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RowJudgement {
    /// [`Decision::Fail`] when some coordinate surely fails, [`Decision::Pass`] when every one
    /// surely passes, [`Decision::Undecided`] otherwise (compute exactly).
    pub decision: Decision,
    /// An upper bound on the largest error in ULPs over the coordinates (from the enclosure
    /// that decided; infinite when nothing could be bounded).
    pub ulps: f64,
    /// A lower bound on it (0 when the enclosure is too wide to say more).
    pub ulps_lower: f64,
    /// Whether the deciding enclosures are the compensated ones (the bounds above are then
    /// tight, `O(ε²)` relative to the condition number).
    pub tight: bool,
}

/// Widen enclosures at `λ̂` to hold at every `λ` within the radii: `wide[c].mu ≥
/// S(|λ̂| + d) − S(|λ̂|)` bounds the move of `P`, `wide[c].s_hi ≥ S(|λ̂| + d)` the condition
/// number (docs/theory.md §14.5).
fn widen(enc: &mut [Enclosure], wide: &[Enclosure]) {
    for (e, w) in enc.iter_mut().zip(wide) {
        if e.is_exact_zero() && w.is_exact_zero() {
            continue;
        }
        e.mu = (e.mu + w.mu) * (1.0 + 2.0 * EPS);
        let lo = e.s_lo - w.mu;
        e.s_lo = if lo > 0.0 {
            lo * (1.0 - 2.0 * EPS)
        } else {
            0.0
        };
        e.s_hi = w.s_hi;
    }
}

/// An upper bound of `(s + t)^n − s^n` for `s, t ≥ 0` (`n ≥ 1`): `n t (s + t)^{n−1}` by the mean
/// value theorem, with `s + t` raised to 1 when smaller and `n t` to the least normal float (so
/// that nothing is subnormal and every rounding is relative), inflated for the `n + 3` roundings;
/// infinite on overflow.
fn growth(n: usize, s: f64, t: f64) -> f64 {
    let q = ((s + t) * (1.0 + 2.0 * EPS)).max(1.0);
    let mut power = 1.0;
    for _ in 1..n {
        power *= q;
    }
    (n as f64 * t).max(f64::MIN_POSITIVE) * power * (1.0 + 4.0 * (n + 2) as f64 * EPS)
}

/// The row's conclusion from one set of enclosures.
fn conclude(th: &Thresholds, claimed: &[f64], enc: &[Enclosure], s: f64) -> RowJudgement {
    let mut all_pass = true;
    let mut any_fail = false;
    let mut ulps = 0f64;
    let mut ulps_lower = 0f64;
    for (y, e) in claimed.iter().zip(enc) {
        match th.decide(*y, e, s) {
            Decision::Pass => {}
            Decision::Fail => any_fail = true,
            Decision::Undecided => all_pass = false,
        }
        ulps = ulps.max(th.ulps_upper(*y, e));
        ulps_lower = ulps_lower.max(th.ulps_lower(*y, e));
    }
    RowJudgement {
        decision: if any_fail {
            Decision::Fail
        } else if all_pass {
            Decision::Pass
        } else {
            Decision::Undecided
        },
        ulps,
        ulps_lower,
        tight: false,
    }
}

impl Filter {
    /// Whether rows at `th` should go straight to the compensated stage: the plain stage's
    /// running bound is typically a few `(m+1)n ε Σ|c|B` (docs/theory.md §14.2), so a tolerance
    /// narrower than about that (`exact`, `correctly_rounded`, `faithful`, a few ulps, a small
    /// `rel`/`abs`/`cond`) is rarely decided by it, and running it first only adds its cost. The
    /// choice affects speed only: [`Filter::judge`] tries both stages before giving up.
    pub fn compensated_first(&self, th: &Thresholds) -> bool {
        let unit = ((self.m + 1) * self.n.max(1)) as f64;
        match (th.precision, &th.tolerance) {
            (_, Tolerance::Exact) => true,
            (Precision::F32, _) => false,
            (Precision::F64, Tolerance::CorrectlyRounded | Tolerance::Faithful) => true,
            (Precision::F64, Tolerance::Ulps(_)) => th.k_hi < 1.5 * unit,
            (Precision::F64, Tolerance::Rel(_)) => th.k_hi < 2.5 * unit * EPS,
            (Precision::F64, Tolerance::Abs(_)) => th.k_hi < 0.3 * unit * EPS * self.scale,
            (Precision::F64, Tolerance::Cond(_) | Tolerance::CondDegree) => {
                th.k_hi < 0.7 * unit * EPS
            }
            (Precision::F64, Tolerance::Bound) => false,
        }
    }

    /// Tight bounds `(lower, upper)` on the largest error in ULPs over the coordinates of
    /// `claimed`, from the compensated enclosure (the plain one where the compensated stage's
    /// guards leave it open): for ranking rows by their error without exact arithmetic.
    pub fn ulps_bounds(
        &self,
        th: &Thresholds,
        lambda: &[f64],
        claimed: &[f64],
        scratch: &mut Scratch,
        enc: &mut [Enclosure],
    ) -> (f64, f64) {
        // the generic compensated stage keeps the plain stage's condition numbers
        if self.lean.is_none() {
            self.evaluate(lambda, scratch, enc);
        }
        self.evaluate_compensated(lambda, scratch, enc);
        if enc.iter().any(|e| !e.mu.is_finite()) {
            self.evaluate(lambda, scratch, enc);
        }
        claimed
            .iter()
            .zip(enc.iter())
            .fold((0f64, 0f64), |(lo, hi), (y, e)| {
                (lo.max(th.ulps_lower(*y, e)), hi.max(th.ulps_upper(*y, e)))
            })
    }

    /// Judge one row: the claimed coordinates `claimed` (finite floats) of `P(λ)` against `th`,
    /// by the plain and the compensated enclosures, in the order [`Filter::compensated_first`]
    /// picks; the second stage runs only when the first leaves the row undecided. `enc` needs
    /// [`Filter::dim`] entries and holds the deciding enclosures afterwards. This is the path of
    /// `tribez check --results` (and of the `check` bench).
    pub fn judge(
        &self,
        th: &Thresholds,
        lambda: &[f64],
        claimed: &[f64],
        scratch: &mut Scratch,
        enc: &mut [Enclosure],
    ) -> RowJudgement {
        let first = self.compensated_first(th);
        self.judge_in_order(th, lambda, claimed, scratch, enc, first)
    }

    /// [`Filter::judge`] starting with the compensated stage whenever a lean kernel exists,
    /// whatever the tolerance: for callers that want the tight ULP figures of every row anyway
    /// (the histogram and worst row of `tribez check --results`), one compensated pass is
    /// cheaper than a plain pass followed by a compensated one.
    pub fn judge_tight(
        &self,
        th: &Thresholds,
        lambda: &[f64],
        claimed: &[f64],
        scratch: &mut Scratch,
        enc: &mut [Enclosure],
    ) -> RowJudgement {
        self.judge_in_order(th, lambda, claimed, scratch, enc, true)
    }

    /// Judge a Cartesian row, its barycentric coordinates computed in floats
    /// ([`cartesian::CartesianMap`]): first at the double-double point `λ̂ + lo` by the lean
    /// kernel, whose enclosure is as tight as at a barycentric row (`O(ε²)`), widened only for
    /// the tiny radii `fine` (`Filter::judge_double_double`); when that leaves the row
    /// undecided, or there is no lean kernel, the widened stages at `λ̂`
    /// ([`Filter::judge_tight_uncertain`]). `tight` in the result: decided by the first.
    pub fn judge_cartesian(
        &self,
        th: &Thresholds,
        point: &cartesian::CartesianPoint,
        claimed: &[f64],
        scratch: &mut Scratch,
        enc: &mut [Enclosure],
    ) -> RowJudgement {
        if let Some(lean) = &self.lean {
            let r = self.judge_double_double(lean, th, point, claimed, scratch, enc);
            if r.decision != Decision::Undecided {
                return r;
            }
        }
        self.judge_tight_uncertain(th, &point.hi, &point.radius, claimed, scratch, enc)
    }

    /// The compensated enclosures at the exact `λ` with `|λ_k − hi_k − lo_k| ≤ fine_k`
    /// (docs/theory.md §14.5): the lean kernel at `hi + lo` ([`kernel::Lean::run_dd`]) encloses
    /// `P(hi + lo)`; `P` moves by at most `S(|hi + lo| + fine) − S(|hi + lo|)` from there, and
    /// with `S(μ) = Σ_α |c_α| B_α(μ) ≤ max|c| (Σ_k μ_k)^n` term by term,
    /// `S(w + t) − S(w) ≤ max|c| ((Σw + Σt)^n − (Σw)^n) ≤ max|c| n Σt (Σw + Σt)^{n−1}` for
    /// `w, t ≥ 0` ([`growth`]), with `Σw ≤ σ = Σ(|hi_k| + |lo_k|)`. That is `O(ε²)` here. The
    /// condition number at `λ` is within the same kind of bound of the kernel's `S(|hi|)`, with
    /// `t = |lo| + fine`.
    fn judge_double_double(
        &self,
        lean: &kernel::Lean,
        th: &Thresholds,
        p: &cartesian::CartesianPoint,
        claimed: &[f64],
        scratch: &mut Scratch,
        enc: &mut [Enclosure],
    ) -> RowJudgement {
        let (m, n) = (self.m, self.n);
        // sums of m + 1 non-negative terms, rounded up
        let up = 1.0 + 4.0 * (m + 2) as f64 * EPS;
        let sum = |f: &dyn Fn(usize) -> f64| (0..=m).map(f).sum::<f64>() * up;
        let sigma_hi = sum(&|k| p.hi[k].abs());
        let sigma = sum(&|k| p.hi[k].abs() + p.lo[k].abs());
        let tau = sum(&|k| p.fine[k]);
        let near = growth(n, sigma, tau);
        let far = growth(n, sigma_hi, sum(&|k| p.lo[k].abs() + p.fine[k]));
        // the kernel's weights per step are Σ(|hi_k| + |lo_k|)
        let absolute = tiny_times(self.mu_absolute_dd * self.geometric_sum(sigma).0 * (1.0 + R));
        let (ok, apex) = lean.run_dd(&p.hi, &p.lo, &mut scratch.lean);
        kernel::enclosures(
            ok && absolute.is_finite() && near.is_finite() && far.is_finite(),
            &apex,
            self.mu_inflate_dd,
            absolute,
            self.s_rel,
            enc,
        );
        for (e, top) in enc.iter_mut().zip(&self.largest) {
            // (+η: the products may be subnormal)
            let moved = top * near * (1.0 + 2.0 * EPS) + TINY;
            let moved_s = top * far * (1.0 + 2.0 * EPS) + TINY;
            e.mu = (e.mu + moved) * (1.0 + 2.0 * EPS);
            let lo = e.s_lo - moved_s;
            e.s_lo = if lo > 0.0 {
                lo * (1.0 - 2.0 * EPS)
            } else {
                0.0
            };
            e.s_hi = (e.s_hi + moved_s) * (1.0 + 2.0 * EPS);
        }
        self.mark_zeros(&p.hi, enc);
        let mut r = conclude(th, claimed, enc, sigma + tau);
        r.tight = enc.iter().all(|e| e.mu.is_finite());
        r
    }

    /// [`Filter::judge_tight`] at the exact point `λ` known only as `λ̂ = lambda` with radii
    /// `|λ_k − λ̂_k| ≤ radius[k]` (a Cartesian input converted in floats,
    /// [`cartesian::CartesianMap`]): every enclosure is widened by `S(|λ̂| + d) − S(|λ̂|)`
    /// (docs/theory.md §14.5), its condition-number bounds made to hold at every such `λ`.
    pub fn judge_tight_uncertain(
        &self,
        th: &Thresholds,
        lambda: &[f64],
        radius: &[f64],
        claimed: &[f64],
        scratch: &mut Scratch,
        enc: &mut [Enclosure],
    ) -> RowJudgement {
        let undecided = RowJudgement {
            decision: Decision::Undecided,
            ulps: f64::INFINITY,
            ulps_lower: 0.0,
            tight: false,
        };
        // |λ̂| and the radii; Σ_k (|λ̂_k| + d_k) ≥ Σ|λ_k| for the a-priori bound's underflow term
        let mut outer = std::mem::take(&mut scratch.outer);
        let mut wide = std::mem::take(&mut scratch.wide);
        outer.clear();
        outer.extend(lambda.iter().map(|l| l.abs()));
        let s_abs: f64 = outer.iter().zip(radius).map(|(a, d)| a + d).sum::<f64>()
            * (1.0 + 2.0 * (self.m + 2) as f64 * EPS);
        wide.clear();
        wide.resize(enc.len(), Enclosure::default());
        self.widening(&outer, radius, scratch, &mut wide);
        let ok = wide.iter().all(|w| w.mu.is_finite() && w.s_hi.is_finite()) && s_abs.is_finite();
        let result = if ok {
            let first = self.lean.is_some();
            let mut r = undecided;
            for stage in 0..2 {
                if (stage == 0) == first {
                    self.evaluate_compensated(lambda, scratch, enc);
                } else {
                    self.evaluate(lambda, scratch, enc);
                }
                widen(enc, &wide);
                r = conclude(th, claimed, enc, s_abs);
                r.tight = false;
                if r.decision != Decision::Undecided {
                    break;
                }
            }
            r
        } else {
            undecided
        };
        scratch.outer = outer;
        scratch.wide = wide;
        result
    }

    /// Per coordinate, upper bounds of `Δ = S(a + d) − S(a)` (in `mu`) and of `S(a + d)` (in
    /// `s_hi`), `a = |λ̂| ≥ 0`, `d ≥ 0`, `S(μ) = Σ_α |c_α| B_α(μ)` (docs/theory.md §14.5).
    ///
    /// de Casteljau on `|c|` at `a + d`, each node split into the part `A` at `a` and the rest:
    /// `A = Σ_k a_k A_k`, `Δ = Σ_k (a_k + d_k) Δ_k + Σ_k d_k A_k`, from `A = |c|`, `Δ = 0`. Every
    /// term is non-negative, so with `K = (4m + 4)n` roundings per path the computed values are
    /// within a factor `1 + γ_K` of the exact ones; we inflate by `1 + 4Kε` and add an absolute
    /// `2^-1074` per operation, scaled by `Σ_{j≤n} (Σ_k (a_k + d_k))^j`, for underflow. The
    /// lean kernel runs the pass where one is compiled (`m ≤ 3`, `dim ≤ 4`).
    fn widening(&self, a: &[f64], d: &[f64], scratch: &mut Scratch, out: &mut [Enclosure]) {
        match &self.lean {
            Some(lean) => {
                let (s_at_a, delta) = lean.run_widen(a, d, &mut scratch.lean);
                self.finish_widening(a, d, s_at_a, delta, out);
            }
            None => self.widening_generic(a, d, scratch, out),
        }
    }

    /// [`Filter::widening`] for any m and dim (the lean kernel computes the same numbers).
    fn widening_generic(&self, a: &[f64], d: &[f64], scratch: &mut Scratch, out: &mut [Enclosure]) {
        let (m, dim) = (self.m, self.dim);
        let Scratch { v, mu, v2, mu2, .. } = scratch;
        v.clear();
        v.extend(self.coords.iter().map(|x| x.abs()));
        mu.clear();
        mu.resize(v.len(), 0.0);
        for stencil in &self.stencils {
            v2.clear();
            mu2.clear();
            for children in stencil.chunks_exact(m + 1) {
                for c in 0..dim {
                    let mut acc = 0.0;
                    let mut delta = 0.0;
                    for k in 0..=m {
                        let r = children[k] * dim + c;
                        acc += a[k] * v[r];
                        delta += (a[k] + d[k]) * mu[r] + d[k] * v[r];
                    }
                    v2.push(acc);
                    mu2.push(delta);
                }
            }
            std::mem::swap(v, v2);
            std::mem::swap(mu, mu2);
        }
        self.finish_widening(a, d, &v[..dim], &mu[..dim], out);
    }

    /// The enclosures of [`Filter::widening`] from the apex's `S(a)` and `Δ` (per coordinate),
    /// inflated for their roundings.
    fn finish_widening(
        &self,
        a: &[f64],
        d: &[f64],
        s_at_a: &[f64],
        delta: &[f64],
        out: &mut [Enclosure],
    ) {
        let (m, dim, n) = (self.m, self.dim, self.n);
        let k = ((4 * m + 4) * n.max(1)) as f64;
        let inflate = 1.0 + 4.0 * k * EPS;
        let sum: f64 =
            a.iter().zip(d).map(|(x, y)| x + y).sum::<f64>() * (1.0 + 2.0 * (m + 2) as f64 * EPS);
        let mut geometric = 0.0;
        let mut power = 1.0;
        for _ in 0..=n {
            geometric += power;
            power *= sum;
        }
        let nodes = crate::simplex::count(m, n) as f64 * (n as f64 + 1.0);
        let absolute = tiny_times(nodes * (6 * m + 8) as f64 * geometric * (1.0 + R));
        for c in 0..dim {
            let delta = delta[c] * inflate + absolute;
            let s_at_a = s_at_a[c] * inflate + absolute;
            let zero = self.zero[c];
            out[c] = Enclosure {
                value: 0.0,
                corr: 0.0,
                mu: if zero { 0.0 } else { delta },
                s_lo: 0.0,
                s_hi: if zero {
                    0.0
                } else {
                    (s_at_a + delta) * (1.0 + 2.0 * EPS)
                },
            };
        }
    }

    fn judge_in_order(
        &self,
        th: &Thresholds,
        lambda: &[f64],
        claimed: &[f64],
        scratch: &mut Scratch,
        enc: &mut [Enclosure],
        compensated_first: bool,
    ) -> RowJudgement {
        let s: f64 = lambda.iter().map(|x| x.abs()).sum();
        // the generic compensated stage needs the plain stage's condition numbers
        let first = self.lean.is_some() && compensated_first;
        if first {
            self.evaluate_compensated(lambda, scratch, enc);
        } else {
            self.evaluate(lambda, scratch, enc);
        }
        let tight = |enc: &[Enclosure]| enc.iter().all(|e| e.mu.is_finite());
        let mut r = conclude(th, claimed, enc, s);
        if r.decision != Decision::Undecided {
            r.tight = first && tight(enc);
            return r;
        }
        if first {
            self.evaluate(lambda, scratch, enc);
        } else {
            self.evaluate_compensated(lambda, scratch, enc);
        }
        let mut r = conclude(th, claimed, enc, s);
        r.tight = !first && tight(enc);
        r
    }
}

/// Dekker's TwoProduct without FMA: `a·b = p + π` exactly when no split overflows and the
/// partial products do not underflow (guarded by the caller) (\[Higham02\] §4.3, Dekker 1971).
#[inline]
fn two_product(a: f64, b: f64) -> (f64, f64) {
    const SPLIT: f64 = 134_217_729.0; // 2^27 + 1
    let p = a * b;
    let ca = SPLIT * a;
    let ah = ca - (ca - a);
    let al = a - ah;
    let cb = SPLIT * b;
    let bh = cb - (cb - b);
    let bl = b - bh;
    (p, al * bl - (((p - ah * bh) - al * bh) - ah * bl))
}

/// Knuth's TwoSum: `a + b = s + σ` exactly (barring overflow).
#[inline]
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

impl Filter {
    /// A compensated enclosure (the second stage, for claims the plain one leaves undecided).
    ///
    /// Every product `λ_k V_k = p_k + π_k` (TwoProduct) and partial sum `s + p = s' + σ` (TwoSum)
    /// is split exactly into the computed value and its error, so with the children's exact
    /// errors `E_k` the node's exact error is `E = Σ_k π_k + Σ σ + Σ_k λ_k E_k`. We compute it in
    /// f64 (`Ê`) with a running bound `ν ≥ |E − Ê|`: `ν = Σ|λ_k| ν_k + ε Σ|partials| + (m+1)η`
    /// (the same model as the plain running bound). Then `|V + Ê − P| ≤ ν`, of order `ε² Σ|c|B`.
    /// For `(m, dim)` with a lean kernel ([`Filter::has_lean_kernel`]: `m ≤ 3`, `dim ≤ 4`) the
    /// condition-number bounds are computed in the same pass; otherwise `out` must hold the
    /// plain enclosures of [`Filter::evaluate`] at the same `λ` and their condition-number
    /// bounds are kept. Guards: a factor of magnitude `≥ 2^990` (the split could overflow) or a
    /// non-zero product of non-zero factors below `2^-900` (TwoProduct could be inexact) makes
    /// the enclosure undecided (NaN).
    pub fn evaluate_compensated(
        &self,
        lambda: &[f64],
        scratch: &mut Scratch,
        out: &mut [Enclosure],
    ) {
        match &self.lean {
            Some(lean) => self.evaluate_lean(lean, lambda, scratch, out),
            None => self.evaluate_compensated_generic(lambda, scratch, out),
        }
        self.mark_zeros(lambda, out);
    }

    /// Whether the lean compensated kernel serves this net (`m ≤ 3`, `dim ≤ 4`, `n ≥ 1`).
    pub fn has_lean_kernel(&self) -> bool {
        self.lean.is_some()
    }

    /// The lean kernel ([`kernel`]): the compensated enclosure and the condition-number bounds
    /// in one pass (`out` need not hold anything).
    ///
    /// The absolute allowance for underflow in computing `ν` and `s` themselves
    /// (`mu_absolute`, per operation) is carried to the apex by the later steps with weight at
    /// most `Σ|λ_k|` per step, so it is scaled by `Σ_{j≤n} (Σ|λ_k|)^j ≥ 1`.
    fn evaluate_lean(
        &self,
        lean: &kernel::Lean,
        lambda: &[f64],
        scratch: &mut Scratch,
        out: &mut [Enclosure],
    ) {
        let absolute = tiny_times(self.mu_absolute * self.geometric(lambda).0 * (1.0 + R));
        let (ok, apex) = lean.run(lambda, &mut scratch.lean);
        kernel::enclosures(
            ok && absolute.is_finite(),
            &apex,
            self.mu_inflate,
            absolute,
            self.s_rel,
            out,
        );
    }

    /// The generic compensated stage (any m and dim), as documented at
    /// [`Filter::evaluate_compensated`].
    fn evaluate_compensated_generic(
        &self,
        lambda: &[f64],
        scratch: &mut Scratch,
        out: &mut [Enclosure],
    ) {
        let (m, dim) = (self.m, self.dim);
        let big = 2f64.powi(990);
        let small = 2f64.powi(-900);
        let Scratch {
            v,
            mu,
            s,
            v2,
            mu2,
            s2,
            ..
        } = scratch;
        // v: values, s: corrections Ê, mu: ν
        v.clear();
        v.extend_from_slice(&self.coords);
        s.clear();
        s.resize(v.len(), 0.0);
        mu.clear();
        mu.resize(v.len(), 0.0);
        let mut bad = lambda.iter().any(|x| x.abs() >= big) || v.iter().any(|x| x.abs() >= big);
        for stencil in &self.stencils {
            v2.clear();
            s2.clear();
            mu2.clear();
            for children in stencil.chunks_exact(m + 1) {
                for c in 0..dim {
                    let mut acc = 0.0;
                    let mut corr = 0.0;
                    let mut partial = 0.0;
                    let mut carried = 0.0;
                    for k in 0..=m {
                        let r = children[k] * dim + c;
                        let (p, pi) = two_product(lambda[k], v[r]);
                        if p.abs() >= big
                            || (p != 0.0 && p.abs() < small)
                            || (p == 0.0 && lambda[k] != 0.0 && v[r] != 0.0)
                        {
                            bad = true;
                        }
                        let term = lambda[k] * s[r];
                        if k == 0 {
                            acc = p;
                            corr = pi + term;
                            partial = term.abs() + corr.abs();
                        } else {
                            let (sum, sigma) = two_sum(acc, p);
                            acc = sum;
                            corr += pi;
                            partial += corr.abs();
                            corr += sigma;
                            partial += corr.abs();
                            corr += term;
                            partial += term.abs() + corr.abs();
                        }
                        carried += lambda[k].abs() * mu[r];
                    }
                    v2.push(acc);
                    s2.push(corr);
                    mu2.push(carried + EPS * partial + (m + 1) as f64 * TINY);
                }
            }
            std::mem::swap(v, v2);
            std::mem::swap(s, s2);
            std::mem::swap(mu, mu2);
        }
        let absolute = tiny_times(self.mu_absolute * self.geometric(lambda).0 * (1.0 + R));
        for c in 0..dim {
            // s_lo and s_hi (the condition number) stay those of the plain enclosure in `out`
            out[c].value = v[c];
            out[c].corr = s[c];
            out[c].mu = if bad || !s[c].is_finite() {
                f64::NAN
            } else {
                mu[c] * self.mu_inflate + absolute
            };
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::exact::ExactEvaluator;
    use crate::number::{exact_f64, parse_rational as q};
    use num_rational::BigRational;
    use num_traits::Signed;

    fn lcg(state: &mut u64) -> f64 {
        *state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((*state >> 11) as f64) / (1u64 << 53) as f64
    }

    /// `tiny_times(k)` is `⌈k⌉ · 2^-1074` exactly below `2^53` and `k · 2^-1074` above (exact
    /// scalings), checked in rationals against the definition, with the edge cases.
    #[test]
    fn tiny_times_is_the_ceiling_multiple_of_the_least_subnormal() {
        let eta = BigRational::new(1.into(), num_bigint::BigInt::from(1) << 1074usize);
        let ks = [
            0.0,
            -1.0,
            0.25,
            1.0,
            1.5,
            60.0,
            123_456.789,
            4_503_599_627_370_495.5,
            4_503_599_627_370_496.0,
            4_503_599_627_370_497.0,
            9_007_199_254_740_993.0,
            1e30,
            2f64.powi(1000),
        ];
        for k in ks {
            let got = exact_f64(tiny_times(k)).unwrap();
            let want = if k <= 0.0 {
                BigRational::from_integer(0.into())
            } else {
                exact_f64(k).unwrap().ceil() * &eta
            };
            assert_eq!(got, want, "k = {k}");
        }
        // the old expression, where it is exact, agrees
        assert_eq!(tiny_times(60.0), 60.0 * TINY);
        assert!(tiny_times(f64::NAN).is_nan());
        assert_eq!(tiny_times(f64::INFINITY), f64::INFINITY);
        // above 2^52 the result is normal, and a power-of-two multiple stays exact
        assert_eq!(tiny_times(2f64.powi(60)), 2f64.powi(-1014));
    }

    #[test]
    fn correct_rounding_at_a_power_of_two_uses_the_smaller_gap_below() {
        use crate::certify::measures::Tolerance;
        // y = 1: the floats below are 2^-53 apart, above 2^-52. P = 1 − 3·2^-55 rounds to
        // 1 − 2^-53, so y = 1 is not correctly rounded (but faithful).
        let th = Thresholds::new(
            &Tolerance::CorrectlyRounded,
            Precision::F64,
            Algorithm::Casteljau,
            2,
            1,
        );
        let e = Enclosure {
            value: 1.0,
            corr: -3.0 * 2f64.powi(-55),
            mu: 2f64.powi(-70),
            s_lo: 1.0,
            s_hi: 1.0,
        };
        assert_eq!(th.decide(1.0, &e, 1.0), Decision::Fail);
        let e = Enclosure {
            value: 1.0,
            corr: -2f64.powi(-56),
            mu: 2f64.powi(-70),
            s_lo: 1.0,
            s_hi: 1.0,
        };
        assert_eq!(th.decide(1.0, &e, 1.0), Decision::Pass);
        let e = Enclosure {
            value: 1.0,
            corr: 3.0 * 2f64.powi(-55),
            mu: 2f64.powi(-70),
            s_lo: 1.0,
            s_hi: 1.0,
        };
        assert_eq!(th.decide(1.0, &e, 1.0), Decision::Pass);
        let thf = Thresholds::new(
            &Tolerance::Faithful,
            Precision::F64,
            Algorithm::Casteljau,
            2,
            1,
        );
        let e = Enclosure {
            value: 1.0,
            corr: -3.0 * 2f64.powi(-55),
            mu: 2f64.powi(-70),
            s_lo: 1.0,
            s_hi: 1.0,
        };
        assert_eq!(thf.decide(1.0, &e, 1.0), Decision::Pass);
    }

    #[test]
    fn correct_rounding_at_the_largest_float_knows_where_overflow_starts() {
        use crate::certify::measures::Tolerance;
        // f32: MAX = 2^128 − 2^104; P ≥ MAX + 2^103 rounds to inf, below that to MAX
        let max = f64::from(f32::MAX);
        for (p, y, half) in [
            (Precision::F32, max, 2f64.powi(103)),
            (Precision::F64, f64::MAX, 2f64.powi(970)),
        ] {
            let th = Thresholds::new(&Tolerance::CorrectlyRounded, p, Algorithm::Casteljau, 2, 1);
            let at = |corr: f64| Enclosure {
                value: y,
                corr,
                mu: 0.0,
                s_lo: y,
                s_hi: y,
            };
            assert_eq!(th.decide(y, &at(0.5 * half), 1.0), Decision::Pass, "{p:?}");
            assert_eq!(th.decide(y, &at(1.5 * half), 1.0), Decision::Fail, "{p:?}");
            let below = |corr: f64| Enclosure {
                value: -y,
                corr,
                mu: 0.0,
                s_lo: y,
                s_hi: y,
            };
            assert_eq!(th.decide(-y, &below(-0.5 * half), 1.0), Decision::Pass);
            assert_eq!(th.decide(-y, &below(-1.5 * half), 1.0), Decision::Fail);
        }
    }

    #[test]
    fn ulp_by_bits_matches_the_exact_ulp() {
        for x in [
            0.0,
            5e-324,
            1e-310,
            2.2250738585072014e-308,
            1e-40,
            1.1754943508222875e-38,
            0.1,
            1.0,
            3.0,
            1e300,
        ] {
            let q = exact_f64(x).unwrap();
            assert_eq!(
                exact_f64(ulp_of(x, Precision::F64)).unwrap(),
                crate::number::ulp_f64(&q),
                "{x}"
            );
            assert_eq!(
                exact_f64(ulp_of(x, Precision::F32)).unwrap(),
                crate::number::ulp_f32(&q),
                "{x}"
            );
        }
    }

    #[test]
    fn enclosures_contain_the_exact_value() {
        let mut st = 7u64;
        for n in [1usize, 2, 3, 5] {
            let simplex = Simplex::new(2, n);
            let coords: Vec<f64> = (0..simplex.len() * 2)
                .map(|i| (lcg(&mut st) - 0.5) * 10f64.powi((i % 7) as i32 * 40 - 120))
                .collect();
            let net = ControlNet::new(simplex, 2, coords);
            let f = Filter::new(&net);
            let exact = ExactEvaluator::new(&net.map(|x| exact_f64(*x).unwrap()));
            let mut sc = Scratch::default();
            let mut out = vec![Enclosure::default(); 2];
            for _ in 0..200 {
                let lam = [
                    lcg(&mut st) * 3.0 - 1.0,
                    lcg(&mut st) * 3.0 - 1.0,
                    lcg(&mut st) * 3.0 - 1.0,
                ];
                f.evaluate(&lam, &mut sc, &mut out);
                let l: Vec<BigRational> = lam.iter().map(|x| exact_f64(*x).unwrap()).collect();
                let p = exact.evaluate(&l, Algorithm::Casteljau);
                let s = crate::certify::bound::condition(&net.map(|x| exact_f64(*x).unwrap()), &l);
                let mut comp = out.clone();
                f.evaluate_compensated(&lam, &mut sc, &mut comp);
                for c in 0..2 {
                    let e = &comp[c];
                    if e.mu.is_finite() {
                        let err = (exact_f64(e.value).unwrap() + exact_f64(e.corr).unwrap()
                            - &p[c])
                            .abs();
                        assert!(err <= exact_f64(e.mu).unwrap(), "compensated n={n} {lam:?}");
                        assert!(e.mu <= out[c].mu, "compensated is sharper n={n}");
                    }
                }
                for c in 0..2 {
                    let e = &out[c];
                    let err = (exact_f64(e.value).unwrap() - &p[c]).abs();
                    assert!(err <= exact_f64(e.mu).unwrap(), "n={n} {lam:?}");
                    assert!(
                        exact_f64(e.s_lo).unwrap() <= s[c] && s[c] <= exact_f64(e.s_hi).unwrap()
                    );
                }
            }
        }
    }

    #[test]
    fn decisions_agree_with_the_exact_judgement() {
        use crate::certify::measures::{Leaf, Tolerance};
        let net = ControlNet::new(
            Simplex::new(2, 3),
            1,
            (0..10).map(|i| 1.0 / (i as f64 + 1.0)).collect(),
        );
        let f = Filter::new(&net);
        let exact = ExactEvaluator::new(&net.map(|x| exact_f64(*x).unwrap()));
        let mut sc = Scratch::default();
        let mut out = vec![Enclosure::default(); 1];
        let mut st = 3u64;
        let tols = [
            "exact",
            "ulps=64",
            "cond=64",
            "ulps=1",
            "ulps=3",
            "abs=1e-16",
            "rel=1e-16",
            "correctly_rounded",
            "faithful",
            "cond=2",
            "bound",
        ];
        for p in [Precision::F64, Precision::F32] {
            for t in tols {
                let tol = Tolerance::parse(t).unwrap();
                let th = Thresholds::new(&tol, p, Algorithm::Casteljau, 2, 3);
                let mut decided = 0;
                for _ in 0..300 {
                    let lam = [lcg(&mut st), lcg(&mut st), lcg(&mut st)];
                    f.evaluate(&lam, &mut sc, &mut out);
                    let l: Vec<BigRational> = lam.iter().map(|x| exact_f64(*x).unwrap()).collect();
                    let pe = &exact.evaluate(&l, Algorithm::Casteljau)[0];
                    let base = match p {
                        Precision::F64 => round_f64(pe),
                        Precision::F32 => f64::from(crate::number::round_f32(pe)),
                    };
                    let steps = (lcg(&mut st) * 5.0) as i32 - 2;
                    let mut y = base;
                    for _ in 0..steps.abs() {
                        y = match (p, steps > 0) {
                            (Precision::F64, true) => y.next_up(),
                            (Precision::F64, false) => y.next_down(),
                            (Precision::F32, true) => f64::from((y as f32).next_up()),
                            (Precision::F32, false) => f64::from((y as f32).next_down()),
                        };
                    }
                    let yq = exact_f64(y).unwrap();
                    let s =
                        crate::certify::bound::condition(&net.map(|x| exact_f64(*x).unwrap()), &l)
                            [0]
                        .clone();
                    let bound =
                        crate::certify::bound::a_priori(Algorithm::Casteljau, p, 2, 3, &s, &l);
                    let leaf = Leaf {
                        precision: Some(p),
                        condition: Some(s),
                        bound,
                    };
                    let truth = tol.accepts(&yq, pe, &leaf).unwrap();
                    let sabs: f64 = lam.iter().map(|x| x.abs()).sum();
                    let mut dec = th.decide(y, &out[0], sabs);
                    if dec == Decision::Undecided {
                        let mut comp = out.clone();
                        f.evaluate_compensated(&lam, &mut sc, &mut comp);
                        dec = th.decide(y, &comp[0], sabs);
                    }
                    match dec {
                        Decision::Pass => {
                            assert!(truth, "{t} {p:?} {lam:?} {y}");
                            decided += 1
                        }
                        Decision::Fail => {
                            assert!(!truth, "{t} {p:?} {lam:?} {y}");
                            decided += 1
                        }
                        Decision::Undecided => {}
                    }
                }
                // with the compensated second stage every tolerance but `exact` decides some claims
                assert!(decided > 0 || t == "exact", "{t} {p:?} never decided");
            }
        }
        let _ = q("1");
    }

    /// A named net with the points to evaluate it at.
    type StressCase = (&'static str, ControlNet<f64>, Vec<Vec<f64>>);

    /// Nets and points that stress the filter: (m, dim) with and without a lean kernel,
    /// ill-conditioned coordinates (an alternating net: `Σ(−1)^{α_0} B_α = (λ_1 + … − λ_0)^n`,
    /// zero on `λ_0 = 1/2` while `Σ|c|B = 1`; the linear `λ_0 − λ_1`), points near those zeros
    /// and outside the simplex (any signs), huge and tiny magnitudes, and inputs that trip the
    /// compensated kernel's guards (tiny control values, subnormal and huge `λ`).
    fn stress_cases() -> Vec<StressCase> {
        let mut st = 11u64;
        let mut cases = Vec::new();
        let points = |st: &mut u64, m: usize, count: usize| -> Vec<Vec<f64>> {
            (0..count)
                .map(|i| {
                    let mut l: Vec<f64> = (0..=m).map(|_| lcg(st)).collect();
                    match i % 5 {
                        // inside, summing to about 1
                        0 => {
                            let t: f64 = l.iter().sum();
                            l.iter_mut().for_each(|x| *x /= t);
                        }
                        // outside: any signs
                        1 => l.iter_mut().for_each(|x| *x = *x * 5.0 - 2.0),
                        // near λ_0 = 1/2 (the alternating net's zero), the rest summing to 1/2
                        2 => {
                            let t: f64 = l[1..].iter().sum();
                            l[1..].iter_mut().for_each(|x| *x *= 0.5 / t);
                            l[0] = 0.5 + (lcg(st) - 0.5) * 1e-12;
                        }
                        // near λ_0 = λ_1 (the linear coordinate's zero)
                        3 => l[1] = l[0] * (1.0 + (lcg(st) - 0.5) * 1e-13),
                        // far out, large weights
                        _ => l.iter_mut().for_each(|x| *x = (*x - 0.3) * 1e3),
                    }
                    l
                })
                .collect()
        };
        for (name, m, dim, n) in [
            ("m=2 dim=3 n=3", 2, 3, 3),
            ("m=1 dim=1 n=5", 1, 1, 5),
            ("m=3 dim=2 n=2", 3, 2, 2),
            ("m=2 dim=4 n=4", 2, 4, 4),
            ("m=2 dim=5 n=3 (generic kernel)", 2, 5, 3),
            ("m=4 dim=1 n=2 (generic kernel)", 4, 1, 2),
        ] {
            let simplex = Simplex::new(m, n);
            let mut coords = Vec::new();
            for alpha in simplex.iter() {
                for c in 0..dim {
                    coords.push(match c {
                        0 => (alpha[0] as f64 - alpha[1] as f64) / n as f64,
                        1 => {
                            if alpha[0] % 2 == 0 {
                                1.0
                            } else {
                                -1.0
                            }
                        }
                        2 => (lcg(&mut st) - 0.5) * 10f64.powi((lcg(&mut st) * 200.0) as i32 - 100),
                        _ => (lcg(&mut st) - 0.5) * 3.0,
                    });
                }
            }
            let pts = points(&mut st, m, 60);
            cases.push((name, ControlNet::new(simplex, dim, coords), pts));
        }
        // guards: subnormal, tiny and huge λ on an ordinary net
        let mut pts = points(&mut st, 2, 20);
        pts.extend([
            vec![5e-324, 0.5, 0.5],
            vec![1e-310, -1e-200, 1.0],
            vec![1e-100, 1e-100, 1.0],
            vec![1e95, -1e95, 1.0],
            vec![1e-95, 1e95, 1.0],
            vec![0.0, 0.0, 1.0],
            vec![0.0, 0.0, 0.0],
        ]);
        let simplex = Simplex::new(2, 3);
        let coords = (0..simplex.len() * 2)
            .map(|i| (lcg(&mut st) - 0.5) * (i as f64 + 1.0))
            .collect();
        cases.push(("guards: λ", ControlNet::new(simplex, 2, coords), pts));
        // guards: tiny control values (below 2^-500) beside ordinary and huge ones
        let simplex = Simplex::new(2, 3);
        let coords: Vec<f64> = (0..simplex.len() * 2)
            .map(|i| match i % 4 {
                0 => 1e-160 * (i as f64 + 1.0),
                1 => -3.0 / (i as f64 + 1.0),
                2 => 1e-300,
                _ => 1e150,
            })
            .collect();
        let mut pts = points(&mut st, 2, 30);
        pts.extend([
            vec![5e-324, 0.5, 0.5],
            vec![1e-310, -1e-200, 1.0],
            vec![1e-100, 1e-100, 1.0],
            vec![1e95, -1e95, 1.0],
            vec![0.0, 0.0, 1.0],
            vec![0.0, 0.0, 0.0],
        ]);
        cases.push(("guards: control", ControlNet::new(simplex, 2, coords), pts));
        cases
    }

    #[test]
    fn every_stage_encloses_the_exact_value_on_the_stress_cases() {
        for (name, net, pts) in stress_cases() {
            let f = Filter::new(&net);
            let exact_net = net.map(|x| exact_f64(*x).unwrap());
            let exact = ExactEvaluator::new(&exact_net);
            let dim = net.dim();
            let mut sc = Scratch::default();
            let (mut plain, mut comp, mut generic) = (
                vec![Enclosure::default(); dim],
                vec![Enclosure::default(); dim],
                vec![Enclosure::default(); dim],
            );
            let mut lean_finite = 0;
            for lam in &pts {
                let l: Vec<BigRational> = lam.iter().map(|x| exact_f64(*x).unwrap()).collect();
                let p = exact.evaluate(&l, Algorithm::Casteljau);
                let s = crate::certify::bound::condition(&exact_net, &l);
                f.evaluate(lam, &mut sc, &mut plain);
                // the lean plain kernel computes the generic code's numbers
                let mut plain_generic = vec![Enclosure::default(); dim];
                f.evaluate_generic(lam, &mut sc, &mut plain_generic);
                for (a, b) in plain.iter().zip(&plain_generic) {
                    let same = |x: f64, y: f64| x == y || (x.is_nan() && y.is_nan());
                    assert!(
                        same(a.value, b.value)
                            && same(a.mu, b.mu)
                            && same(a.s_lo, b.s_lo)
                            && same(a.s_hi, b.s_hi),
                        "{name}: lean plain {a:?} generic {b:?} at {lam:?}"
                    );
                }
                // the lean kernel (where compiled) overwrites the condition numbers: start from
                // nonsense to see that it does
                comp.iter_mut().for_each(|e| {
                    *e = Enclosure {
                        s_lo: -1.0,
                        s_hi: -1.0,
                        ..plain[0]
                    }
                });
                if !f.has_lean_kernel() {
                    comp.copy_from_slice(&plain);
                }
                f.evaluate_compensated(lam, &mut sc, &mut comp);
                generic.copy_from_slice(&plain);
                f.evaluate_compensated_generic(lam, &mut sc, &mut generic);
                for c in 0..dim {
                    let within = |e: &Enclosure, what: &str| {
                        if !(e.value.is_finite() && e.corr.is_finite() && e.mu.is_finite()) {
                            return false;
                        }
                        let err = (exact_f64(e.value).unwrap() + exact_f64(e.corr).unwrap()
                            - &p[c])
                            .abs();
                        assert!(
                            err <= exact_f64(e.mu).unwrap(),
                            "{name}: {what} misses P at {lam:?}, coordinate {c}"
                        );
                        if e.s_hi.is_finite() {
                            assert!(
                                exact_f64(e.s_lo).unwrap() <= s[c]
                                    && s[c] <= exact_f64(e.s_hi).unwrap(),
                                "{name}: {what} condition number at {lam:?}, coordinate {c}"
                            );
                        }
                        true
                    };
                    within(&plain[c], "plain");
                    let g = within(&generic[c], "generic compensated");
                    if within(&comp[c], "compensated") {
                        lean_finite += 1;
                        if g {
                            // the same operations in the same order
                            assert_eq!(comp[c].value, generic[c].value, "{name}");
                            assert_eq!(comp[c].corr, generic[c].corr, "{name}");
                        }
                    }
                }
            }
            // (tiny control values trip the lean kernel's guard on every point)
            assert!(
                lean_finite > 0 || (name == "guards: control" && f.has_lean_kernel()),
                "{name}: the compensated stage never applied"
            );
        }
    }

    #[test]
    fn the_lean_widening_computes_the_generic_numbers_on_the_stress_cases() {
        let same = |x: f64, y: f64| x.to_bits() == y.to_bits() || (x.is_nan() && y.is_nan());
        let mut lean_nets = 0;
        for (name, net, pts) in stress_cases() {
            let f = Filter::new(&net);
            lean_nets += usize::from(f.has_lean_kernel());
            let dim = net.dim();
            let mut sc = Scratch::default();
            let (mut lean, mut generic) = (
                vec![Enclosure::default(); dim],
                vec![Enclosure::default(); dim],
            );
            for lam in &pts {
                let a: Vec<f64> = lam.iter().map(|x| x.abs()).collect();
                // radii: none, a few ulps, subnormal, large, and uneven across coordinates
                for scale in [0.0, 4.0 * EPS, 1e-310, 1e-3] {
                    let d: Vec<f64> = a
                        .iter()
                        .enumerate()
                        .map(|(k, x)| (x + 1.0) * scale * (k + 1) as f64)
                        .collect();
                    f.widening(&a, &d, &mut sc, &mut lean);
                    f.widening_generic(&a, &d, &mut sc, &mut generic);
                    for (x, y) in lean.iter().zip(&generic) {
                        assert!(
                            same(x.mu, y.mu) && same(x.s_hi, y.s_hi) && same(x.s_lo, y.s_lo),
                            "{name}: lean {x:?} generic {y:?} at {lam:?}, radii {d:?}"
                        );
                    }
                }
            }
        }
        assert!(lean_nets > 0, "no stress case has a lean kernel");
    }

    #[test]
    fn row_judgements_agree_with_the_exact_judgement_on_the_stress_cases() {
        use crate::certify::measures::{Leaf, Tolerance};
        let tols = [
            "exact",
            "ulps=1",
            "ulps=3",
            "ulps=64",
            "abs=1e-16",
            "rel=1e-16",
            "rel=1e-12",
            "correctly_rounded",
            "faithful",
            "cond=2",
            "cond=64",
            "bound",
        ];
        let mut st = 5u64;
        let mut compensated_decided = 0;
        for (name, net, pts) in stress_cases() {
            let (m, n, dim) = (net.m(), net.degree(), net.dim());
            let f = Filter::new(&net);
            let exact_net = net.map(|x| exact_f64(*x).unwrap());
            let exact = ExactEvaluator::new(&exact_net);
            let mut sc = Scratch::default();
            let mut enc = vec![Enclosure::default(); dim];
            for lam in &pts {
                let l: Vec<BigRational> = lam.iter().map(|x| exact_f64(*x).unwrap()).collect();
                let pe = exact.evaluate(&l, Algorithm::Casteljau);
                let s = crate::certify::bound::condition(&exact_net, &l);
                for p in [Precision::F64, Precision::F32] {
                    // the claimed row: each coordinate the rounded exact value, moved by −2..2 units
                    let mut ys = Vec::with_capacity(dim);
                    for exact_c in &pe {
                        let mut y = match p {
                            Precision::F64 => round_f64(exact_c),
                            Precision::F32 => f64::from(crate::number::round_f32(exact_c)),
                        };
                        let steps = (lcg(&mut st) * 5.0) as i32 - 2;
                        for _ in 0..steps.abs() {
                            y = match (p, steps > 0) {
                                (Precision::F64, true) => y.next_up(),
                                (Precision::F64, false) => y.next_down(),
                                (Precision::F32, true) => f64::from((y as f32).next_up()),
                                (Precision::F32, false) => f64::from((y as f32).next_down()),
                            };
                        }
                        ys.push(y);
                    }
                    if ys.iter().any(|y| !y.is_finite()) {
                        continue;
                    }
                    for t in tols {
                        let tol = Tolerance::parse(t).unwrap();
                        let th = Thresholds::new(&tol, p, Algorithm::Casteljau, m, n);
                        let truth = (0..dim).all(|c| {
                            let leaf = Leaf {
                                precision: Some(p),
                                condition: Some(s[c].clone()),
                                bound: crate::certify::bound::a_priori(
                                    Algorithm::Casteljau,
                                    p,
                                    m,
                                    n,
                                    &s[c],
                                    &l,
                                ),
                            };
                            tol.accepts(&exact_f64(ys[c]).unwrap(), &pe[c], &leaf)
                                .unwrap()
                        });
                        let r = f.judge(&th, lam, &ys, &mut sc, &mut enc);
                        match r.decision {
                            Decision::Pass => assert!(truth, "{name} {t} {p:?} {lam:?} {ys:?}"),
                            Decision::Fail => assert!(!truth, "{name} {t} {p:?} {lam:?} {ys:?}"),
                            Decision::Undecided => {}
                        }
                        if r.decision == Decision::Pass {
                            // the ulps figure bounds the true error
                            for c in 0..dim {
                                let e = crate::number::ulps_error_f64(
                                    &exact_f64(ys[c]).unwrap(),
                                    &pe[c],
                                );
                                if p == Precision::F64 && r.ulps.is_finite() {
                                    assert!(
                                        e <= BigRational::from_float(r.ulps).unwrap(),
                                        "{name} {t} ulps"
                                    );
                                }
                            }
                        }
                        if p == Precision::F64 {
                            // the row's largest error in ULPs lies between the lower and upper
                            // figures of the judgement and of the compensated ulps_bounds
                            let e_max = (0..dim)
                                .map(|c| {
                                    crate::number::ulps_error_f64(
                                        &exact_f64(ys[c]).unwrap(),
                                        &pe[c],
                                    )
                                })
                                .max()
                                .unwrap();
                            let (lo, hi) = f.ulps_bounds(&th, lam, &ys, &mut sc, &mut enc);
                            for (lo, hi) in [(r.ulps_lower, r.ulps), (lo, hi)] {
                                assert!(
                                    BigRational::from_float(lo).unwrap() <= e_max,
                                    "{name} {t} lower {lo} > {e_max}"
                                );
                                if hi.is_finite() {
                                    assert!(
                                        e_max <= BigRational::from_float(hi).unwrap(),
                                        "{name} {t} upper {hi} < {e_max}"
                                    );
                                }
                            }
                        }
                        if r.decision != Decision::Undecided
                            && f.has_lean_kernel()
                            && f.compensated_first(&th)
                        {
                            compensated_decided += 1;
                        }
                    }
                }
            }
        }
        assert!(compensated_decided > 100, "{compensated_decided}");
    }

    #[test]
    fn tight_tolerances_go_to_the_compensated_stage_first() {
        use crate::certify::measures::Tolerance;
        let net = ControlNet::new(
            Simplex::new(2, 3),
            3,
            (0..30).map(|i| 1.0 / (i as f64 + 1.0)).collect(),
        );
        let f = Filter::new(&net);
        assert!(f.has_lean_kernel());
        let first = |t: &str, p| {
            let th = Thresholds::new(&Tolerance::parse(t).unwrap(), p, Algorithm::Casteljau, 2, 3);
            f.compensated_first(&th)
        };
        for t in [
            "exact",
            "correctly_rounded",
            "faithful",
            "ulps=4",
            "rel=1e-15",
            "cond=2",
        ] {
            assert!(first(t, Precision::F64), "{t}");
        }
        for t in ["cond=9", "bound", "ulps=64", "rel=1e-12", "abs=1e-6"] {
            assert!(!first(t, Precision::F64), "{t}");
        }
        for t in ["correctly_rounded", "faithful", "ulps=1"] {
            assert!(!first(t, Precision::F32), "{t}");
        }
    }

    /// Runs the lean kernel of `net` (if it has one) both ways at every point of `pts` and
    /// asserts the same guard verdict and, where the guards hold, the same bits in every apex
    /// quantity; returns how many points were compared.
    fn fma_equals_dekker(name: &str, net: &ControlNet<f64>, pts: &[Vec<f64>]) -> usize {
        let f = Filter::new(net);
        let Some(lean) = &f.lean else { return 0 };
        let (mut a, mut b) = (
            kernel::LeanScratch::default(),
            kernel::LeanScratch::default(),
        );
        for lam in pts {
            let (ok, x) = lean.run(lam, &mut a);
            let (ok_d, y) = lean.run_dekker(lam, &mut b);
            assert_eq!(ok, ok_d, "{name}: guards at {lam:?}");
            let bits = |q: &[f64]| q.iter().map(|v| v.to_bits()).collect::<Vec<_>>();
            assert_eq!(bits(x.value), bits(y.value), "{name}: values at {lam:?}");
            assert_eq!(bits(x.s), bits(y.s), "{name}: condition at {lam:?}");
            if ok {
                assert_eq!(bits(x.corr), bits(y.corr), "{name}: corrections at {lam:?}");
                assert_eq!(bits(x.nu), bits(y.nu), "{name}: bounds at {lam:?}");
            }
            // and at a double-double point
            let lo = low_parts(lam);
            let (ok, x) = lean.run_dd(lam, &lo, &mut a);
            let (ok_d, y) = lean.run_dd_dekker(lam, &lo, &mut b);
            assert_eq!(ok, ok_d, "{name}: guards at {lam:?} + {lo:?}");
            assert_eq!(
                bits(x.value),
                bits(y.value),
                "{name}: values at {lam:?} + {lo:?}"
            );
            if ok {
                assert_eq!(bits(x.corr), bits(y.corr), "{name}: corrections at {lam:?}");
                assert_eq!(bits(x.nu), bits(y.nu), "{name}: bounds at {lam:?} + {lo:?}");
            }
        }
        pts.len()
    }

    /// Low parts for a point: `λ_k·2^-54` times a factor in `[−1, 1)` that varies with `k` (0
    /// for some coordinates), as the Cartesian map's double-double results have.
    fn low_parts(lam: &[f64]) -> Vec<f64> {
        lam.iter()
            .enumerate()
            .map(|(k, x)| x * 2f64.powi(-54) * [0.0, 0.75, -1.0, -0.3][k % 4])
            .collect()
    }

    /// At a double-double point `λ = hi + lo` (the Cartesian rows' first stage), the enclosures
    /// contain the exact value and condition number at `hi + lo` (computed exactly), on every
    /// stress case; and they are tight: the error bound is below a thousandth of an ulp of
    /// the condition number wherever the guards let the kernel run.
    #[test]
    fn double_double_enclosures_hold_on_the_stress_cases() {
        let mut tight = 0;
        for (name, net, pts) in stress_cases() {
            let f = Filter::new(&net);
            let Some(lean) = &f.lean else { continue };
            let exact_net = net.map(|x| exact_f64(*x).unwrap());
            let exact = ExactEvaluator::new(&exact_net);
            let mut sc = Scratch::default();
            let mut enc = vec![Enclosure::default(); net.dim()];
            let th = Thresholds::new(
                &Tolerance::parse("ulps=1").unwrap(),
                Precision::F64,
                Algorithm::Casteljau,
                net.m(),
                net.degree(),
            );
            for lam in &pts {
                let lo = low_parts(lam);
                let point = cartesian::CartesianPoint {
                    hi: lam.clone(),
                    radius: vec![f64::INFINITY; lam.len()],
                    fine: vec![TINY; lam.len()],
                    lo: lo.clone(),
                };
                let l: Vec<BigRational> = lam
                    .iter()
                    .zip(&lo)
                    .map(|(h, x)| exact_f64(*h).unwrap() + exact_f64(*x).unwrap())
                    .collect();
                let p = exact.evaluate(&l, Algorithm::Casteljau);
                let s = crate::certify::bound::condition(&exact_net, &l);
                let claimed: Vec<f64> = p.iter().map(round_f64).collect();
                f.judge_double_double(lean, &th, &point, &claimed, &mut sc, &mut enc);
                for (c, e) in enc.iter().enumerate() {
                    if !(e.value.is_finite() && e.corr.is_finite() && e.mu.is_finite()) {
                        continue;
                    }
                    let err =
                        (exact_f64(e.value).unwrap() + exact_f64(e.corr).unwrap() - &p[c]).abs();
                    assert!(
                        err <= exact_f64(e.mu).unwrap(),
                        "{name}: misses P at {lam:?} + {lo:?}, coordinate {c}"
                    );
                    assert!(
                        exact_f64(e.s_lo).unwrap() <= s[c] && s[c] <= exact_f64(e.s_hi).unwrap(),
                        "{name}: condition number at {lam:?} + {lo:?}, coordinate {c}"
                    );
                    if e.mu <= 1e-3 * EPS * e.s_hi {
                        tight += 1;
                    }
                }
            }
        }
        assert!(tight > 100, "only {tight} tight enclosures");
    }

    /// The compensated kernel with FMA (where the processor has AVX2 and FMA) computes the
    /// Dekker kernel's numbers bit for bit on the stress cases, guards included.
    #[test]
    fn the_fma_kernel_equals_the_dekker_kernel_on_the_stress_cases() {
        let mut compared = 0;
        for (name, net, pts) in stress_cases() {
            compared += fma_equals_dekker(name, &net, &pts);
        }
        assert!(compared > 300, "{compared}");
        #[cfg(target_arch = "x86_64")]
        {
            let fma = std::arch::is_x86_feature_detected!("avx2")
                && std::arch::is_x86_feature_detected!("fma");
            let (name, net, _) = stress_cases().swap_remove(0);
            let f = Filter::new(&net);
            assert_eq!(f.lean.as_ref().unwrap().uses_fma(), fma, "{name}");
            if !fma {
                eprintln!("this processor lacks AVX2 or FMA: both kernels are Dekker's here");
            }
        }
    }

    /// A float `mantissa · 2^exponent` with a random sign, or 0.
    fn scaled() -> impl proptest::strategy::Strategy<Value = f64> {
        use proptest::prelude::*;
        (-1.0f64..1.0, -80i32..80, 0u8..10).prop_map(
            |(x, e, zero)| {
                if zero == 0 { 0.0 } else { x * 2f64.powi(e) }
            },
        )
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(48))]

        /// Every kernel (lean where compiled, generic otherwise) encloses the exact value of
        /// random nets of mixed magnitudes at random points of any sign, and the lean plain
        /// kernel computes the generic one's numbers.
        #[test]
        fn enclosures_hold_on_random_nets(
            m in 1usize..=4,
            n in 1usize..=4,
            dim in 1usize..=5,
            values in proptest::collection::vec(scaled(), 140),
            lam in proptest::collection::vec(-3.0f64..3.0, 5),
        ) {
            let simplex = Simplex::new(m, n);
            let coords: Vec<f64> = (0..simplex.len() * dim).map(|i| values[i % values.len()]).collect();
            let net = ControlNet::new(simplex, dim, coords);
            let f = Filter::new(&net);
            let exact_net = net.map(|x| exact_f64(*x).unwrap());
            let lam = &lam[..=m];
            let l: Vec<BigRational> = lam.iter().map(|x| exact_f64(*x).unwrap()).collect();
            let p = ExactEvaluator::new(&exact_net).evaluate(&l, Algorithm::Casteljau);
            let s = crate::certify::bound::condition(&exact_net, &l);
            let mut sc = Scratch::default();
            let mut plain = vec![Enclosure::default(); dim];
            let mut generic = vec![Enclosure::default(); dim];
            f.evaluate(lam, &mut sc, &mut plain);
            f.evaluate_generic(lam, &mut sc, &mut generic);
            f.mark_zeros(lam, &mut generic);
            proptest::prop_assert_eq!(&plain, &generic);
            let mut comp = plain.clone();
            f.evaluate_compensated(lam, &mut sc, &mut comp);
            for c in 0..dim {
                for e in [&plain[c], &comp[c]] {
                    if e.mu.is_finite() {
                        let err = (exact_f64(e.value).unwrap() + exact_f64(e.corr).unwrap() - &p[c]).abs();
                        proptest::prop_assert!(err <= exact_f64(e.mu).unwrap());
                        proptest::prop_assert!(exact_f64(e.s_lo).unwrap() <= s[c] && s[c] <= exact_f64(e.s_hi).unwrap());
                    }
                }
            }
        }

        /// The FMA kernel equals the Dekker kernel bit for bit on random nets of mixed
        /// magnitudes (some beyond the guards) at random points of any sign and magnitude.
        #[test]
        fn the_fma_kernel_equals_the_dekker_kernel_on_random_nets(
            m in 1usize..=3,
            n in 1usize..=7,
            dim in 1usize..=4,
            values in proptest::collection::vec(scaled(), 140),
            wild in proptest::collection::vec((-1.0f64..1.0, -320i32..320), 4),
            lam in proptest::collection::vec(proptest::collection::vec(-3.0f64..3.0, 4), 8),
        ) {
            let simplex = Simplex::new(m, n);
            let coords: Vec<f64> = (0..simplex.len() * dim)
                .map(|i| match (i % 17, wild.get(i % 5)) {
                    (0, Some(&(x, e))) => x * 2f64.powi(e),
                    _ => values[i % values.len()],
                })
                .collect();
            let net = ControlNet::new(simplex, dim, coords);
            let mut pts: Vec<Vec<f64>> = lam.iter().map(|l| l[..=m].to_vec()).collect();
            pts.push(wild.iter().take(m + 1).map(|&(x, e)| x * 2f64.powi(e)).collect());
            proptest::prop_assert_eq!(fma_equals_dekker("random", &net, &pts), pts.len());
        }

        /// Coordinates whose control values are all zero are exactly 0 at every point: the
        /// filter decides them without exact arithmetic (a claimed 0 always passes; a non-zero
        /// claim fails every tolerance whose threshold is 0 there), and every row decision
        /// agrees with the exact judgement (the generic exact path, [`ExactEvaluator`]).
        #[test]
        fn zero_coordinates_are_decided_and_agree_with_the_exact_path(
            m in 1usize..=4,
            n in 1usize..=4,
            dim in 1usize..=5,
            zero_mask in 1u32..32,
            values in proptest::collection::vec(scaled(), 140),
            lam in proptest::collection::vec(-3.0f64..3.0, 5),
            zero_claims in proptest::collection::vec((0u8..6, 0u32..4), 5),
        ) {
            use crate::certify::measures::{Leaf, Tolerance};
            let simplex = Simplex::new(m, n);
            let zero = |c: usize| zero_mask & (1 << c) != 0;
            let coords: Vec<f64> = (0..simplex.len() * dim)
                .map(|i| if zero(i % dim) { 0.0 } else { values[i % values.len()] })
                .collect();
            let net = ControlNet::new(simplex, dim, coords);
            let f = Filter::new(&net);
            let exact_net = net.map(|x| exact_f64(*x).unwrap());
            let lam = &lam[..=m];
            let l: Vec<BigRational> = lam.iter().map(|x| exact_f64(*x).unwrap()).collect();
            let pe = ExactEvaluator::new(&exact_net).evaluate(&l, Algorithm::Casteljau);
            let s = crate::certify::bound::condition(&exact_net, &l);
            for p in [Precision::F64, Precision::F32] {
                // claimed: the rounded exact value on the other coordinates; on the zero ones 0,
                // −0, a few of the smallest subnormals of the precision, or a normal number
                let tiny = match p { Precision::F64 => f64::from_bits(1), Precision::F32 => f64::from(f32::from_bits(1)) };
                let ys: Vec<f64> = (0..dim).map(|c| {
                    if zero(c) {
                        let (kind, k) = zero_claims[c];
                        match kind {
                            0 | 1 => 0.0,
                            2 => -0.0,
                            3 => f64::from(k) * tiny,
                            4 => -f64::from(k + 1) * tiny,
                            _ => f64::from(k + 1) * 1e-3,
                        }
                    } else {
                        match p {
                            Precision::F64 => round_f64(&pe[c]),
                            Precision::F32 => f64::from(crate::number::round_f32(&pe[c])),
                        }
                    }
                }).collect();
                if ys.iter().any(|y| !y.is_finite()) {
                    continue;
                }
                for t in ["exact", "ulps=1", "ulps=2", "ulps=1/2", "abs=1e-300", "rel=1e-12", "correctly_rounded", "faithful", "cond", "cond=64", "bound"] {
                    let tol = Tolerance::parse(t).unwrap();
                    let th = Thresholds::new(&tol, p, Algorithm::Casteljau, m, n);
                    let leaf = |c: usize| Leaf {
                        precision: Some(p),
                        condition: Some(s[c].clone()),
                        bound: crate::certify::bound::a_priori(Algorithm::Casteljau, p, m, n, &s[c], &l),
                    };
                    let tol_k = tol.for_patch(m, n);
                    let truth_c = |c: usize| tol_k.accepts(&exact_f64(ys[c]).unwrap(), &pe[c], &leaf(c)).unwrap();
                    let truth = (0..dim).all(truth_c);
                    let mut sc = Scratch::default();
                    let mut enc = vec![Enclosure::default(); dim];
                    let r = f.judge(&th, lam, &ys, &mut sc, &mut enc);
                    match r.decision {
                        Decision::Pass => proptest::prop_assert!(truth, "{} {:?} {:?}", t, p, ys),
                        Decision::Fail => proptest::prop_assert!(!truth, "{} {:?} {:?}", t, p, ys),
                        Decision::Undecided => {}
                    }
                    let sabs: f64 = lam.iter().map(|x| x.abs()).sum();
                    for c in (0..dim).filter(|c| zero(*c)) {
                        proptest::prop_assert!(pe[c] == BigRational::from_integer(0.into()));
                        for stage in 0..2 {
                            if stage == 0 { f.evaluate(lam, &mut sc, &mut enc) } else { f.evaluate_compensated(lam, &mut sc, &mut enc) }
                            proptest::prop_assert!(enc[c].is_exact_zero());
                            let d = th.decide(ys[c], &enc[c], sabs);
                            match d {
                                Decision::Pass => proptest::prop_assert!(truth_c(c), "{} {:?} {}", t, p, ys[c]),
                                Decision::Fail => proptest::prop_assert!(!truth_c(c), "{} {:?} {}", t, p, ys[c]),
                                Decision::Undecided => {}
                            }
                            // decided without big integers: a claimed zero always, any claim
                            // against a zero threshold, and ulps (|y| is k ulps of 0, k an
                            // integer, and N a float: compared exactly, even at k = N)
                            if ys[c] == 0.0 || !matches!(t, "bound" | "abs=1e-300") {
                                proptest::prop_assert!(d != Decision::Undecided, "{} {:?} {}", t, p, ys[c]);
                            }
                            // the ULP figures are exact: |y| / ulp(0)
                            if p == Precision::F64 {
                                let u = crate::number::ulps_error_f64(&exact_f64(ys[c]).unwrap(), &pe[c]);
                                let max = BigRational::from_float(f64::MAX).unwrap();
                                let (lo, hi) = (th.ulps_lower(ys[c], &enc[c]), th.ulps_upper(ys[c], &enc[c]));
                                if hi.is_finite() {
                                    proptest::prop_assert_eq!(BigRational::from_float(hi).unwrap(), u.clone());
                                    proptest::prop_assert_eq!(BigRational::from_float(lo).unwrap(), u);
                                } else {
                                    // |y| / ulp(0) beyond the largest float
                                    proptest::prop_assert!(u > max && lo == f64::MAX);
                                }
                            }
                        }
                    }
                }
            }
        }

        /// Cartesian rows (docs/theory.md §14.5): on random domain simplices, many of them
        /// nearly degenerate (a vertex within 2^-40·t of the opposite face, far away, or huge),
        /// the float conversion's radii contain the exact barycentric coordinates (around `λ̂` and
        /// around the double-double `λ̂ + lo`), the enclosures of both the widened stage alone and
        /// the double-double one first contain the exact value and condition number at them,
        /// and every decision of the filter agrees with the exact judgement (the generic exact
        /// path).
        #[test]
        fn cartesian_rows_are_enclosed_and_judged_soundly(
            m in 1usize..=3,
            n in 1usize..=4,
            dim in 1usize..=3,
            values in proptest::collection::vec(scaled(), 60),
            verts in proptest::collection::vec(-4.0f64..4.0, 12),
            squash in 0u8..4,
            x01 in proptest::collection::vec(-0.2f64..1.2, 3),
            steps in proptest::collection::vec(-2i32..=2, 3),
        ) {
            use crate::certify::measures::{Leaf, Tolerance};
            use crate::domain::Domain;
            use cartesian::{CartesianMap, CartesianPoint};
            // the vertices: random, then (squash) the last one pushed towards the opposite face,
            // or scaled up
            let mut v: Vec<Vec<f64>> = (0..=m).map(|k| verts[k * m..(k + 1) * m].to_vec()).collect();
            match squash {
                1 => {
                    // last vertex = mean of the others + 2^-40 · a random offset
                    for j in 0..m {
                        let mean = v[..m].iter().map(|p| p[j]).sum::<f64>() / m as f64;
                        v[m][j] = mean + v[m][j] * 2f64.powi(-40);
                    }
                }
                2 => v.iter_mut().for_each(|p| p.iter_mut().for_each(|c| *c *= 1e6)),
                3 => v.iter_mut().for_each(|p| p.iter_mut().for_each(|c| *c = *c / 3.0 + 1e3)),
                _ => {}
            }
            let vq: Vec<Vec<BigRational>> = v.iter().map(|p| p.iter().map(|c| exact_f64(*c).unwrap()).collect()).collect();
            let Ok(domain) = Domain::new(vq) else { return Ok(()); };
            let Some(map) = CartesianMap::new(&domain) else { return Ok(()); };
            // a float point: an affine combination of the vertices, computed in floats
            let w: Vec<f64> = {
                let mut w: Vec<f64> = x01[..m].to_vec();
                let rest = 1.0 - w.iter().sum::<f64>();
                w.insert(0, rest);
                w
            };
            let x: Vec<f64> = (0..m).map(|j| (0..=m).map(|k| w[k] * v[k][j]).sum()).collect();
            let xq: Vec<BigRational> = x.iter().map(|c| exact_f64(*c).unwrap()).collect();
            let lam = domain.barycentric(&xq).unwrap();
            let mut point = CartesianPoint::default();
            proptest::prop_assert!(map.barycentric(&x, &mut point));
            let (lh, d) = (point.hi.clone(), point.radius.clone());
            for k in 0..=m {
                let err = (exact_f64(lh[k]).unwrap() - &lam[k]).abs();
                proptest::prop_assert!(err <= exact_f64(d[k]).unwrap(), "k={} {} > {}", k, err, d[k]);
                let fine = (exact_f64(lh[k]).unwrap() + exact_f64(point.lo[k]).unwrap() - &lam[k]).abs();
                proptest::prop_assert!(fine <= exact_f64(point.fine[k]).unwrap(), "k={} {} > {}", k, fine, point.fine[k]);
            }
            let simplex = Simplex::new(m, n);
            let coords: Vec<f64> = (0..simplex.len() * dim).map(|i| values[i % values.len()]).collect();
            let net = ControlNet::new(simplex, dim, coords);
            let f = Filter::new(&net);
            let exact_net = net.map(|x| exact_f64(*x).unwrap());
            let pe = ExactEvaluator::new(&exact_net).evaluate(&lam, Algorithm::Casteljau);
            let s = crate::certify::bound::condition(&exact_net, &lam);
            let ys: Vec<f64> = (0..dim).map(|c| {
                let mut y = round_f64(&pe[c]);
                for _ in 0..steps[c].abs() {
                    y = if steps[c] > 0 { y.next_up() } else { y.next_down() };
                }
                y
            }).collect();
            if ys.iter().any(|y| !y.is_finite()) {
                return Ok(());
            }
            let mut sc = Scratch::default();
            let mut enc = vec![Enclosure::default(); dim];
            // the lean widening pass computes the generic code's numbers
            let outer: Vec<f64> = lh.iter().map(|x| x.abs()).collect();
            let (mut wl, mut wg) = (vec![Enclosure::default(); dim], vec![Enclosure::default(); dim]);
            f.widening(&outer, &d, &mut sc, &mut wl);
            f.widening_generic(&outer, &d, &mut sc, &mut wg);
            for (x, y) in wl.iter().zip(&wg) {
                proptest::prop_assert!(x.mu.to_bits() == y.mu.to_bits() && x.s_hi.to_bits() == y.s_hi.to_bits(), "{:?} {:?}", x, y);
            }
            for t in ["exact", "ulps=1", "ulps=4", "ulps=64", "abs=1e-12", "rel=1e-12", "correctly_rounded", "faithful", "cond", "cond=2", "bound"] {
                let tol = Tolerance::parse(t).unwrap().for_patch(m, n);
                let p = Precision::F64;
                let th = Thresholds::new(&tol, p, Algorithm::Casteljau, m, n);
                let truth = (0..dim).all(|c| {
                    let leaf = Leaf {
                        precision: Some(p),
                        condition: Some(s[c].clone()),
                        bound: crate::certify::bound::a_priori(Algorithm::Casteljau, p, m, n, &s[c], &lam),
                    };
                    tol.accepts(&exact_f64(ys[c]).unwrap(), &pe[c], &leaf).unwrap()
                });
                for dd in [false, true] {
                let r = if dd {
                    f.judge_cartesian(&th, &point, &ys, &mut sc, &mut enc)
                } else {
                    f.judge_tight_uncertain(&th, &lh, &d, &ys, &mut sc, &mut enc)
                };
                // the deciding enclosures hold at the exact point
                for c in 0..dim {
                    let e = &enc[c];
                    if e.mu.is_finite() && e.value.is_finite() && e.corr.is_finite() {
                        let err = (exact_f64(e.value).unwrap() + exact_f64(e.corr).unwrap() - &pe[c]).abs();
                        proptest::prop_assert!(err <= exact_f64(e.mu).unwrap(), "{} c={}", t, c);
                        if e.s_hi.is_finite() {
                            proptest::prop_assert!(exact_f64(e.s_lo).unwrap() <= s[c] && s[c] <= exact_f64(e.s_hi).unwrap(), "{} c={} cond", t, c);
                        }
                    }
                }
                match r.decision {
                    Decision::Pass => proptest::prop_assert!(truth, "{} {:?} {:?}", t, x, ys),
                    Decision::Fail => proptest::prop_assert!(!truth, "{} {:?} {:?}", t, x, ys),
                    Decision::Undecided => {}
                }
                if r.ulps.is_finite() {
                    let e_max = (0..dim).map(|c| crate::number::ulps_error_f64(&exact_f64(ys[c]).unwrap(), &pe[c])).max().unwrap();
                    proptest::prop_assert!(e_max <= BigRational::from_float(r.ulps).unwrap());
                    proptest::prop_assert!(BigRational::from_float(r.ulps_lower).unwrap() <= e_max);
                }
                }
            }
        }
    }
}
