//! Rational Bézier simplices: a polynomial patch divided by another (docs/theory.md §10).
//!
//! With weights `w_α` and points `c_α ∈ ℚ^d`:
//!
//! `p(λ) = Σ_α w_α c_α B^n_α(λ) / Σ_α w_α B^n_α(λ)`.
//!
//! The **homogeneous net** has the points `(w_α c_α, w_α) ∈ ℚ^{d+1}` (weight last). Every
//! polynomial algorithm (de Casteljau, blossom, subdivision, elevation) runs on it unchanged;
//! dividing by the last coordinate at the very end gives the rational patch. Exact evaluation
//! here is done two ways that must agree exactly:
//!
//! * [`RationalPatch::evaluate`]: homogeneous de Casteljau (integer arithmetic, one division);
//! * [`RationalPatch::evaluate_ratio`]: the numerator `Σ w c B` and the denominator `Σ w B` as two
//!   separate polynomial patches, each by the direct Bernstein sum, then their quotient.
//!
//! **Weights.** Positive weights keep the denominator `> 0` on the closed simplex. Zero and
//! negative weights are accepted in files, but the denominator may then vanish: evaluating (or
//! differentiating) where it is zero is an error ([`CoreError::RationalUndefined`], exit status 2
//! on the command line) that names the point. A zero weight at a corner makes that corner a point at
//! infinity, so the patch is undefined there.
//!
//! ```
//! use tribez::hazmat::number::parse_rational as q;
//! use tribez::hazmat::patch::{ControlNet, BezierPatch};
//! use tribez::hazmat::rational::RationalPatch;
//! // the quarter circle as a rational quadratic curve: (1,0), (1,1), (0,1) with weights 1, 1, 2
//! let pts: Vec<Vec<_>> = [["1", "0"], ["1", "1"], ["0", "1"]].iter().map(|p| p.iter().map(|x| q(x).unwrap()).collect()).collect();
//! let r = RationalPatch::new(BezierPatch::new(ControlNet::from_points(1, 2, &pts)), ["1", "1", "2"].map(|w| q(w).unwrap()).to_vec());
//! let p = r.evaluate(&[q("1/2").unwrap(), q("1/2").unwrap()]).unwrap();
//! assert_eq!(p, [q("3/5").unwrap(), q("4/5").unwrap()]); // 9/25 + 16/25 = 1
//! ```

use num_rational::BigRational;
use num_traits::{One, Zero};

use crate::error::CoreError;
use crate::exact::{Algorithm, ExactEvaluator};
use crate::patch::{BezierPatch, ControlNet};
use crate::symbolic::{Polynomial, barycentric_form};
use crate::{casteljau, float::Float};

/// A rational Bézier simplex: the points (with domain and name) of [`BezierPatch`] and one weight per
/// control point, in the canonical order.
#[derive(Clone, Debug, PartialEq)]
pub struct RationalPatch {
    /// Points `c_α`, domain and name.
    pub patch: BezierPatch,
    /// Weights `w_α`, canonical order.
    pub weights: Vec<BigRational>,
}

fn undefined(lambda: &[BigRational]) -> CoreError {
    CoreError::RationalUndefined {
        at: lambda.to_vec(),
    }
}

impl RationalPatch {
    /// A rational patch; `weights` has one entry per control point.
    pub fn new(patch: BezierPatch, weights: Vec<BigRational>) -> Self {
        assert_eq!(
            weights.len(),
            patch.net.len(),
            "one weight per control point"
        );
        RationalPatch { patch, weights }
    }

    /// The homogeneous net `(w_α c_α, w_α)`, weight last (`d + 1` coordinates).
    pub fn homogeneous(&self) -> ControlNet<BigRational> {
        let net = &self.patch.net;
        let coords = net
            .points()
            .zip(&self.weights)
            .flat_map(|(p, w)| {
                p.iter()
                    .map(|x| x * w)
                    .chain(std::iter::once(w.clone()))
                    .collect::<Vec<_>>()
            })
            .collect();
        ControlNet::new(net.simplex().clone(), net.dim() + 1, coords)
    }

    /// Back from a homogeneous net (weight last): `c_α = X_α / w_α`. An error if some weight is
    /// zero (that control point is at infinity).
    pub fn from_homogeneous(
        net: &ControlNet<BigRational>,
        like: &BezierPatch,
    ) -> Result<Self, CoreError> {
        assert!(
            net.dim() >= 2,
            "a homogeneous net has at least 2 coordinates"
        );
        let d = net.dim() - 1;
        let mut points = Vec::with_capacity(net.len());
        let mut weights = Vec::with_capacity(net.len());
        for (alpha, p) in net.entries() {
            let w = &p[d];
            if w.is_zero() {
                return Err(CoreError::ZeroWeight {
                    index: alpha.to_vec(),
                });
            }
            points.push(p[..d].iter().map(|x| x / w).collect::<Vec<_>>());
            weights.push(w.clone());
        }
        let mut patch = like.clone();
        patch.net = ControlNet::from_points(net.m(), net.degree(), &points);
        Ok(RationalPatch { patch, weights })
    }

    /// The numerator patch `Σ w_α c_α B_α` (points `w_α c_α`).
    pub fn numerator(&self) -> ControlNet<BigRational> {
        let net = &self.patch.net;
        let coords = net
            .points()
            .zip(&self.weights)
            .flat_map(|(p, w)| p.iter().map(|x| x * w).collect::<Vec<_>>())
            .collect();
        ControlNet::new(net.simplex().clone(), net.dim(), coords)
    }

    /// The denominator patch `Σ w_α B_α` (a scalar net of the weights).
    pub fn denominator(&self) -> ControlNet<BigRational> {
        ControlNet::new(self.patch.net.simplex().clone(), 1, self.weights.clone())
    }

    /// `p(λ)` by homogeneous de Casteljau (integer arithmetic, one division at the end).
    /// `λ` need not sum to one (the rational map is homogeneous of degree 0).
    pub fn evaluate(&self, lambda: &[BigRational]) -> Result<Vec<BigRational>, CoreError> {
        let h = ExactEvaluator::new(&self.homogeneous()).evaluate(lambda, Algorithm::Casteljau);
        // invariant: the homogeneous net has d + 1 ≥ 2 coordinates (d ≥ 1 points plus the weight)
        let (w, x) = h.split_last().expect("d + 1 >= 2 coordinates");
        if w.is_zero() {
            return Err(undefined(lambda));
        }
        Ok(x.iter().map(|c| c / w).collect())
    }

    /// `p(λ)` as the quotient of two separately evaluated polynomial patches (Bernstein sums).
    pub fn evaluate_ratio(&self, lambda: &[BigRational]) -> Result<Vec<BigRational>, CoreError> {
        let den = ExactEvaluator::new(&self.denominator()).evaluate(lambda, Algorithm::Bernstein);
        if den[0].is_zero() {
            return Err(undefined(lambda));
        }
        let num = ExactEvaluator::new(&self.numerator()).evaluate(lambda, Algorithm::Bernstein);
        Ok(num.iter().map(|x| x / &den[0]).collect())
    }

    /// The directional derivative `D_d p(λ)` (`d` sums to zero), by the quotient rule on the
    /// homogeneous net: with `X = Σ w c B`, `W = Σ w B` and `D_d F(λ) = n · F[d, λ^{n−1}]`
    /// (the blossom with one argument `d`),
    ///
    /// `D_d p = (D_d X · W − X · D_d W) / W²`.
    pub fn derivative(
        &self,
        lambda: &[BigRational],
        direction: &[BigRational],
    ) -> Result<Vec<BigRational>, CoreError> {
        self.derivative_of_order(lambda, &[direction])
    }

    /// The mixed directional derivative `D_{d^{(1)}} ⋯ D_{d^{(r)}} p(λ)` of any order `r`
    /// (`r` may exceed the degree: a rational patch is not a polynomial).
    ///
    /// Leibniz's rule on `X = p · W`, over the subsets `S` of the directions, gives
    /// `D_S p = (D_S X − Σ_{T ⊊ S} D_T p · D_{S∖T} W) / W`, solved for growing `S` from
    /// `D_∅ p = X / W`. The homogeneous derivatives are blossoms:
    /// `D_S F(λ) = n!/(n−|S|)! · F[d^{(S)}, λ^{n−|S|}]`, zero when `|S| > n`. The work grows as
    /// `3^r`; orders above 12 are refused.
    pub fn derivative_of_order(
        &self,
        lambda: &[BigRational],
        directions: &[&[BigRational]],
    ) -> Result<Vec<BigRational>, CoreError> {
        const MAX_ORDER: usize = 12;
        let r = directions.len();
        if r > MAX_ORDER {
            return Err(CoreError::RationalOrder {
                order: r,
                limit: MAX_ORDER,
            });
        }
        let h = self.homogeneous();
        let n = h.degree();
        let dim = h.dim() - 1;
        // D_S (X, W) for every subset S (bit k: direction k).
        let hom: Vec<Vec<BigRational>> = (0..1usize << r)
            .map(|set| {
                let size = set.count_ones() as usize;
                if size > n {
                    return vec![BigRational::zero(); dim + 1];
                }
                let mut args: Vec<&[BigRational]> = (0..r)
                    .filter(|k| set >> k & 1 == 1)
                    .map(|k| directions[k])
                    .collect();
                args.extend(std::iter::repeat_n(lambda, n - size));
                let f =
                    BigRational::from_integer(crate::derivative::falling_factorial(n, size).into());
                casteljau::blossom(&h, &args)
                    .into_iter()
                    .map(|c| c * &f)
                    .collect()
            })
            .collect();
        let w = &hom[0][dim];
        if w.is_zero() {
            return Err(undefined(lambda));
        }
        let mut p: Vec<Vec<BigRational>> = vec![Vec::new(); 1 << r];
        // subsets in an order where every proper subset comes first (numerically smaller)
        for set in 0..1usize << r {
            let mut v: Vec<BigRational> = hom[set][..dim].to_vec();
            // proper subsets T of S: T = (t − 1) & S walking down from S
            let mut t = set;
            while t != 0 {
                t = (t - 1) & set;
                let dw = &hom[set & !t][dim];
                if !dw.is_zero() {
                    for (vc, pc) in v.iter_mut().zip(&p[t]) {
                        *vc -= pc * dw;
                    }
                }
            }
            p[set] = v.into_iter().map(|x| x / w).collect();
        }
        // invariant: `p` has one entry per subset of the directions (2^k ≥ 1 of them), the full set last
        Ok(p.pop().expect("the full set"))
    }

    /// The tangent frame at `λ` over `domain` (docs/theory.md §7 for the polynomial case): the
    /// point, the level-`(n−1)` de Casteljau points of the homogeneous net projected
    /// (`c_k = X_k / W_k`, through which the tangent plane passes), the partials by the quotient
    /// rule, and for triangles in `ℝ³` the normal `p_x × p_y` beside
    /// `(n²/D) · W_0 W_1 W_2 / W³ · (c_1 − c_0) × (c_2 − c_0)` (`W` the weight at `λ`, `W_k` those
    /// of the level-`(n−1)` points, `D = 2·signed area`): with `μ_k = λ_k W_k / W` the point is
    /// `Σ μ_k c_k`, `p_x = (n/W) Σ δ_k W_k (c_k − p)`, and `(c_k − p) × (c_l − p) = μ_m (c_1 − c_0) × (c_2 − c_0)`
    /// for `(k, l, m)` cyclic, which gives the product.
    pub fn tangent_frame(
        &self,
        domain: &crate::domain::Domain,
        lambda: &[BigRational],
    ) -> Result<crate::derivative::TangentFrame, CoreError> {
        let h = self.homogeneous();
        let n = h.degree();
        let hf = crate::derivative::tangent_frame(&h, domain, lambda)?;
        let dim = h.dim() - 1;
        // invariant: the tangent frame of the homogeneous net has its d + 1 ≥ 2 coordinates
        let (w, x) = hf.point.split_last().expect("d + 1 coordinates");
        if w.is_zero() {
            return Err(undefined(lambda));
        }
        let point: Vec<BigRational> = x.iter().map(|c| c / w).collect();
        let mut intermediate = Vec::with_capacity(hf.intermediate.len());
        for (k, c) in hf.intermediate.iter().enumerate() {
            // invariant: every intermediate point of the homogeneous net has d + 1 ≥ 2 coordinates
            let (wk, xk) = c.split_last().expect("d + 1 coordinates");
            if wk.is_zero() {
                return Err(CoreError::FrameAtInfinity {
                    level: n - 1,
                    point: k,
                    at: lambda.to_vec(),
                });
            }
            intermediate.push(xk.iter().map(|v| v / wk).collect::<Vec<_>>());
        }
        let w2 = w * w;
        let partials: Vec<Vec<BigRational>> = hf
            .partials
            .iter()
            .map(|d| {
                (0..dim)
                    .map(|c| (&d[c] * w - &x[c] * &d[dim]) / &w2)
                    .collect()
            })
            .collect();
        let scale = if domain.m() == 2 && dim == 3 {
            let weights: BigRational = hf.intermediate.iter().map(|c| c[dim].clone()).product();
            let nq = BigRational::from_integer(n.into());
            Some(&nq * &nq / domain.determinant() * weights / (&w2 * w))
        } else {
            None
        };
        Ok(crate::derivative::TangentFrame::assemble(
            point,
            intermediate,
            partials,
            scale,
        ))
    }

    /// The float path: the homogeneous net rounded to `F`, de Casteljau in `F` at the rounded
    /// `λ`, one division at the end (what a float implementation does).
    pub fn evaluate_float<F: Float + std::ops::Div<Output = F>>(&self, lambda: &[F]) -> Vec<F> {
        let h: ControlNet<F> = self.homogeneous().map(F::round);
        divide_last(&casteljau::evaluate(&h, lambda))
    }

    /// The homogeneous components `(X_1, …, X_d, W)` as polynomials in the barycentric
    /// variables.
    pub fn homogeneous_form(&self) -> Vec<Polynomial> {
        barycentric_form(&self.homogeneous())
    }

    /// The residual of an implicit equation `F(x_1, …, x_d) = 0` on the patch, cleared of
    /// denominators: `W^k · F(X/W)`, with `k` the degree of `F`, a polynomial in the barycentric
    /// variables. It is identically zero exactly when the whole patch lies on `F = 0`.
    pub fn implicit_residual(&self, f: &Polynomial) -> Polynomial {
        let comps = self.homogeneous_form();
        // invariant: the homogeneous form has d + 1 ≥ 2 components
        let (w, x) = comps.split_last().expect("d + 1 coordinates");
        homogenised_residual(f, x, w)
    }
}

/// The final step of the float path: `(X_1, …, X_d, W) ↦ (X_1/W, …, X_d/W)`, one division each.
pub fn divide_last<F: Float + std::ops::Div<Output = F>>(v: &[F]) -> Vec<F> {
    // invariant: the float path's homogeneous results have d + 1 ≥ 2 coordinates (every caller passes one)
    let (w, x) = v.split_last().expect("d + 1 coordinates");
    x.iter().map(|&c| c / *w).collect()
}

/// `W^k F(X/W)` for `F` of degree `k` in `X.len()` variables: each term `c X^e` becomes
/// `c X^e W^{k − |e|}`.
pub fn homogenised_residual(f: &Polynomial, x: &[Polynomial], w: &Polynomial) -> Polynomial {
    assert_eq!(
        f.nvars(),
        x.len(),
        "the implicit equation has one variable per coordinate"
    );
    let nv = w.nvars();
    let k = f.degree().unwrap_or(0);
    let mut out = Polynomial::zero(nv);
    for (e, c) in f.terms() {
        let mut term = Polynomial::constant(nv, c.clone());
        for (xi, &ei) in x.iter().zip(e) {
            term = term.mul(&xi.pow(ei));
        }
        let total: u32 = e.iter().sum();
        term = term.mul(&w.pow(k - total));
        out = out.add(&term);
    }
    out
}

impl RationalPatch {
    /// The rational blossom `b[u_1, …, u_n] = X[u_1, …, u_n] / W[u_1, …, u_n]`: the blossom of
    /// the homogeneous net `(w_α c_α, w_α)` (docs/theory.md §4: de Casteljau with argument `u_k` at
    /// level `k`), projected by its last coordinate. It is symmetric in its arguments, and on the
    /// diagonal `b[u, …, u] = p(u)`; with the corners as arguments it gives the control points,
    /// `b[e_0^{α_0}, …, e_m^{α_m}] = c_α`. Undefined (an error naming the arguments) where the
    /// weight blossom `W[u_1, …, u_n]` is 0.
    ///
    /// ```
    /// use tribez::hazmat::number::parse_rational as q;
    /// use tribez::hazmat::patch::{ControlNet, BezierPatch};
    /// use tribez::hazmat::rational::RationalPatch;
    /// let v = |t: &[&str]| t.iter().map(|x| q(x).unwrap()).collect::<Vec<_>>();
    /// // the quarter circle (1,0), (1,1), (0,1), weights 1, 1, 2 (as in the module example)
    /// let pts = vec![v(&["1", "0"]), v(&["1", "1"]), v(&["0", "1"])];
    /// let r = RationalPatch::new(BezierPatch::new(ControlNet::from_points(1, 2, &pts)), v(&["1", "1", "2"]));
    /// let h = v(&["1/2", "1/2"]);
    /// assert_eq!(r.blossom(&[h.clone(), h]).unwrap(), v(&["3/5", "4/5"])); // the diagonal: p(1/2, 1/2)
    /// // b[e_0, e_1] = X_1 / W_1 = c_1
    /// assert_eq!(r.blossom(&[v(&["1", "0"]), v(&["0", "1"])]).unwrap(), v(&["1", "1"]));
    /// // W[u, v] = u_0 v_0 + (u_0 v_1 + u_1 v_0) + 2 u_1 v_1 = 1 + v_1 - 1 = 0 at u = (0, 1), v = (2, -1)
    /// assert!(r.blossom(&[v(&["0", "1"]), v(&["2", "-1"])]).is_err());
    /// ```
    pub fn blossom(&self, args: &[Vec<BigRational>]) -> Result<Vec<BigRational>, CoreError> {
        let h = crate::blossom::blossom(&self.homogeneous(), args)?;
        // invariant: the blossom of the homogeneous net has d + 1 ≥ 2 coordinates
        let (w, x) = h.split_last().expect("d + 1 >= 2 coordinates");
        if w.is_zero() {
            return Err(CoreError::BlossomUndefined {
                args: args.to_vec(),
            });
        }
        Ok(x.iter().map(|c| c / w).collect())
    }
}

impl RationalPatch {
    /// All weights equal to one: the polynomial patch.
    pub fn polynomial(patch: BezierPatch) -> Self {
        let n = patch.net.len();
        RationalPatch {
            patch,
            weights: vec![BigRational::one(); n],
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::any_patch::AnyPatch;
    use crate::number::parse_rational as q;
    use num_traits::One;
    use proptest::prelude::*;

    /// docs/theory.md §10: the quartic octant, weights ×6 and points in canonical order.
    pub(crate) fn octant() -> RationalPatch {
        let w = [
            "12", "12", "16", "24", "48", "9", "8", "10", "18", "7", "6", "9", "6", "6", "6",
        ];
        let c = [
            ["1", "0", "0"],
            ["1", "1/2", "0"],
            ["3/4", "3/4", "0"],
            ["1/2", "1", "0"],
            ["0", "1", "0"],
            ["1", "0", "1/3"],
            ["1", "5/8", "1/2"],
            ["3/5", "1", "3/5"],
            ["0", "1", "1/3"],
            ["6/7", "0", "5/7"],
            ["2/3", "2/3", "1"],
            ["0", "8/9", "7/9"],
            ["1/2", "0", "1"],
            ["0", "1/2", "1"],
            ["0", "0", "1"],
        ];
        let pts: Vec<Vec<BigRational>> = c
            .iter()
            .map(|p| p.iter().map(|x| q(x).unwrap()).collect())
            .collect();
        RationalPatch::new(
            BezierPatch::new(ControlNet::from_points(2, 4, &pts)),
            w.iter().map(|x| q(x).unwrap()).collect(),
        )
    }

    fn r(xs: &[&str]) -> Vec<BigRational> {
        xs.iter().map(|x| q(x).unwrap()).collect()
    }

    /// The constructions of [`crate::capability::Constructions`], back to rational patches.
    trait Rational {
        fn elevate(&self, r: usize) -> Result<RationalPatch, CoreError>;
        fn subpatch(&self, f: &[Vec<BigRational>]) -> Result<RationalPatch, CoreError>;
        fn split_at(&self, t: &[BigRational]) -> Result<Vec<RationalPatch>, CoreError>;
    }

    fn rational(a: AnyPatch) -> RationalPatch {
        match a {
            AnyPatch::Rational(r) => r,
            other => panic!("a rational construction gave {}", other.described()),
        }
    }

    impl Rational for RationalPatch {
        fn elevate(&self, r: usize) -> Result<RationalPatch, CoreError> {
            crate::capability::Constructions::elevate(self, r).map(rational)
        }
        fn subpatch(&self, f: &[Vec<BigRational>]) -> Result<RationalPatch, CoreError> {
            crate::capability::Constructions::subpatch(self, f).map(rational)
        }
        fn split_at(&self, t: &[BigRational]) -> Result<Vec<RationalPatch>, CoreError> {
            let pieces = crate::capability::Constructions::split_at(self, t)?;
            Ok(pieces.into_iter().map(rational).collect())
        }
    }

    #[test]
    fn octant_is_on_the_unit_sphere_identically() {
        let f = Polynomial::parse("x^2 + y^2 + z^2 - 1", &["x", "y", "z"]).unwrap();
        assert!(octant().implicit_residual(&f).is_zero());
        // and a plane through it is not: the residual of x + y + z - 1 is not identically 0
        let g = Polynomial::parse("x + y + z - 1", &["x", "y", "z"]).unwrap();
        assert!(!octant().implicit_residual(&g).is_zero());
    }

    #[test]
    fn octant_rational_point_theory_section_10() {
        let at = r(&["1/3", "1/4", "5/12"]);
        let want = r(&["1020/1681", "969/1681", "920/1681"]);
        assert_eq!(octant().evaluate(&at).unwrap(), want);
        assert_eq!(octant().evaluate_ratio(&at).unwrap(), want);
        // corners
        assert_eq!(
            octant().evaluate(&r(&["1", "0", "0"])).unwrap(),
            r(&["1", "0", "0"])
        );
        assert_eq!(
            octant().evaluate(&r(&["0", "0", "1"])).unwrap(),
            r(&["0", "0", "1"])
        );
    }

    #[test]
    fn zero_denominator_is_an_error_naming_the_point() {
        let mut p = octant();
        p.weights[0] = BigRational::zero();
        let e = p.evaluate(&r(&["1", "0", "0"])).unwrap_err().to_string();
        assert!(e.contains("undefined at (1, 0, 0)"), "{e}");
        assert!(p.evaluate_ratio(&r(&["1", "0", "0"])).is_err());
        assert!(
            p.derivative(&r(&["1", "0", "0"]), &r(&["-1", "1", "0"]))
                .is_err()
        );
        // elsewhere it is defined
        assert!(p.evaluate(&r(&["1/3", "1/3", "1/3"])).is_ok());
    }

    #[test]
    fn round_trip_through_the_homogeneous_net() {
        let p = octant();
        assert_eq!(
            RationalPatch::from_homogeneous(&p.homogeneous(), &p.patch).unwrap(),
            p
        );
    }

    #[test]
    fn derivative_is_tangent_to_the_sphere() {
        // p · D p = 0 on the unit sphere, exactly.
        let p = octant();
        let at = r(&["1/3", "1/4", "5/12"]);
        let x = p.evaluate(&at).unwrap();
        for d in [r(&["1", "-1", "0"]), r(&["0", "1", "-1"])] {
            let dp = p.derivative(&at, &d).unwrap();
            let dot: BigRational = x.iter().zip(&dp).map(|(a, b)| a * b).sum();
            assert!(dot.is_zero());
            assert!(dp.iter().any(|c| !c.is_zero()));
        }
    }

    #[test]
    fn derivative_of_a_quarter_circle_matches_the_formula() {
        // (1,0),(1,1),(0,1), weights 1,1,2 is ((1-t²), 2t)/(1+t²) with t = v... check D at t=0:
        // u=1, v=0: derivative along (-1, 1) is (0, 2).
        let pts: Vec<Vec<BigRational>> = [["1", "0"], ["1", "1"], ["0", "1"]]
            .iter()
            .map(|p| r(p))
            .collect();
        let rp = RationalPatch::new(
            BezierPatch::new(ControlNet::from_points(1, 2, &pts)),
            r(&["1", "1", "2"]),
        );
        assert_eq!(
            rp.derivative(&r(&["1", "0"]), &r(&["-1", "1"])).unwrap(),
            r(&["0", "2"])
        );
    }

    #[test]
    fn float_path_is_close() {
        let p = octant();
        let at = [1.0 / 3.0, 0.25, 5.0 / 12.0];
        let f = p.evaluate_float::<f64>(&at);
        let exact = p.evaluate(&r(&["1/3", "1/4", "5/12"])).unwrap();
        for (a, b) in f.iter().zip(&exact) {
            assert!((a - crate::number::round_f64(b)).abs() < 1e-14);
        }
    }

    /// Numbers a + b√2 with a, b rational: enough to run the generic de Casteljau on the
    /// quadratic "octant" candidate, whose edge weights are √2/2 (docs/theory.md §10).
    #[derive(Clone, Debug, PartialEq)]
    struct Q2(BigRational, BigRational);

    impl std::ops::Add for Q2 {
        type Output = Q2;
        fn add(self, o: Q2) -> Q2 {
            Q2(self.0 + o.0, self.1 + o.1)
        }
    }
    impl std::ops::Add<&Q2> for Q2 {
        type Output = Q2;
        fn add(self, o: &Q2) -> Q2 {
            self + o.clone()
        }
    }
    impl std::ops::Sub for Q2 {
        type Output = Q2;
        fn sub(self, o: Q2) -> Q2 {
            Q2(self.0 - o.0, self.1 - o.1)
        }
    }
    impl std::ops::Sub<&Q2> for Q2 {
        type Output = Q2;
        fn sub(self, o: &Q2) -> Q2 {
            self - o.clone()
        }
    }
    impl std::ops::Mul for Q2 {
        type Output = Q2;
        fn mul(self, o: Q2) -> Q2 {
            let two = BigRational::from_integer(2.into());
            Q2(
                &self.0 * &o.0 + two * &self.1 * &o.1,
                &self.0 * &o.1 + &self.1 * &o.0,
            )
        }
    }
    impl std::ops::Mul<&Q2> for Q2 {
        type Output = Q2;
        fn mul(self, o: &Q2) -> Q2 {
            self * o.clone()
        }
    }
    impl std::ops::Neg for Q2 {
        type Output = Q2;
        fn neg(self) -> Q2 {
            Q2(-self.0, -self.1)
        }
    }
    impl Zero for Q2 {
        fn zero() -> Q2 {
            Q2(BigRational::zero(), BigRational::zero())
        }
        fn is_zero(&self) -> bool {
            self.0.is_zero() && self.1.is_zero()
        }
    }
    impl One for Q2 {
        fn one() -> Q2 {
            Q2(BigRational::one(), BigRational::zero())
        }
    }
    impl crate::scalar::Scalar for Q2 {
        fn from_u64(k: u64) -> Q2 {
            Q2(BigRational::from_integer(k.into()), BigRational::zero())
        }
        fn from_biguint(k: &num_bigint::BigUint) -> Q2 {
            Q2(
                BigRational::from_integer(k.clone().into()),
                BigRational::zero(),
            )
        }
    }

    #[test]
    fn quadratic_candidate_misses_the_sphere() {
        // docs/theory.md §10/§15: the only quadratic candidate for the octant has corners e_x, e_y,
        // e_z (weight 1) and edge points (1,1,0), (0,1,1), (1,0,1) with weight √2/2. Run the
        // generic homogeneous de Casteljau in Q(√2).
        let rat = |t: &str| Q2(q(t).unwrap(), BigRational::zero());
        let half_sqrt2 = Q2(BigRational::zero(), q("1/2").unwrap());
        // canonical order 200, 110, 020, 101, 011, 002
        let points = [
            ["1", "0", "0"],
            ["1", "1", "0"],
            ["0", "1", "0"],
            ["1", "0", "1"],
            ["0", "1", "1"],
            ["0", "0", "1"],
        ];
        let weights = [
            rat("1"),
            half_sqrt2.clone(),
            rat("1"),
            half_sqrt2.clone(),
            half_sqrt2,
            rat("1"),
        ];
        let mut coords = Vec::new();
        for (p, w) in points.iter().zip(&weights) {
            coords.extend(p.iter().map(|x| rat(x) * w));
            coords.push(w.clone());
        }
        let net = ControlNet::new(crate::simplex::Simplex::new(2, 2), 4, coords);
        let norm_minus_w2 = |lam: &[&str]| {
            let lam: Vec<Q2> = lam.iter().map(|t| rat(t)).collect();
            let h = casteljau::evaluate(&net, &lam);
            h[0].clone() * &h[0] + h[1].clone() * &h[1] + h[2].clone() * &h[2]
                - h[3].clone() * &h[3]
        };
        // the edge midpoints are on the sphere (the boundary arcs are exact quarter circles) …
        assert!(norm_minus_w2(&["1/2", "1/2", "0"]).is_zero());
        assert!(norm_minus_w2(&["0", "1/2", "1/2"]).is_zero());
        // … the centroid is not: X·X − W² ≠ 0. With W = (3 + 3√2)/9 and X·X = 3(1 + 2√2)²/81,
        // |P|² = X·X / W² = 11/3 − 2√2 ≈ 0.838 (docs/theory.md §10).
        let c = norm_minus_w2(&["1/3", "1/3", "1/3"]);
        assert!(!c.is_zero());
        let lam: Vec<Q2> = ["1/3", "1/3", "1/3"].iter().map(|t| rat(t)).collect();
        let h = casteljau::evaluate(&net, &lam);
        let xx = h[0].clone() * &h[0] + h[1].clone() * &h[1] + h[2].clone() * &h[2];
        let w2 = h[3].clone() * &h[3];
        // xx = (11/3 − 2√2) · W², checked without division
        assert_eq!(xx, Q2(q("11/3").unwrap(), q("-2").unwrap()) * w2);
        assert_eq!(h[3], Q2(q("1/3").unwrap(), q("1/3").unwrap()));
    }

    #[test]
    fn elevation_and_subdivision_of_the_octant_stay_on_the_sphere() {
        let f = Polynomial::parse("x^2 + y^2 + z^2 - 1", &["x", "y", "z"]).unwrap();
        let p = octant();
        let up = p.elevate(2).unwrap();
        assert_eq!(up.patch.net.degree(), 6);
        assert!(up.implicit_residual(&f).is_zero());
        let at = r(&["1/3", "1/4", "5/12"]);
        assert_eq!(up.evaluate(&at).unwrap(), p.evaluate(&at).unwrap());
        // split at the centroid: piece s is the parent with vertex s replaced by t
        let t = r(&["1/3", "1/3", "1/3"]);
        let pieces = p.split_at(&t).unwrap();
        for (s, piece) in pieces.iter().enumerate() {
            assert!(piece.implicit_residual(&f).is_zero());
            assert!(piece.weights.iter().all(|w| w > &BigRational::zero()));
            // the piece's point (1/2, 1/4, 1/4) maps to Σ μ_k v_k in the parent
            let mu = r(&["1/2", "1/4", "1/4"]);
            let mut parent = vec![BigRational::zero(); 3];
            for (k, m) in mu.iter().enumerate() {
                let v: Vec<BigRational> = if k == s {
                    t.clone()
                } else {
                    (0..3)
                        .map(|i| {
                            if i == k {
                                BigRational::one()
                            } else {
                                BigRational::zero()
                            }
                        })
                        .collect()
                };
                for i in 0..3 {
                    parent[i] += m * &v[i];
                }
            }
            assert_eq!(piece.evaluate(&mu).unwrap(), p.evaluate(&parent).unwrap());
        }
        // a subpatch over [a1, midpoint(a1,a2), centroid]
        let f3 = vec![r(&["1", "0", "0"]), r(&["1/2", "1/2", "0"]), t.clone()];
        let sub = p.subpatch(&f3).unwrap();
        assert!(sub.implicit_residual(&f).is_zero());
        assert_eq!(
            sub.evaluate(&r(&["0", "0", "1"])).unwrap(),
            p.evaluate(&t).unwrap()
        );
    }

    #[test]
    fn a_zero_weight_after_elevation_is_an_error() {
        // weights 1, -1 on a linear curve: the elevated middle weight is (1 + -1)/2 = 0
        let pts: Vec<Vec<BigRational>> = [["0"], ["1"]].iter().map(|p| r(p)).collect();
        let rp = RationalPatch::new(
            BezierPatch::new(ControlNet::from_points(1, 1, &pts)),
            r(&["1", "-1"]),
        );
        let e = rp.elevate(1).unwrap_err().to_string();
        assert!(e.contains("weight 0"), "{e}");
    }

    #[test]
    fn derivatives_of_any_order() {
        // Constant weights: the rational patch is the polynomial one, derivatives of every order
        // agree, and vanish above the degree.
        let poly = crate::testing::finn();
        let r = RationalPatch::new(
            BezierPatch {
                name: None,
                net: poly.clone(),
                domain: None,
            },
            vec![BigRational::from_integer(5.into()); poly.len()],
        );
        let lam = crate::testing::r(&["1/2", "1/3", "1/6"]);
        let d = crate::testing::r(&["1", "0", "-1"]);
        let e = crate::testing::r(&["0", "1", "-1"]);
        for dirs in [vec![&d[..]], vec![&d[..], &e[..]]] {
            assert_eq!(
                r.derivative_of_order(&lam, &dirs).unwrap(),
                crate::derivative::directional_derivative(&poly, &dirs, &lam)
            );
        }
        assert!(
            r.derivative_of_order(&lam, &[&d, &e, &d])
                .unwrap()
                .iter()
                .all(Zero::is_zero)
        );
        // Elevation keeps the function, so every derivative (here of order 3 and 5, above the
        // octant's degree 4 too) is the same from the elevated net.
        let p = octant();
        let up = p.elevate(2).unwrap();
        let lam = crate::testing::r(&["1/3", "1/4", "5/12"]);
        let dirs: Vec<&[BigRational]> = vec![&d, &e, &d];
        assert_eq!(
            p.derivative_of_order(&lam, &dirs).unwrap(),
            up.derivative_of_order(&lam, &dirs).unwrap()
        );
        let five: Vec<&[BigRational]> = vec![&d, &e, &d, &e, &e];
        let v = p.derivative_of_order(&lam, &five).unwrap();
        assert!(v.iter().any(|x| !x.is_zero()));
        assert_eq!(v, up.derivative_of_order(&lam, &five).unwrap());
        assert!(p.derivative_of_order(&lam, &[&d[..]; 13]).is_err());
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(48))]
        #[test]
        fn homogeneous_casteljau_equals_the_ratio_and_is_reparametrisation_invariant(
            a in 0i64..50, b in 0i64..50, c in 1i64..50, rho in 1i64..7, sigma in 1i64..7,
        ) {
            let s = a + b + c;
            let lam = vec![BigRational::new(a.into(), s.into()), BigRational::new(b.into(), s.into()), BigRational::new(c.into(), s.into())];
            let p = octant();
            let x = p.evaluate(&lam).unwrap();
            prop_assert_eq!(&x, &p.evaluate_ratio(&lam).unwrap());
            // the point is on the sphere
            let norm: BigRational = x.iter().map(|t| t * t).sum();
            prop_assert!(norm.is_one());
            // ρ-reparametrisation (docs/theory.md §10): w_ijk ρ1^i ρ2^j ρ3^k, u_k ↦ ρ_k u_k / (ρ·u)
            let rho = [BigRational::from_integer(rho.into()), BigRational::from_integer(sigma.into()), BigRational::one()];
            let mut q2 = p.clone();
            for (w, alpha) in q2.weights.iter_mut().zip(p.patch.net.simplex().iter()) {
                for (k, &e) in alpha.iter().enumerate() {
                    *w = &*w * num_traits::pow(rho[k].clone(), e as usize);
                }
            }
            let mu: Vec<BigRational> = lam.iter().zip(&rho).map(|(l, r)| l / r).collect();
            prop_assert_eq!(q2.evaluate(&mu).unwrap(), x);
        }

        #[test]
        fn second_order_matches_the_closed_form_quotient_rule(
            a in 0i64..30, b in 0i64..30, c in 1i64..30,
            d0 in -5i64..6, d1 in -5i64..6, e0 in -5i64..6, e1 in -5i64..6,
        ) {
            // D_e D_d (X/W) = X_de/W − (X_d W_e + X_e W_d + X W_de)/W² + 2 X W_d W_e/W³,
            // from the polynomials of the homogeneous form (not Leibniz's recursion over subsets).
            let s = a + b + c;
            let lam = vec![BigRational::new(a.into(), s.into()), BigRational::new(b.into(), s.into()), BigRational::new(c.into(), s.into())];
            let dir = |x: i64, y: i64| vec![BigRational::from_integer(x.into()), BigRational::from_integer(y.into()), BigRational::from_integer((-x - y).into())];
            let (d, e) = (dir(d0, d1), dir(e0, e1));
            let p = octant();
            let h = p.homogeneous_form();
            let along = |f: &Polynomial, v: &[BigRational]| -> Polynomial {
                (0..3).fold(Polynomial::zero(3), |acc, k| acc.add(&f.derivative(k).scale(&v[k])))
            };
            let (w, x) = h.split_last().unwrap();
            let at = |f: &Polynomial| f.evaluate(&lam);
            let (wv, wd, we, wde) = (at(w), at(&along(w, &d)), at(&along(w, &e)), at(&along(&along(w, &d), &e)));
            let want: Vec<BigRational> = x
                .iter()
                .map(|xc| {
                    let (xv, xd, xe, xde) = (at(xc), at(&along(xc, &d)), at(&along(xc, &e)), at(&along(&along(xc, &d), &e)));
                    &xde / &wv - (&xd * &we + &xe * &wd + &xv * &wde) / (&wv * &wv)
                        + BigRational::from_integer(2.into()) * &xv * &wd * &we / (&wv * &wv * &wv)
                })
                .collect();
            prop_assert_eq!(p.derivative_of_order(&lam, &[&d, &e]).unwrap(), want);
        }

        #[test]
        fn rational_tangent_frame_is_consistent(
            a in 0i64..30, b in 0i64..30, c in 1i64..30,
        ) {
            // On the sphere the normal is radial; the projected intermediate points give the same
            // normal through (n²/D) W_0 W_1 W_2 / W³ (c_1 − c_0) × (c_2 − c_0); the partials are the
            // quotient-rule derivatives along the domain's axes.
            let s = a + b + c;
            let lam = vec![BigRational::new(a.into(), s.into()), BigRational::new(b.into(), s.into()), BigRational::new(c.into(), s.into())];
            let p = octant();
            let f = p.tangent_frame(&crate::domain::Domain::reference(2), &lam).unwrap();
            let nrm = f.normal.clone().unwrap();
            prop_assert_eq!(f.normal_from_intermediate.clone().unwrap(), nrm.clone());
            prop_assert!(crate::derivative::cross(&nrm, &f.point).iter().all(Zero::is_zero));
            prop_assert!(f.regular);
            let axis = |k: usize| { let mut v = vec![BigRational::zero(); 3]; v[k] = BigRational::one(); v[2] -= BigRational::one(); v };
            prop_assert_eq!(&f.partials[0], &p.derivative(&lam, &axis(0)).unwrap());
            prop_assert_eq!(&f.partials[1], &p.derivative(&lam, &axis(1)).unwrap());
        }

        #[test]
        fn quotient_rule_matches_the_symbolic_derivative(
            a in 0i64..30, b in 0i64..30, c in 1i64..30, d0 in -5i64..6, d1 in -5i64..6,
        ) {
            // D_d p = Σ_k d_k ∂(X/W)/∂λ_k, from the polynomials of the homogeneous form.
            let s = a + b + c;
            let lam = vec![BigRational::new(a.into(), s.into()), BigRational::new(b.into(), s.into()), BigRational::new(c.into(), s.into())];
            let d = vec![BigRational::from_integer(d0.into()), BigRational::from_integer(d1.into()), BigRational::from_integer((-d0 - d1).into())];
            let p = octant();
            let h = p.homogeneous_form();
            let (w, x) = h.split_last().unwrap();
            let wv = w.evaluate(&lam);
            let dw: BigRational = (0..3).map(|k| &d[k] * w.derivative(k).evaluate(&lam)).sum();
            let want: Vec<BigRational> = x
                .iter()
                .map(|xc| {
                    let dx: BigRational = (0..3).map(|k| &d[k] * xc.derivative(k).evaluate(&lam)).sum();
                    (dx * &wv - xc.evaluate(&lam) * &dw) / (&wv * &wv)
                })
                .collect();
            prop_assert_eq!(p.derivative(&lam, &d).unwrap(), want);
        }
    }
}
