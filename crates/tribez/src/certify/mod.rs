//! Certification: how far a claimed floating-point value is from the exact one, whether that is
//! acceptable, and the proven error bounds of tribez's own float algorithms.
//!
//! This module belongs to the core: it depends only on the exact engine and the float types,
//! never on files or the command line (the claim files in [`crate::claims`] and the commands
//! use it).
//!
//! * [`measures`]: tolerances (`exact`, `ulps=N`, `abs=E`, `rel=E`, `correctly_rounded`,
//!   `faithful`, `cond=K`, `bound`) and the exact error measures (absolute, relative, ULPs,
//!   correct rounding).
//! * [`bound`]: the a-priori forward error bounds of de Casteljau and of the direct Bernstein form
//!   (docs/theory.md §14.1), and the condition number `Σ|c_i| B_i(|λ|)`.
//! * [`filter`]: the floating-point filter: an f64 de Casteljau with a rigorous running error
//!   bound (docs/theory.md §14.2) that decides the clear claims without big integers.

pub mod beyond;
pub mod bound;
pub mod filter;
pub mod measures;
pub mod sample;

use num_rational::BigRational;

use crate::exact::{Algorithm, ExactEvaluator};
use crate::float::{Float, Precision};
use crate::patch::ControlNet;
use filter::{Decision, Enclosure, Filter, Scratch, Thresholds};
use measures::{Leaf, Tolerance};

/// A patch prepared for certifying a float algorithm in precision `F`: its control points rounded
/// to `F` (what the float code sees), exactly and as an f64 filter.
pub struct Certifier<F: Float> {
    /// The rounded net.
    pub net: ControlNet<F>,
    /// Its exact values.
    pub exact_net: ControlNet<BigRational>,
    /// Exact evaluator of the rounded net (homogeneous form).
    pub exact: ExactEvaluator,
    filter: Filter,
    thresholds: [Thresholds; 2],
}

/// One float evaluation judged against its a-priori bound.
#[derive(Clone, Debug, PartialEq)]
pub struct BoundCheck {
    /// Every coordinate's error is within the bound.
    pub within: bool,
    /// The filter could not decide and exact arithmetic was used.
    pub fell_back: bool,
    /// The case lies outside the bound's hypotheses (overflow; underflow for the Bernstein form).
    pub outside_hypothesis: bool,
}

impl<F: Float> Certifier<F> {
    /// Prepare `net` (exact) for precision `F`.
    pub fn new(net: &ControlNet<BigRational>) -> Self {
        let fnet: ControlNet<F> = crate::float::net_to(net);
        let exact_net = fnet.map(|x| x.exact().unwrap_or_default());
        let (m, n) = (net.m(), net.degree());
        Certifier {
            filter: Filter::new(&fnet.map(|x| x.widen())),
            exact: ExactEvaluator::new(&exact_net),
            thresholds: [Algorithm::Casteljau, Algorithm::Bernstein]
                .map(|a| Thresholds::new(&Tolerance::Bound, F::PRECISION, a, m, n)),
            net: fnet,
            exact_net,
        }
    }

    /// Run `algorithm` in `F` at `lambda` (floats) and check its result against the a-priori
    /// bound ([`bound::a_priori`]): by the float filter when it decides, else exactly.
    pub fn check(
        &self,
        algorithm: Algorithm,
        lambda: &[F],
        scratch: &mut (Scratch, Vec<Enclosure>),
    ) -> (Vec<F>, BoundCheck) {
        let y = run::<F>(algorithm, &self.net, lambda);
        let outside = y.iter().any(|v| !v.finite())
            || (algorithm == Algorithm::Bernstein && bernstein_may_underflow(&self.net, lambda));
        if outside {
            return (
                y,
                BoundCheck {
                    within: true,
                    fell_back: false,
                    outside_hypothesis: true,
                },
            );
        }
        let lam64: Vec<f64> = lambda.iter().map(|x| x.widen()).collect();
        let (sc, enc) = scratch;
        enc.resize(self.filter.dim(), Enclosure::default());
        self.filter.evaluate(&lam64, sc, enc);
        let th = &self.thresholds[usize::from(algorithm == Algorithm::Bernstein)];
        let s: f64 = lam64.iter().map(|x| x.abs()).sum();
        let mut decisions: Vec<Decision> = y
            .iter()
            .zip(enc.iter())
            .map(|(v, e)| th.decide(v.widen(), e, s))
            .collect();
        if !decisions.iter().all(|d| *d == Decision::Pass) {
            self.filter.evaluate_compensated(&lam64, sc, enc);
            decisions = y
                .iter()
                .zip(enc.iter())
                .map(|(v, e)| th.decide(v.widen(), e, s))
                .collect();
        }
        if decisions.iter().all(|d| *d == Decision::Pass) {
            return (
                y,
                BoundCheck {
                    within: true,
                    fell_back: false,
                    outside_hypothesis: false,
                },
            );
        }
        let within = self.exact_within(algorithm, lambda, &y);
        (
            y,
            BoundCheck {
                within,
                fell_back: true,
                outside_hypothesis: false,
            },
        )
    }

    /// At the float inputs `lambda` (the control points as rounded): the exact value `P(λ)`,
    /// the condition numbers `Σ|c_i| B_i(|λ|)` and the a-priori bound of `algorithm` per
    /// coordinate ([`bound::a_priori`]; `None` where `Kε ≥ 1`).
    pub fn seen(
        &self,
        algorithm: Algorithm,
        lambda: &[F],
    ) -> (Vec<BigRational>, Vec<BigRational>, Option<Vec<BigRational>>) {
        let lam: Vec<BigRational> = lambda
            .iter()
            .map(|x| x.exact().unwrap_or_default())
            .collect();
        self.seen_exact(algorithm, &lam)
    }

    /// [`Certifier::seen`] at exact inputs `lam`, which need not be floats: the exact
    /// barycentric coordinates of a float Cartesian point (docs/guide.md §7), where the a-priori
    /// bound is that of the algorithm run at those coordinates.
    pub fn seen_exact(
        &self,
        algorithm: Algorithm,
        lam: &[BigRational],
    ) -> (Vec<BigRational>, Vec<BigRational>, Option<Vec<BigRational>>) {
        let p = self.exact.evaluate_fast(lam);
        let cond = bound::condition(&self.exact_net, lam);
        let (m, n) = (self.net.m(), self.net.degree());
        let bounds = cond
            .iter()
            .map(|s| bound::a_priori(algorithm, F::PRECISION, m, n, s, lam))
            .collect();
        (p, cond, bounds)
    }

    /// The exact check: `|y_c − P_c(λ)| ≤ bound_c` for every coordinate.
    pub fn exact_within(&self, algorithm: Algorithm, lambda: &[F], y: &[F]) -> bool {
        let (p, cond, bounds) = self.seen(algorithm, lambda);
        y.iter().enumerate().all(|(c, v)| {
            let leaf = Leaf {
                precision: Some(F::PRECISION),
                condition: Some(cond[c].clone()),
                bound: bounds.as_ref().map(|b| b[c].clone()),
            };
            v.exact()
                .is_some_and(|yq| Tolerance::Bound.accepts(&yq, &p[c], &leaf).unwrap_or(false))
        })
    }
}

/// tribez's float evaluation by `algorithm` ([`crate::casteljau::evaluate`] or
/// [`crate::bernstein::evaluate`], the generic code).
pub fn run<F: Float>(algorithm: Algorithm, net: &ControlNet<F>, lambda: &[F]) -> Vec<F> {
    match algorithm {
        Algorithm::Casteljau => crate::casteljau::evaluate(net, lambda),
        Algorithm::Bernstein => crate::bernstein::evaluate(net, lambda),
    }
}

/// Could a product chain of the Bernstein form come near the underflow threshold (outside the
/// hypothesis of its bound)? Checked on logarithms: every partial product
/// `C(n;α) Π_{k≤j} λ_k^{α_k}` and every term `|c_α| B_α` that is not exactly zero must stay above
/// `2^(emin + 2)`.
pub fn bernstein_may_underflow<F: Float>(net: &ControlNet<F>, lambda: &[F]) -> bool {
    let emin = match F::PRECISION {
        Precision::F64 => -1022.0,
        Precision::F32 => -126.0,
    };
    let logs: Vec<f64> = lambda.iter().map(|x| x.widen().abs().log2()).collect();
    for (alpha, point) in net.entries() {
        if alpha
            .iter()
            .zip(&logs)
            .any(|(&a, l)| a > 0 && *l == f64::NEG_INFINITY)
        {
            continue; // the term is exactly zero
        }
        let mut acc = crate::number::round_f64(&BigRational::from_integer(
            crate::simplex::multinomial(alpha).into(),
        ))
        .log2();
        for (&a, l) in alpha.iter().zip(&logs) {
            acc += f64::from(a) * l;
            if acc < emin + 2.0 {
                return true;
            }
        }
        for c in point {
            let lc = c.widen().abs().log2();
            if lc != f64::NEG_INFINITY && acc + lc < emin + 2.0 {
                return true;
            }
        }
    }
    false
}
