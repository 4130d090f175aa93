//! The polynomial kinds: Bézier simplices of any dimension `m`, and functional patches (a
//! Bézier simplex with one ordinate per control point, `d = 1`, over a domain simplex; the same
//! evaluation, float program and bound).
//!
//! * exact: `P(λ) = Σ c_α B^n_α(λ)` by the exact kernel ([`crate::exact::ExactEvaluator`]);
//!   coordinates that do not sum to 1 evaluate the homogeneous form;
//! * float program: de Casteljau or the direct Bernstein form in `F` on the control points
//!   rounded to `F` (`crate::certify::run`);
//! * bound: `γ_K Σ|c_i| B_i(|λ|)` (docs/theory.md §14.1, `crate::certify::bound::a_priori`),
//!   the condition number `Σ|c_i| B_i(|λ|)`, via `crate::certify::Certifier`.

use std::borrow::Cow;

use num_rational::BigRational;

use crate::any_patch::AnyPatch;
use crate::capability::traits::{
    BoundText, Constructions, ErrorBound, ExactEval, FloatCase, FloatEval, FloatProgram,
    InputSpace, Narrow, PointEvaluator, Seen, Shape, SymbolicForm, check_len, exact_values,
    narrowed, round_input, with_net,
};
use crate::certify::Certifier;
use crate::error::CoreError;
use crate::exact::{Algorithm, ExactEvaluator};
use crate::float::Precision;
use crate::patch::{BezierPatch, ControlNet};

/// The explanation of the polynomial bound in a certification report.
pub const POLYNOMIAL_NOTE: &str = "bound: |fl(p) − P(λ)| ≤ γ_K Σ|c_i| B_i(|λ|) (γ_K = Kε/(1−Kε)); cond = Σ|c_i|B_i(|λ|), relcond = cond/|P|; err/bound = largest observed error over its bound";

struct Exact {
    evaluator: ExactEvaluator,
    m: usize,
}

impl PointEvaluator for Exact {
    fn evaluate(&self, input: &[BigRational]) -> Result<Vec<BigRational>, CoreError> {
        check_len(input, self.m + 1)?;
        Ok(self.evaluator.evaluate_fast(input))
    }

    fn total(&self) -> bool {
        true
    }
}

impl ExactEval for BezierPatch {
    fn shape(&self) -> Shape {
        Shape {
            simplex_dim: self.net.m(),
            degree: self.net.degree(),
            dimension: self.net.dim(),
            input: InputSpace::Barycentric { m: self.net.m() },
        }
    }

    fn exact_evaluator(&self) -> Box<dyn PointEvaluator + '_> {
        Box::new(Exact {
            evaluator: ExactEvaluator::new(&self.net),
            m: self.net.m(),
        })
    }

    fn cartesian_input(&self, x: &[BigRational]) -> Result<Vec<BigRational>, CoreError> {
        self.domain_or_reference().barycentric(x)
    }

    fn symbolic(&self, cartesian: bool) -> SymbolicForm {
        use crate::symbolic::{
            barycentric_form, barycentric_names, cartesian_form, cartesian_names,
        };
        let m = self.net.m();
        let (names, components) = if cartesian {
            (
                cartesian_names(m),
                cartesian_form(&self.net, &self.domain_or_reference()),
            )
        } else {
            (barycentric_names(m), barycentric_form(&self.net))
        };
        SymbolicForm {
            names,
            components,
            denominator: None,
        }
    }
}

const ALGORITHMS: &[Algorithm] = &[Algorithm::Casteljau, Algorithm::Bernstein];

impl FloatEval for BezierPatch {
    fn float_algorithms(&self) -> &'static [Algorithm] {
        ALGORITHMS
    }

    fn algorithm_name(&self, algorithm: Algorithm) -> &'static str {
        match algorithm {
            Algorithm::Casteljau => "casteljau",
            Algorithm::Bernstein => "bernstein",
        }
    }

    fn float_program(&self, precision: Precision) -> Result<Box<dyn FloatProgram + '_>, CoreError> {
        Ok(match precision {
            Precision::F64 => Box::new(Program::<f64>::new(&self.net)?),
            Precision::F32 => Box::new(Program::<f32>::new(&self.net)?),
        })
    }
}

/// The float program in `F`: the certifier of [`crate::certify`] (rounded net, its exact values
/// and exact evaluator).
struct Program<F: Narrow> {
    cert: Certifier<F>,
}

impl<F: Narrow> Program<F> {
    /// An error if a control point overflows `F` (its exact value would be unknown).
    fn new(net: &ControlNet<BigRational>) -> Result<Self, CoreError> {
        if net.coords().iter().any(|q| !F::round(q).finite()) {
            return Err(CoreError::Overflows {
                what: "a control point",
                precision: F::PRECISION.name(),
            });
        }
        Ok(Program {
            cert: Certifier::new(net),
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

    fn run(&self, algorithm: Algorithm, input: &[f64]) -> Vec<f64> {
        crate::certify::run(algorithm, &self.cert.net, &narrowed::<F>(input))
            .iter()
            .map(|y| y.widen())
            .collect()
    }

    fn exact_seen(&self, input: &[f64]) -> Option<Vec<BigRational>> {
        let lam = exact_values(&narrowed::<F>(input))?;
        Some(self.cert.exact.evaluate_fast(&lam))
    }

    fn error_bound(&self) -> Option<&dyn ErrorBound> {
        Some(self)
    }
}

impl<F: Narrow> ErrorBound for Program<F> {
    fn seen(&self, algorithm: Algorithm, input: &[f64]) -> Seen {
        let lam: Vec<F> = narrowed(input);
        let (exact, condition, bound) = self.cert.seen(algorithm, &lam);
        Seen {
            input: lam.iter().map(|x| x.exact().unwrap_or_default()).collect(),
            exact: Some(exact),
            condition: Some(condition),
            bound,
            cond_tolerance: true,
        }
    }

    fn seen_exact(&self, algorithm: Algorithm, input: &[BigRational]) -> Seen {
        let (exact, condition, bound) = self.cert.seen_exact(algorithm, input);
        Seen {
            input: input.to_vec(),
            exact: Some(exact),
            condition: Some(condition),
            bound,
            cond_tolerance: true,
        }
    }

    fn certify(&self, algorithm: Algorithm, input: &[f64]) -> FloatCase {
        let lam: Vec<F> = narrowed(input);
        let y = crate::certify::run(algorithm, &self.cert.net, &lam);
        let outside = y.iter().any(|v| !v.finite())
            || (algorithm == Algorithm::Bernstein
                && crate::certify::bernstein_may_underflow(&self.cert.net, &lam));
        let (exact, condition, bound) = self.cert.seen(algorithm, &lam);
        FloatCase {
            input: lam.iter().map(|x| x.exact().unwrap_or_default()).collect(),
            y: y.iter().map(|v| v.widen()).collect(),
            exact: Some(exact),
            condition: Some(condition),
            bound: bound.filter(|_| !outside),
            outside,
            failure: None,
            coordinates: None,
        }
    }

    fn text(&self, _algorithm: Algorithm) -> BoundText {
        BoundText {
            label: None,
            note: POLYNOMIAL_NOTE,
            outside: None,
            coordinates: None,
        }
    }
}

/// The constructions of a polynomial patch; `wrap` makes the result the same kind (Bézier or
/// functional).
pub(crate) struct Polynomial<'a> {
    /// The patch.
    pub patch: &'a BezierPatch,
    /// Back to the kind.
    pub wrap: fn(BezierPatch) -> AnyPatch,
    /// A functional patch (it has a graph).
    pub functional: bool,
}

impl Constructions for Polynomial<'_> {
    fn linear_net(&self) -> Cow<'_, ControlNet<BigRational>> {
        Cow::Borrowed(&self.patch.net)
    }

    fn with_linear_net(
        &self,
        net: ControlNet<BigRational>,
        f: Option<&[Vec<BigRational>]>,
    ) -> Result<AnyPatch, CoreError> {
        Ok((self.wrap)(with_net(self.patch, net, f)?))
    }

    fn blossom(&self, args: &[Vec<BigRational>]) -> Result<Vec<BigRational>, CoreError> {
        crate::blossom::blossom(&self.patch.net, args)
    }

    fn graph(&self) -> Option<Result<AnyPatch, CoreError>> {
        self.functional
            .then(|| crate::functional::graph(self.patch).map(AnyPatch::Bezier))
    }

    fn domain(&self) -> crate::domain::Domain {
        self.patch.domain_or_reference()
    }

    fn derivative(
        &self,
        at: &[BigRational],
        directions: &[&[BigRational]],
    ) -> Result<Vec<BigRational>, CoreError> {
        crate::derivative::check_order(directions.len(), self.patch.net.degree())?;
        Ok(crate::derivative::directional_derivative(
            &self.patch.net,
            directions,
            at,
        ))
    }

    fn tangent_frame(
        &self,
        at: &[BigRational],
    ) -> Result<crate::derivative::TangentFrame, CoreError> {
        crate::derivative::tangent_frame(&self.patch.net, &self.domain(), at)
    }
}
