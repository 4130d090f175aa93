//! Rational Bézier simplices: `p(λ) = Σ w_α c_α B_α(λ) / Σ w_α B_α(λ)`.
//!
//! * exact: homogeneous de Casteljau on `(w_α c_α, w_α)` and one division
//!   ([`RationalPatch::evaluate`]); undefined where the denominator vanishes;
//! * float program: the homogeneous net rounded to `F`, de Casteljau in `F`, one division
//!   ([`RationalPatch::evaluate_float`]); de Casteljau only;
//! * bound: `(e_N + |q| e_D)/|D̂| + ε|ŷ|/(1−ε) + η` when certifying a run, its a-priori form for a
//!   claimed value (`crate::certify::bound`), via `RationalCertifier`.

use std::borrow::Cow;

use num_rational::BigRational;

use crate::capability::traits::SymbolicForm;

use crate::any_patch::AnyPatch;
use crate::capability::traits::check_len;
use crate::capability::traits::{
    BoundText, Constructions, ErrorBound, ExactEval, FloatCase, FloatEval, FloatProgram,
    InputSpace, Narrow, PointEvaluator, Seen, Shape, narrowed, round_input, with_net,
};
use crate::certify::beyond::RationalCertifier;
use crate::certify::bound::roundings;
use crate::error::CoreError;
use crate::exact::Algorithm;
use crate::float::Precision;
use crate::patch::ControlNet;
use crate::rational::RationalPatch;

/// The explanation of the rational bound in a certification report.
pub const RATIONAL_NOTE: &str = "bound (rational, homogeneous de Casteljau + one division): |fl(N̂/D̂) − q| ≤ (e_N + |q| e_D)/|D̂| + ε|fl(N̂/D̂)|/(1−ε) + η, e_N = γ_K Σ|w_i c_i| B_i(|λ|), e_D = γ_K Σ|w_i| B_i(|λ|), needs |D̂| > e_D; cond = (Σ|w c|B(|λ|) + |q| Σ|w|B(|λ|))/|D|, relcond = cond/|q|";

struct Exact<'a>(&'a RationalPatch);

impl PointEvaluator for Exact<'_> {
    fn evaluate(&self, input: &[BigRational]) -> Result<Vec<BigRational>, CoreError> {
        check_len(input, self.0.patch.net.m() + 1)?;
        self.0.evaluate(input)
    }
}

impl ExactEval for RationalPatch {
    fn shape(&self) -> Shape {
        let net = &self.patch.net;
        Shape {
            simplex_dim: net.m(),
            degree: net.degree(),
            dimension: net.dim(),
            input: InputSpace::Barycentric { m: net.m() },
        }
    }

    fn exact_evaluator(&self) -> Box<dyn PointEvaluator + '_> {
        Box::new(Exact(self))
    }

    fn cartesian_input(&self, x: &[BigRational]) -> Result<Vec<BigRational>, CoreError> {
        self.patch.domain_or_reference().barycentric(x)
    }

    /// The homogeneous form `(Σ w_α c_α B_α, Σ w_α B_α)`, in Cartesian variables composed with
    /// the barycentric coordinates of the domain.
    fn symbolic(&self, cartesian: bool) -> SymbolicForm {
        use crate::symbolic::{barycentric_names, barycentric_of_cartesian, cartesian_names};
        let m = self.patch.net.m();
        let mut h = self.homogeneous_form();
        let names = if cartesian {
            let subs = barycentric_of_cartesian(&self.patch.domain_or_reference());
            h = h.iter().map(|p| p.compose(&subs)).collect();
            cartesian_names(m)
        } else {
            barycentric_names(m)
        };
        let denominator = h.pop();
        SymbolicForm {
            names,
            components: h,
            denominator,
        }
    }
}

impl FloatEval for RationalPatch {
    fn float_algorithms(&self) -> &'static [Algorithm] {
        &[Algorithm::Casteljau]
    }

    fn algorithm_name(&self, _algorithm: Algorithm) -> &'static str {
        "homogeneous de Casteljau"
    }

    fn float_program(&self, precision: Precision) -> Result<Box<dyn FloatProgram + '_>, CoreError> {
        Ok(match precision {
            Precision::F64 => Box::new(Program::<f64>::new(self)?),
            Precision::F32 => Box::new(Program::<f32>::new(self)?),
        })
    }
}

struct Program<F: Narrow> {
    cert: RationalCertifier<F>,
}

impl<F: Narrow> Program<F> {
    fn new(r: &RationalPatch) -> Result<Self, CoreError> {
        Ok(Program {
            cert: RationalCertifier::new(r)?,
        })
    }
}

impl<F: Narrow> FloatProgram for Program<F> {
    fn precision(&self) -> Precision {
        F::PRECISION
    }

    fn round_input(&self, input: &[BigRational]) -> Result<Vec<f64>, CoreError> {
        check_len(input, self.cert.net.m() + 1)?;
        round_input::<F>(input)
    }

    fn run(&self, _algorithm: Algorithm, input: &[f64]) -> Vec<f64> {
        let v = crate::casteljau::evaluate(&self.cert.net, &narrowed::<F>(input));
        crate::rational::divide_last(&v)
            .iter()
            .map(|y| y.widen())
            .collect()
    }

    fn exact_seen(&self, input: &[f64]) -> Option<Vec<BigRational>> {
        self.cert.exact_at(&narrowed::<F>(input))
    }

    fn error_bound(&self) -> Option<&dyn ErrorBound> {
        Some(self)
    }
}

impl<F: Narrow> ErrorBound for Program<F> {
    fn seen(&self, _algorithm: Algorithm, input: &[f64]) -> Seen {
        let lam: Vec<F> = narrowed(input);
        let (exact, condition, bound) = self.cert.seen(&lam);
        Seen {
            input: lam.iter().map(|x| x.exact().unwrap_or_default()).collect(),
            exact,
            condition,
            bound,
            cond_tolerance: true,
        }
    }

    fn seen_exact(&self, _algorithm: Algorithm, input: &[BigRational]) -> Seen {
        let (exact, condition, bound) = self.cert.seen_exact(input);
        Seen {
            input: input.to_vec(),
            exact,
            condition,
            bound,
            cond_tolerance: true,
        }
    }

    fn certify(&self, _algorithm: Algorithm, input: &[f64]) -> FloatCase {
        let lam: Vec<F> = narrowed(input);
        let at: Vec<BigRational> = lam.iter().map(|x| x.exact().unwrap_or_default()).collect();
        let case = self.cert.check(&lam);
        let failure =
            (!case.outside && (case.exact.is_none() || case.bound.is_none())).then(|| {
                format!(
                    "at {}: the exact denominator vanishes although |D̂| > e_D",
                    crate::domain::format_tuple(&at)
                )
            });
        FloatCase {
            input: at,
            y: case.y.iter().map(|y| y.widen()).collect(),
            condition: case.exact.as_ref().and(case.condition),
            exact: case.exact,
            bound: case.bound,
            outside: case.outside,
            failure,
            coordinates: None,
        }
    }

    fn no_bound_reason(&self) -> &'static str {
        "the denominator's error bound e_D is not below |D| (its sign is not certain)"
    }

    fn text(&self, algorithm: Algorithm) -> BoundText {
        let k = roundings(algorithm, self.cert.net.m(), self.cert.net.degree());
        BoundText {
            label: Some(format!("γ_{k},÷")),
            note: RATIONAL_NOTE,
            outside: Some(
                "overflow, or |D̂| ≤ e_D (the denominator's sign is not certain, e.g. where it vanishes outside the simplex)",
            ),
            coordinates: None,
        }
    }
}

impl Constructions for RationalPatch {
    fn linear_net(&self) -> Cow<'_, ControlNet<BigRational>> {
        Cow::Owned(self.homogeneous())
    }

    fn with_linear_net(
        &self,
        net: ControlNet<BigRational>,
        f: Option<&[Vec<BigRational>]>,
    ) -> Result<AnyPatch, CoreError> {
        let mut r = RationalPatch::from_homogeneous(&net, &self.patch)?;
        r.patch = with_net(&self.patch, r.patch.net, f)?;
        Ok(AnyPatch::Rational(r))
    }

    fn blossom(&self, args: &[Vec<BigRational>]) -> Result<Vec<BigRational>, CoreError> {
        RationalPatch::blossom(self, args)
    }

    fn domain(&self) -> crate::domain::Domain {
        self.patch.domain_or_reference()
    }

    fn derivative(
        &self,
        at: &[BigRational],
        directions: &[&[BigRational]],
    ) -> Result<Vec<BigRational>, CoreError> {
        self.derivative_of_order(at, directions)
    }

    fn tangent_frame(
        &self,
        at: &[BigRational],
    ) -> Result<crate::derivative::TangentFrame, CoreError> {
        RationalPatch::tangent_frame(self, &self.patch.domain_or_reference(), at)
    }

    fn projected(&self) -> bool {
        true
    }
}
