//! Certifying the float paths of rational patches and S-patches.
//!
//! * [`RationalCertifier`]: homogeneous de Casteljau in float on the rounded homogeneous net and
//!   one division, judged against the exact quotient at the inputs as the code saw them and the
//!   proven bound [`bound::rational_a_posteriori`].
//! * [`SPatchCertifier`]: float Wachspress coordinates `λ̂` and float de Casteljau. The total
//!   error is measured exactly; only the de Casteljau part has a proven bound
//!   (`γ_K Σ|P_α| B_α(|λ̂|)` at the float coordinates `λ̂`, [`bound::a_priori`]). There is **no
//!   proven bound for the coordinate computation** here, so the total error is reported, not
//!   judged.

use std::ops::Div;

use num_rational::BigRational;
use num_traits::{Signed, Zero};

use super::bound;
use crate::casteljau;
use crate::error::CoreError;
use crate::exact::{Algorithm, ExactEvaluator};
use crate::float::Float;
use crate::patch::ControlNet;
use crate::rational::RationalPatch;
use crate::spatch::{Polygon, SPatch};

/// A rational patch prepared for certification in precision `F`.
pub struct RationalCertifier<F: Float> {
    /// The rounded homogeneous net `(RN(w_i c_i), RN(w_i))`, weight last.
    pub net: ControlNet<F>,
    /// Its exact values.
    pub exact_net: ControlNet<BigRational>,
    exact: ExactEvaluator,
}

/// One float evaluation of a rational patch, judged.
#[derive(Clone, Debug)]
pub struct RationalCase<F> {
    /// The float result `fl(N̂/D̂)` per coordinate.
    pub y: Vec<F>,
    /// The exact value `q = N/D` at the inputs as seen (`None` where `D = 0`).
    pub exact: Option<Vec<BigRational>>,
    /// The proven bound per coordinate (`None`: outside the hypothesis).
    pub bound: Option<Vec<BigRational>>,
    /// The condition numbers `κ_c` ([`bound::rational_condition`]).
    pub condition: Option<Vec<BigRational>>,
    /// Overflow, or `|D̂| ≤ e_D` (the sign of the denominator is not certain): not judged.
    pub outside: bool,
}

impl<F: Float + Div<Output = F>> RationalCertifier<F> {
    /// Round the homogeneous net of `r` to `F`; an overflowing entry is an error.
    pub fn new(r: &RationalPatch) -> Result<Self, CoreError> {
        let net: ControlNet<F> = r.homogeneous().map(F::round);
        if net.coords().iter().any(|x| !x.finite()) {
            return Err(CoreError::Overflows {
                what: "a weighted control point w·c or a weight",
                precision: F::PRECISION.name(),
            });
        }
        let exact_net = net.map(|x| x.exact().unwrap_or_default());
        Ok(RationalCertifier {
            exact: ExactEvaluator::new(&exact_net),
            net,
            exact_net,
        })
    }

    /// The exact quotient `N/D` of the rounded homogeneous net at the float inputs `lambda`
    /// (`None` where `D = 0` or an input is not finite).
    pub fn exact_at(&self, lambda: &[F]) -> Option<Vec<BigRational>> {
        let lam: Vec<BigRational> = lambda.iter().map(|x| x.exact()).collect::<Option<_>>()?;
        let h = self.exact.evaluate(&lam, Algorithm::Casteljau);
        // invariant: the homogeneous net has d + 1 ≥ 2 coordinates
        let (w, x) = h.split_last().expect("d + 1 coordinates");
        (!w.is_zero()).then(|| x.iter().map(|c| c / w).collect())
    }

    /// Evaluate in `F` at `lambda` (the code of [`RationalPatch::evaluate_float`]) and judge.
    pub fn check(&self, lambda: &[F]) -> RationalCase<F> {
        let v = casteljau::evaluate(&self.net, lambda);
        let y = crate::rational::divide_last(&v);
        let (m, n) = (self.net.m(), self.net.degree());
        let mut case = RationalCase {
            y,
            exact: None,
            bound: None,
            condition: None,
            outside: true,
        };
        if v.iter().chain(&case.y).any(|x| !x.finite()) {
            return case;
        }
        let lam: Vec<BigRational> = lambda
            .iter()
            .map(|x| x.exact().unwrap_or_default())
            .collect();
        let h = self.exact.evaluate(&lam, Algorithm::Casteljau);
        let cond = bound::condition(&self.exact_net, &lam);
        let errs: Option<Vec<BigRational>> = cond
            .iter()
            .map(|s| bound::a_priori(Algorithm::Casteljau, F::PRECISION, m, n, s, &lam))
            .collect();
        let Some(errs) = errs else { return case };
        // invariant: one bound per homogeneous coordinate, d + 1 ≥ 2 of them
        let (e_den, e_num) = errs.split_last().expect("d + 1 coordinates");
        // invariant: the homogeneous net has d + 1 ≥ 2 coordinates
        let (d, num) = h.split_last().expect("d + 1 coordinates");
        let d_hat = v.last().and_then(|x| x.exact()).unwrap_or_default();
        if d_hat.abs() <= *e_den {
            return case; // the denominator's sign is not certain
        }
        case.outside = false;
        if d.is_zero() {
            // impossible if §14.1 holds: |D̂ − 0| ≤ e_D < |D̂|; report it as a violation
            case.bound = Some(vec![BigRational::zero(); num.len()]);
            return case;
        }
        let q: Vec<BigRational> = num.iter().map(|x| x / d).collect();
        let y_hat: Vec<BigRational> = case
            .y
            .iter()
            .map(|x| x.exact().unwrap_or_default())
            .collect();
        case.bound = bound::rational_a_posteriori(F::PRECISION, e_num, e_den, &q, &d_hat, &y_hat);
        // invariant: one condition number per homogeneous coordinate, d + 1 ≥ 2 of them
        let (cd, cn) = cond.split_last().expect("d + 1 coordinates");
        case.condition = Some(
            cn.iter()
                .zip(&q)
                .map(|(cc, qc)| (cc + qc.abs() * cd) / d.abs())
                .collect(),
        );
        case.exact = Some(q);
        case
    }
}

/// The exact side of one float evaluation at the inputs as seen: exact value, condition numbers
/// and the a-priori bound per coordinate (`None` where undefined or outside the hypotheses).
pub type SeenParts = (
    Option<Vec<BigRational>>,
    Option<Vec<BigRational>>,
    Option<Vec<BigRational>>,
);

impl<F: Float + Div<Output = F>> RationalCertifier<F> {
    /// At the float inputs `lambda`: the exact quotient `q = N/D` of the rounded homogeneous net
    /// (`None` where `D = 0`), the condition numbers `κ_c` ([`bound::rational_condition`]) and
    /// the a-priori bound [`bound::rational_a_priori`] (`None` where `|D| ≤ e_D`), the bound a
    /// claim is judged against (it does not need the computed denominator).
    pub fn seen(&self, lambda: &[F]) -> SeenParts {
        let lam: Vec<BigRational> = lambda
            .iter()
            .map(|x| x.exact().unwrap_or_default())
            .collect();
        self.seen_exact(&lam)
    }

    /// [`RationalCertifier::seen`] at exact inputs `lam`, which need not be floats (the exact
    /// barycentric coordinates of a float Cartesian point).
    pub fn seen_exact(&self, lam: &[BigRational]) -> SeenParts {
        let h = self.exact.evaluate(lam, Algorithm::Casteljau);
        // invariant: the homogeneous net has d + 1 ≥ 2 coordinates
        let (d, num) = h.split_last().expect("d + 1 coordinates");
        if d.is_zero() {
            return (None, None, None);
        }
        let q: Vec<BigRational> = num.iter().map(|x| x / d).collect();
        let condition = bound::rational_condition(&self.exact_net, lam);
        let (m, n) = (self.net.m(), self.net.degree());
        let errs: Option<Vec<BigRational>> = bound::condition(&self.exact_net, lam)
            .iter()
            .map(|s| bound::a_priori(Algorithm::Casteljau, F::PRECISION, m, n, s, lam))
            .collect();
        let bounds = errs.and_then(|e| {
            let (e_den, e_num) = e.split_last()?;
            bound::rational_a_priori(F::PRECISION, e_num, e_den, &q, d)
        });
        (Some(q), condition, bounds)
    }
}

/// An S-patch prepared for certification in precision `F`: polygon and control points rounded.
pub struct SPatchCertifier<F: Float> {
    /// The S-patch with rounded vertices and control points (exact values of the floats).
    pub seen: SPatch,
    /// The rounded control net.
    pub net: ControlNet<F>,
    /// The rounded vertices.
    pub vertices: Vec<[F; 2]>,
    exact: ExactEvaluator,
}

/// One float evaluation of an S-patch, measured.
#[derive(Clone, Debug)]
pub struct SPatchCase<F> {
    /// The float result.
    pub y: Vec<F>,
    /// The float Wachspress coordinates `λ̂`.
    pub lambda: Vec<F>,
    /// The exact value `S(p̂)` of the rounded S-patch at the rounded point (`None`: the rounded
    /// point is outside the rounded polygon).
    pub exact: Option<Vec<BigRational>>,
    /// The exact Wachspress coordinates `λ(p̂)`.
    pub exact_lambda: Option<Vec<BigRational>>,
    /// The exact de Casteljau value `P(λ̂)` at the float coordinates.
    pub casteljau_exact: Vec<BigRational>,
    /// The proven bound of the de Casteljau part, `|ŷ − P(λ̂)|`, per coordinate.
    pub casteljau_bound: Option<Vec<BigRational>>,
    /// `Σ|P_α| B_α(|λ̂|)` per coordinate.
    pub condition: Vec<BigRational>,
    /// The proven relative bound `θ` of the float coordinates, `|λ̂_i − λ_i| ≤ θ λ_i`
    /// ([`bound::wachspress_relative`]; `None` outside its hypotheses: a point on or very near
    /// an edge, underflow).
    pub theta: Option<BigRational>,
    /// The proven bound of the total error `|ŷ − S(p̂)|` per coordinate: the de Casteljau part
    /// plus `((1 + θ)^n − 1)/(1 − θ)^n Σ|P_α| B_α(λ̂)` ([`bound::coordinate_factor`]).
    pub total_bound: Option<Vec<BigRational>>,
    /// Overflow or non-finite coordinates: not judged.
    pub outside: bool,
}

impl<F: Float + Div<Output = F>> SPatchCertifier<F> {
    /// Round `s` to `F`; a rounded polygon that is no longer strictly convex, or an overflow, is
    /// an error.
    pub fn new(s: &SPatch) -> Result<Self, CoreError> {
        let p = F::PRECISION.name();
        let vertices: Vec<[F; 2]> = s
            .polygon
            .vertices()
            .iter()
            .map(|v| [F::round(&v[0]), F::round(&v[1])])
            .collect();
        let net: ControlNet<F> = s.net.map(F::round);
        if net.coords().iter().any(|x| !x.finite())
            || vertices.iter().flatten().any(|x| !x.finite())
        {
            return Err(CoreError::Overflows {
                what: "a vertex or control point",
                precision: p,
            });
        }
        let polygon = Polygon::new(
            vertices
                .iter()
                .map(|v| v.iter().map(|x| x.exact().unwrap_or_default()).collect())
                .collect(),
        )
        .map_err(|e| CoreError::Rounded {
            what: "the polygon",
            precision: p,
            error: Box::new(e),
        })?;
        let exact_net = net.map(|x| x.exact().unwrap_or_default());
        Ok(SPatchCertifier {
            exact: ExactEvaluator::new(&exact_net),
            seen: SPatch::new(polygon, exact_net)?,
            net,
            vertices,
        })
    }

    /// At the float point `p`: the exact value `S(p̂)` of the rounded S-patch (`None` outside
    /// the rounded polygon), the condition numbers `Σ|P_α| B_α(λ(p̂))` at the exact Wachspress
    /// coordinates, and the proven bound of the whole float path
    /// ([`SPatchCase::total_bound`]).
    pub fn seen(&self, p: &[F; 2]) -> SeenParts {
        let point: Vec<BigRational> = p.iter().map(|x| x.exact().unwrap_or_default()).collect();
        let Ok((lambda, exact)) = self.seen.evaluate(&point) else {
            return (None, None, None);
        };
        let condition = bound::condition(&self.seen.net, &lambda);
        (Some(exact), Some(condition), self.check(p).total_bound)
    }

    /// Evaluate in `F` at the float point `p` (the code of [`SPatch::evaluate_float`]) and measure.
    pub fn check(&self, p: &[F; 2]) -> SPatchCase<F> {
        let lambda = crate::spatch::wachspress_float(&self.vertices, p);
        let y = casteljau::evaluate(&self.net, &lambda);
        let (m, n) = (self.net.m(), self.net.degree());
        let outside = lambda.iter().chain(&y).any(|x| !x.finite());
        let lam_q: Vec<BigRational> = lambda
            .iter()
            .map(|x| x.exact().unwrap_or_default())
            .collect();
        let casteljau_exact = self.exact.evaluate(&lam_q, Algorithm::Casteljau);
        let condition = bound::condition(&self.seen.net, &lam_q);
        let casteljau_bound: Option<Vec<BigRational>> = condition
            .iter()
            .map(|s| bound::a_priori(Algorithm::Casteljau, F::PRECISION, m, n, s, &lam_q))
            .collect();
        let point: Vec<BigRational> = p.iter().map(|x| x.exact().unwrap_or_default()).collect();
        let (exact_lambda, exact) = match self.seen.evaluate(&point) {
            Ok((l, v)) => (Some(l), Some(v)),
            Err(_) => (None, None),
        };
        let theta = bound::wachspress_relative(
            F::PRECISION,
            self.seen.polygon.vertices(),
            &[point[0].clone(), point[1].clone()],
        );
        let total_bound = match (&theta, &casteljau_bound) {
            (Some(t), Some(b)) => {
                let factor = bound::coordinate_factor(t, n);
                Some(
                    b.iter()
                        .zip(&condition)
                        .map(|(bc, kc)| bc + &factor * kc)
                        .collect(),
                )
            }
            _ => None,
        };
        SPatchCase {
            y,
            lambda,
            exact,
            exact_lambda,
            casteljau_exact,
            casteljau_bound,
            condition,
            theta,
            total_bound,
            outside,
        }
    }
}
