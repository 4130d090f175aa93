//! S-patches (Loop and DeRose): a Bézier simplex of dimension `N − 1` composed with the
//! Wachspress coordinates `λ(p)` of a convex `N`-gon; points are Cartesian `(x, y)`.
//!
//! * exact: `S(p) = P(λ(p))` (`SPatch::evaluate`); undefined outside the polygon;
//! * float program: float Wachspress coordinates `λ̂` on the rounded polygon, then de Casteljau
//!   in `F` on the rounded control points (`SPatch::evaluate_float`);
//! * bound: the whole float path, `(γ_K + ((1+θ)^n − 1)/(1−θ)^n) Σ|P_α| B_α(|λ̂|)`
//!   (`crate::certify::beyond::SPatchCase::total_bound`), via `SPatchCertifier`; the
//!   coordinates `λ̂` are judged against their relative bound `θ`.

use num_rational::BigRational;

use crate::capability::traits::SymbolicForm;

use crate::capability::traits::check_len;
use crate::capability::traits::{
    BoundText, CoordinateCase, CoordinateText, ErrorBound, ExactEval, FloatCase, FloatEval,
    FloatProgram, InputSpace, Narrow, PointEvaluator, Seen, Shape, narrowed, round_input,
};
use crate::certify::beyond::SPatchCertifier;
use crate::certify::bound::roundings;
use crate::error::CoreError;
use crate::exact::Algorithm;
use crate::float::Precision;
use crate::spatch::SPatch;

/// The explanation of the S-patch bound in a certification report.
pub const SPATCH_NOTE: &str = "S-patch: the TOTAL error against the exact S-patch (rounded polygon and control points) at the rounded point, judged against the proven bound |ŷ − S(p̂)| ≤ (γ_K + ((1+θ)^n − 1)/(1−θ)^n) Σ|P_α| B_α(|λ̂|): de Casteljau at the float coordinates λ̂ plus their relative error θ (float Wachspress, bound.rs wachspress_relative); cond = Σ|P_α| B_α(|λ̂|), relcond = cond/|S|";

struct Exact<'a>(&'a SPatch);

impl PointEvaluator for Exact<'_> {
    fn evaluate(&self, input: &[BigRational]) -> Result<Vec<BigRational>, CoreError> {
        check_len(input, 2)?;
        Ok(self.0.evaluate(input)?.1)
    }

    fn coordinates(&self, input: &[BigRational]) -> Result<Option<Vec<BigRational>>, CoreError> {
        check_len(input, 2)?;
        Ok(Some(self.0.polygon.wachspress(input)?))
    }
}

impl ExactEval for SPatch {
    fn shape(&self) -> Shape {
        Shape {
            simplex_dim: self.net.m(),
            degree: self.net.degree(),
            dimension: self.net.dim(),
            input: InputSpace::Polygon {
                vertices: self.polygon.vertices().to_vec(),
            },
        }
    }

    fn exact_evaluator(&self) -> Box<dyn PointEvaluator + '_> {
        Box::new(Exact(self))
    }

    fn cartesian_input(&self, x: &[BigRational]) -> Result<Vec<BigRational>, CoreError> {
        check_len(x, 2)?;
        Ok(x.to_vec())
    }

    /// The rational form in `x, y`: `Σ_α P_α C(d;α) Π ω_i^{α_i}` over `(Σ ω)^d` (the variables
    /// are Cartesian whatever `cartesian` says: an S-patch has no barycentric variables).
    fn symbolic(&self, _cartesian: bool) -> SymbolicForm {
        let (components, denominator) = self.rational_form();
        SymbolicForm {
            names: crate::symbolic::cartesian_names(2),
            components,
            denominator: Some(denominator),
        }
    }
}

impl FloatEval for SPatch {
    fn float_algorithms(&self) -> &'static [Algorithm] {
        &[Algorithm::Casteljau]
    }

    fn algorithm_name(&self, _algorithm: Algorithm) -> &'static str {
        "Wachspress + de Casteljau"
    }

    fn float_program(&self, precision: Precision) -> Result<Box<dyn FloatProgram + '_>, CoreError> {
        Ok(match precision {
            Precision::F64 => Box::new(Program::<f64>::new(self)?),
            Precision::F32 => Box::new(Program::<f32>::new(self)?),
        })
    }
}

struct Program<F: Narrow> {
    cert: SPatchCertifier<F>,
}

impl<F: Narrow> Program<F> {
    fn new(s: &SPatch) -> Result<Self, CoreError> {
        Ok(Program {
            cert: SPatchCertifier::new(s)?,
        })
    }

    fn point(input: &[f64]) -> [F; 2] {
        [F::narrow(input[0]), F::narrow(input[1])]
    }
}

impl<F: Narrow> FloatProgram for Program<F> {
    fn precision(&self) -> Precision {
        F::PRECISION
    }

    fn round_input(&self, input: &[BigRational]) -> Result<Vec<f64>, CoreError> {
        check_len(input, 2)?;
        round_input::<F>(input)
    }

    fn run(&self, _algorithm: Algorithm, input: &[f64]) -> Vec<f64> {
        let lambda = crate::spatch::wachspress_float(&self.cert.vertices, &Self::point(input));
        crate::casteljau::evaluate(&self.cert.net, &lambda)
            .iter()
            .map(|y| y.widen())
            .collect()
    }

    fn exact_seen(&self, input: &[f64]) -> Option<Vec<BigRational>> {
        let p: Vec<BigRational> = narrowed::<F>(input)
            .iter()
            .map(|x| x.exact())
            .collect::<Option<_>>()?;
        self.cert.seen.evaluate(&p).ok().map(|(_, v)| v)
    }

    fn error_bound(&self) -> Option<&dyn ErrorBound> {
        Some(self)
    }
}

impl<F: Narrow> ErrorBound for Program<F> {
    fn seen(&self, _algorithm: Algorithm, input: &[f64]) -> Seen {
        let p = Self::point(input);
        let (exact, condition, bound) = self.cert.seen(&p);
        Seen {
            input: p.iter().map(|x| x.exact().unwrap_or_default()).collect(),
            exact,
            condition,
            bound,
            // the float coordinates add an error that Σ|P_α|B_α does not measure
            cond_tolerance: false,
        }
    }

    fn seen_exact(&self, algorithm: Algorithm, input: &[BigRational]) -> Seen {
        // a point of floats of the precision (what a float program can be given): `seen`
        let floats: Option<Vec<f64>> = input
            .iter()
            .map(|q| {
                let x = F::round(q);
                (x.exact().as_ref() == Some(q)).then(|| x.widen())
            })
            .collect();
        if let Some(xs) = floats.filter(|xs| xs.len() == 2) {
            return self.seen(algorithm, &xs);
        }
        let (exact, condition) = match self.cert.seen.evaluate(input) {
            Ok((lambda, v)) => (
                Some(v),
                Some(crate::certify::bound::condition(
                    &self.cert.seen.net,
                    &lambda,
                )),
            ),
            Err(_) => (None, None),
        };
        Seen {
            input: input.to_vec(),
            exact,
            condition,
            bound: None,
            cond_tolerance: false,
        }
    }

    fn certify(&self, _algorithm: Algorithm, input: &[f64]) -> FloatCase {
        let p = Self::point(input);
        let case = self.cert.check(&p);
        let mut out = FloatCase {
            input: p.iter().map(|x| x.exact().unwrap_or_default()).collect(),
            y: case.y.iter().map(|y| y.widen()).collect(),
            exact: None,
            condition: None,
            bound: None,
            outside: true,
            failure: None,
            coordinates: None,
        };
        if case.outside {
            return out;
        }
        // the rounded point outside the rounded polygon: not measured
        let (Some(v), Some(l)) = (case.exact, case.exact_lambda) else {
            return out;
        };
        let coordinate_bound = case
            .theta
            .as_ref()
            .filter(|_| case.total_bound.is_some())
            .map(|theta| l.iter().map(|e| theta * e).collect());
        out.coordinates = Some(CoordinateCase {
            values: case.lambda.iter().map(|x| x.widen()).collect(),
            exact: l,
            bound: coordinate_bound,
        });
        out.exact = Some(v);
        out.condition = Some(case.condition);
        // near an edge or underflow: outside the coordinates' bound
        out.outside = case.total_bound.is_none();
        out.bound = case.total_bound;
        out
    }

    fn no_bound_reason(&self) -> &'static str {
        "it is on or too near an edge of the polygon (or its numbers too small) for the float Wachspress coordinates' bound"
    }

    fn text(&self, algorithm: Algorithm) -> BoundText {
        let k = roundings(algorithm, self.cert.net.m(), self.cert.net.degree());
        BoundText {
            label: Some(format!("γ_{k}+θ")),
            note: SPATCH_NOTE,
            outside: Some(
                "overflow, the rounded point outside the rounded polygon, or so near an edge (or so small) that the coordinates' bound does not apply",
            ),
            coordinates: Some(CoordinateText {
                all: "Wachspress coordinates λ̂",
                one: "Wachspress coordinate ",
            }),
        }
    }
}
