//! [`judge`]: one call that judges a float result.
//!
//! Given a patch, the input as the float program saw it, the values it claims and a tolerance,
//! the judge does what certification does (docs/theory.md §14):
//!
//! 1. rounds the patch's numbers to the precision, as the float code holds them (control
//!    points; for a rational patch the homogeneous net `(w c, w)`; for an S-patch the polygon
//!    too), and the input to the precision (a no-op for floats of that precision);
//! 2. evaluates exactly at the input as seen, with the numbers as seen (barycentric coordinates
//!    that do not sum to 1, as `(0.5, 0.1, 0.4)` in binary does not, evaluate the homogeneous
//!    form, which is what the float code computes);
//! 3. measures each claimed value against that exact value: the error in ULPs of the precision
//!    (binade ULP, docs/theory.md §14.4), correct rounding, and with the intended exact input
//!    ([`judge_with`]) the error against the exact value there;
//! 4. gives the condition number and the proven a-priori bound of the float program, and the
//!    verdict of the tolerance ([`Tolerance::accepts`], one comparison path for every
//!    tolerance).
//!
//! ```
//! use tribez::{Degree, Patch, Precision, SimplexDim, Tolerance, judge, parse_rational};
//! let q = |s: &str| parse_rational(s).unwrap();
//! let p = |xs: [&str; 3]| xs.map(q).to_vec();
//! let patch = Patch::bezier(SimplexDim(2), Degree(2), vec![
//!     p(["0", "0", "0"]), p(["1", "0", "2"]), p(["0", "2", "0"]),
//!     p(["0", "1", "0"]), p(["1", "1", "1"]), p(["0", "2", "1"]),
//! ]).unwrap();
//! // a float program evaluated it at (0.5, 1/3, 1/6) in f64 and got the nearest floats of the
//! // exact values at what it saw (computed with Python's fractions: fixtures/judge/derive.py)
//! let input = [0.5, 1.0 / 3.0, 1.0 / 6.0];
//! let claimed = [0.4444444444444444, 0.5555555555555555, 0.8055555555555555];
//! let tol = Tolerance::parse("correctly_rounded").unwrap();
//! let j = judge(&patch, &input, &claimed, &tol, Precision::F64).unwrap();
//! assert!(j.passed);
//! // one ULP off in the first coordinate is not correctly rounded
//! let off = [0.4444444444444445, 0.5555555555555555, 0.8055555555555555];
//! assert!(!judge(&patch, &input, &off, &tol, Precision::F64).unwrap().passed);
//! ```

use num_rational::BigRational;
use serde::Serialize;

use crate::api_error::Error;
use crate::capability::InputSpace;
use crate::certify::measures::{Leaf, Measures, Tolerance};
use crate::exact::Algorithm;
use crate::float::Precision;
use crate::judge_refusal::{Lacks, Refusal};
use crate::patch_type::{Patch, PatchKind};

/// One claimed coordinate, judged.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct CoordinateJudgement {
    /// The claimed value.
    pub claimed: f64,
    /// The exact value at the input as seen (patch numbers as seen).
    #[serde(serialize_with = "ser::rational")]
    pub exact: BigRational,
    /// The exact value at the intended input (the exact patch), when given.
    #[serde(serialize_with = "ser::opt_rational")]
    pub exact_intended: Option<BigRational>,
    /// `|claimed − exact| / ulp(exact)` at the input as seen (`None`: the claim is not finite).
    #[serde(serialize_with = "ser::opt_rational")]
    pub ulps: Option<BigRational>,
    /// The same against the exact value at the intended input.
    #[serde(serialize_with = "ser::opt_rational")]
    pub ulps_intended: Option<BigRational>,
    /// Is the claim the nearest float (ties to even) to the exact value at the input as seen?
    pub correctly_rounded: bool,
    /// The condition number of this coordinate at the input as seen (`Σ|c_i| B_i(|λ|)` for a
    /// polynomial patch).
    #[serde(serialize_with = "ser::opt_rational")]
    pub condition: Option<BigRational>,
    /// The proven a-priori bound of the float program's absolute error (`None`: outside its
    /// hypotheses).
    #[serde(serialize_with = "ser::opt_rational")]
    pub bound: Option<BigRational>,
    /// The tolerance accepts this coordinate.
    pub passed: bool,
}

/// The verdict of [`judge`] on one float result.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Judgement {
    /// Every coordinate passed.
    pub passed: bool,
    /// The kind of patch.
    pub kind: PatchKind,
    /// The precision (`"f64"`, `"f32"`).
    #[serde(serialize_with = "ser::precision")]
    pub precision: Precision,
    /// The tolerance as written.
    #[serde(serialize_with = "ser::display")]
    pub tolerance: Tolerance,
    /// The float algorithm whose bound is given.
    pub algorithm: &'static str,
    /// The exact values of the input as seen.
    #[serde(serialize_with = "ser::rationals")]
    pub input_seen: Vec<BigRational>,
    /// Per coordinate.
    pub coordinates: Vec<CoordinateJudgement>,
}

impl std::fmt::Display for Judgement {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let o = |x: &Option<BigRational>| {
            x.as_ref()
                .map_or("n/a".to_string(), crate::number::ulps_decimal)
        };
        writeln!(
            f,
            "{} under {} ({} {}, input as seen {})",
            if self.passed { "passed" } else { "FAILED" },
            self.tolerance,
            self.precision.name(),
            self.algorithm,
            crate::domain::format_tuple(&self.input_seen),
        )?;
        for (c, j) in self.coordinates.iter().enumerate() {
            write!(
                f,
                "  [{c}] {} vs exact {}: {} ulp as seen",
                j.claimed,
                j.exact,
                o(&j.ulps)
            )?;
            if j.exact_intended.is_some() {
                write!(f, ", {} ulp as intended", o(&j.ulps_intended))?;
            }
            writeln!(
                f,
                ", {}, cond {}, bound {}: {}",
                if j.correctly_rounded {
                    "correctly rounded"
                } else {
                    "not correctly rounded"
                },
                j.condition
                    .as_ref()
                    .map_or("n/a".into(), crate::certify::measures::sci),
                j.bound
                    .as_ref()
                    .map_or("n/a".into(), crate::certify::measures::sci),
                if j.passed { "ok" } else { "FAILS" }
            )?;
        }
        Ok(())
    }
}

/// Judge a float result: `patch` evaluated by a float program of `precision` at `input` (as the
/// program saw it: floats of the precision) gave `claimed`; does `tolerance` accept it? The
/// float program is the kind's default (de Casteljau); see the module documentation.
pub fn judge(
    patch: &Patch,
    input: &[f64],
    claimed: &[f64],
    tolerance: &Tolerance,
    precision: Precision,
) -> Result<Judgement, Error> {
    judge_with(patch, input, claimed, tolerance, precision, None)
}

/// [`judge`], also measuring the claim against the exact value at the `intended` exact input
/// (the point the program was meant to evaluate at, before its input was rounded).
pub fn judge_with(
    patch: &Patch,
    input: &[f64],
    claimed: &[f64],
    tolerance: &Tolerance,
    precision: Precision,
    intended: Option<&[BigRational]>,
) -> Result<Judgement, Error> {
    let algorithm = patch
        .float()
        .map_or(Algorithm::Casteljau, |f| f.float_algorithms()[0]);
    judge_algorithm(
        patch, algorithm, input, claimed, tolerance, precision, intended,
    )
}

/// Which argument of a judgement a [`Refusal`] is about ([`exact_side`]), so that a caller
/// reading the arguments from a file can locate it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Part {
    /// The patch (its float program: rounding overflows).
    Patch,
    /// The algorithm.
    Algorithm,
    /// The input.
    Input,
    /// The tolerance.
    Tolerance,
}

/// The exact side of a judgement (steps 1, 2 and 4 of the module documentation): what every
/// coordinate's verdict is measured against.
pub(crate) struct Side {
    /// The name of the float algorithm.
    pub algorithm: &'static str,
    /// The exact values of the input as seen.
    pub input_seen: Vec<BigRational>,
    /// The exact value at the input as seen (patch numbers as seen).
    pub exact: Vec<BigRational>,
    /// The exact value at the intended input, when given.
    pub exact_intended: Option<Vec<BigRational>>,
    /// The condition number per coordinate, where defined.
    pub condition: Option<Vec<BigRational>>,
    /// The proven a-priori bound per coordinate, where the point is inside its hypotheses.
    pub bound: Option<Vec<BigRational>>,
    /// Does `cond=K` mean anything for this kind?
    pub cond_tolerance: bool,
}

impl Side {
    /// What the tolerance may need at coordinate `c`.
    pub fn leaf(&self, c: usize, precision: Precision) -> Leaf {
        Leaf {
            precision: Some(precision),
            condition: self
                .condition
                .as_ref()
                .filter(|_| self.cond_tolerance)
                .and_then(|k| k.get(c).cloned()),
            bound: self.bound.as_ref().and_then(|b| b.get(c).cloned()),
        }
    }
}

/// The exact side of judging `patch`'s float program of `precision` running `algorithm` at
/// `input` with `tolerance`: the checks, then the exact value at the input as seen, the exact
/// value at the `intended` input, the condition numbers and the bound. The one path of
/// [`judge_algorithm`] and of `eval` claims with a precision ([`crate::claims`]).
pub(crate) fn exact_side(
    patch: &Patch,
    algorithm: Algorithm,
    input: &[f64],
    tolerance: &Tolerance,
    precision: Precision,
    intended: Option<&[BigRational]>,
) -> Result<Side, (Part, Refusal)> {
    let described = patch.as_any().described();
    let float = patch.float().ok_or((
        Part::Patch,
        Refusal::Unsupported {
            kind: described,
            what: Lacks::FloatProgram,
        },
    ))?;
    if !float.float_algorithms().contains(&algorithm) {
        return Err((
            Part::Algorithm,
            Refusal::Unsupported {
                kind: described,
                what: Lacks::Algorithm {
                    algorithm,
                    has: float.float_algorithms(),
                    path: float.algorithm_name(float.float_algorithms()[0]),
                },
            },
        ));
    }
    let shape = patch.shape();
    let width = shape.input.len();
    if input.len() != width {
        return Err((
            Part::Input,
            Refusal::Size {
                what: match shape.input {
                    InputSpace::Barycentric { .. } => "barycentric coordinates of the input",
                    InputSpace::Polygon { .. } => "Cartesian coordinates of the input",
                },
                expected: width,
                found: input.len(),
            },
        ));
    }
    if let Some(i) = intended.filter(|i| i.len() != width) {
        return Err((
            Part::Input,
            Refusal::Size {
                what: "coordinates of the intended input",
                expected: width,
                found: i.len(),
            },
        ));
    }
    let exact_input: Vec<BigRational> = input
        .iter()
        .map(|&x| {
            crate::number::exact_f64(x).ok_or((
                Part::Input,
                Refusal::NotFinite {
                    what: "input",
                    value: x,
                },
            ))
        })
        .collect::<Result<_, _>>()?;
    let program = float
        .float_program(precision)
        .map_err(|e| (Part::Patch, e.into()))?;
    let seen_input = program
        .round_input(&exact_input)
        .map_err(|e| (Part::Input, e.into()))?;
    let bounds = program.error_bound().ok_or((
        Part::Patch,
        Refusal::Unsupported {
            kind: described,
            what: Lacks::ErrorBound,
        },
    ))?;
    let seen = bounds.seen(algorithm, &seen_input);
    if tolerance.is_cond() && !seen.cond_tolerance {
        return Err((
            Part::Tolerance,
            Refusal::Unsupported {
                kind: described,
                what: Lacks::CondTolerance {
                    tolerance: tolerance.clone(),
                    kinds: patch.kind().plural(),
                },
            },
        ));
    }
    let exact = seen.exact.clone().ok_or_else(|| {
        (
            Part::Input,
            Refusal::Undefined {
                kind: described,
                input: seen.input.clone(),
                precision,
            },
        )
    })?;
    if *tolerance == Tolerance::Bound && seen.bound.is_none() {
        return Err((
            Part::Tolerance,
            Refusal::NoBound {
                precision,
                reason: bounds.no_bound_reason(),
            },
        ));
    }
    let exact_intended = match intended {
        Some(i) => Some(
            patch
                .exact()
                .exact_evaluator()
                .evaluate(i)
                .map_err(|e| (Part::Input, e.into()))?,
        ),
        None => None,
    };
    Ok(Side {
        algorithm: float.algorithm_name(algorithm),
        input_seen: seen.input,
        exact,
        exact_intended,
        condition: seen.condition,
        bound: seen.bound,
        cond_tolerance: seen.cond_tolerance,
    })
}

/// [`judge_with`] for a named float `algorithm` of the kind (a polynomial patch also has the
/// direct Bernstein form, [`Algorithm::Bernstein`], whose bound differs).
pub fn judge_algorithm(
    patch: &Patch,
    algorithm: Algorithm,
    input: &[f64],
    claimed: &[f64],
    tolerance: &Tolerance,
    precision: Precision,
    intended: Option<&[BigRational]>,
) -> Result<Judgement, Error> {
    let shape = patch.shape();
    if claimed.len() != shape.dimension {
        return Err(Error::Refusal(Refusal::Size {
            what: "claimed coordinates",
            expected: shape.dimension,
            found: claimed.len(),
        }));
    }
    let side = exact_side(patch, algorithm, input, tolerance, precision, intended)
        .map_err(|(_, e)| Error::from(e))?;
    let tolerance = &tolerance.for_patch(shape.simplex_dim, shape.degree);
    let mut coordinates = Vec::with_capacity(claimed.len());
    for (c, &y) in claimed.iter().enumerate() {
        let condition = side.condition.as_ref().map(|k| k[c].clone());
        let bound = side.bound.as_ref().map(|b| b[c].clone());
        let intended_c = side.exact_intended.as_ref().map(|e| e[c].clone());
        let exact = &side.exact[c];
        let judged = match crate::number::exact_f64(y) {
            None => CoordinateJudgement {
                claimed: y,
                exact: exact.clone(),
                exact_intended: intended_c,
                ulps: None,
                ulps_intended: None,
                correctly_rounded: false,
                condition,
                bound,
                passed: false,
            },
            Some(yq) => {
                let m = Measures::new(&yq, exact, Some(precision));
                let passed = tolerance
                    .accepts(&yq, exact, &side.leaf(c, precision))
                    .map_err(|needs| Error::Tolerance {
                        coordinate: c,
                        needs,
                    })?;
                CoordinateJudgement {
                    claimed: y,
                    exact: exact.clone(),
                    ulps_intended: intended_c
                        .as_ref()
                        .and_then(|i| Measures::new(&yq, i, Some(precision)).ulps),
                    exact_intended: intended_c,
                    ulps: m.ulps,
                    correctly_rounded: m.correctly_rounded == Some(true),
                    condition,
                    bound,
                    passed,
                }
            }
        };
        coordinates.push(judged);
    }
    Ok(Judgement {
        passed: coordinates.iter().all(|c| c.passed),
        kind: patch.kind(),
        precision,
        tolerance: tolerance.clone(),
        algorithm: side.algorithm,
        input_seen: side.input_seen,
        coordinates,
    })
}

/// Serialisation of exact numbers as their exact text (`"4/9"`).
mod ser {
    use num_rational::BigRational;
    use serde::Serializer;

    pub fn rational<S: Serializer>(q: &BigRational, s: S) -> Result<S::Ok, S::Error> {
        s.collect_str(q)
    }

    pub fn opt_rational<S: Serializer>(q: &Option<BigRational>, s: S) -> Result<S::Ok, S::Error> {
        match q {
            Some(q) => s.collect_str(q),
            None => s.serialize_none(),
        }
    }

    pub fn rationals<S: Serializer>(qs: &[BigRational], s: S) -> Result<S::Ok, S::Error> {
        s.collect_seq(qs.iter().map(ToString::to_string))
    }

    pub fn precision<S: Serializer>(p: &crate::float::Precision, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(p.name())
    }

    pub fn display<S: Serializer, T: std::fmt::Display>(t: &T, s: S) -> Result<S::Ok, S::Error> {
        s.collect_str(t)
    }
}
