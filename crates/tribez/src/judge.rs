//! [`judge`]: one call that judges a float result.
//!
//! Given a patch, the input as the float program saw it, the values it claims and a tolerance,
//! the judge does what certification does (docs/theory.md §14):
//!
//! 1. rounds the patch's numbers to the precision, as the float code holds them (control
//!    points; for a rational patch the homogeneous net `(w c, w)`; for an S-patch the polygon
//!    too), and the input to the precision (a no-op for floats of that precision); a Cartesian
//!    input ([`JudgeInput::Cartesian`]) is then converted exactly to barycentric coordinates;
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
//!
//! A float program given a **Cartesian** point of the patch's domain is judged with
//! [`judge_cartesian`] ([`JudgeInput::Cartesian`]): the point is rounded to the precision, then
//! converted exactly to barycentric coordinates, and the verdict uses the exact value there. Those
//! coordinates are rationals, never rounded: in the triangle (0,0), (3,0), (0,3) the point (1, 1)
//! is (1/3, 1/3, 1/3). On the plane `21 λ0 + 67 λ1 − 2 λ2` the value there is
//! (21 + 67 − 2)/3 = 86/3; its binade ULP is 2^-48 (16 ≤ 86/3 < 32), and 86·2^48 ≡ 2 (mod 3), so
//! 86/3 lies 2/3 ulp above one float and 1/3 ulp below the next, its correct rounding:
//!
//! ```
//! use tribez::{Patch, Precision, Tolerance, judge_cartesian, parse_rational};
//! let q = |s: &str| parse_rational(s).unwrap();
//! let plane = Patch::from_json(r#"{"degree": 1,
//!     "control_points": {"1,0,0": ["21"], "0,1,0": ["67"], "0,0,1": ["-2"]},
//!     "domain": [["0", "0"], ["3", "0"], ["0", "3"]]}"#).unwrap();
//! let tol = Tolerance::parse("correctly_rounded").unwrap();
//! let j = judge_cartesian(&plane, &[1.0, 1.0], &[28.666666666666668], &tol, Precision::F64)
//!     .unwrap();
//! assert_eq!(j.input_seen, vec![q("1/3"), q("1/3"), q("1/3")]);
//! assert_eq!(j.coordinates[0].exact, q("86/3"));
//! assert_eq!(j.coordinates[0].ulps, Some(q("1/3")));
//! assert!(j.passed);
//! // the float below, 2/3 ulp away, is not correctly rounded
//! let j = judge_cartesian(&plane, &[1.0, 1.0], &[28.666666666666664], &tol, Precision::F64)
//!     .unwrap();
//! assert_eq!(j.coordinates[0].ulps, Some(q("2/3")));
//! assert!(!j.passed);
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

/// The point a float program evaluated at, as it was given to the program ([`judge_input`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum JudgeInput<'a> {
    /// The kind's own coordinates: the `m + 1` barycentric coordinates of a patch over a simplex
    /// (any sum: the homogeneous form is evaluated), the Cartesian point `(x, y)` of an S-patch.
    /// Each is rounded to the precision (a no-op for floats of it) and judged there.
    Native(&'a [f64]),
    /// A Cartesian point `x` of the patch's domain (`m` coordinates; `(x, y)` for an S-patch),
    /// rounded to the precision (a no-op for floats of it) and then converted **exactly** to
    /// barycentric coordinates with the patch's domain, `λ = D⁻¹ (x, 1)` by Cramer's rule
    /// (docs/theory.md §2; the reference triangle when the patch has no domain). The exact value,
    /// the condition number `Σ|c_α| B_α(|λ|)` and the a-priori bound are those at that exact `λ`,
    /// which is in general not a tuple of floats (`(1, 1)` in the triangle `(0,0), (3,0), (0,3)`
    /// is `(1/3, 1/3, 1/3)`); it is never rounded. This is how claim files (`cartesian` with a
    /// `precision`, docs/guide.md §7) and `check --results --cartesian` batches judge a point.
    /// For an S-patch, whose input is Cartesian, the same as [`JudgeInput::Native`].
    Cartesian(&'a [f64]),
}

/// Judge a float result: `patch` evaluated by a float program of `precision` at `input` (as the
/// program saw it: floats of the precision) gave `claimed`; does `tolerance` accept it? The
/// float program is the kind's default (de Casteljau); see the module documentation. `input` is
/// in the kind's own coordinates ([`JudgeInput::Native`]); for a Cartesian point of a patch over
/// a simplex, see [`judge_cartesian`].
pub fn judge(
    patch: &Patch,
    input: &[f64],
    claimed: &[f64],
    tolerance: &Tolerance,
    precision: Precision,
) -> Result<Judgement, Error> {
    judge_with(patch, input, claimed, tolerance, precision, None)
}

/// [`judge`] at a Cartesian point `point` of the patch's domain ([`JudgeInput::Cartesian`]):
/// the point is rounded to the precision and converted exactly to barycentric coordinates, and
/// the verdict uses the exact value there. `Judgement::input_seen` holds those exact barycentric
/// coordinates.
pub fn judge_cartesian(
    patch: &Patch,
    point: &[f64],
    claimed: &[f64],
    tolerance: &Tolerance,
    precision: Precision,
) -> Result<Judgement, Error> {
    judge_input(
        patch,
        default_algorithm(patch),
        JudgeInput::Cartesian(point),
        claimed,
        tolerance,
        precision,
        None,
    )
}

/// The kind's default float algorithm (the first of its float program's).
fn default_algorithm(patch: &Patch) -> Algorithm {
    patch
        .float()
        .map_or(Algorithm::Casteljau, |f| f.float_algorithms()[0])
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
    judge_algorithm(
        patch,
        default_algorithm(patch),
        input,
        claimed,
        tolerance,
        precision,
        intended,
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

/// The input of [`exact_side`], in the kind's own coordinates.
#[derive(Clone, Copy, Debug)]
pub(crate) enum SideInput<'a> {
    /// Floats as given to the program: rounded to the precision (a no-op for floats of it).
    Floats(&'a [f64]),
    /// The exact input as seen, already rounded where rounding applies: the exact barycentric
    /// coordinates of a rounded Cartesian point (in general not floats), used as they are.
    Seen(&'a [BigRational]),
}

impl SideInput<'_> {
    fn len(&self) -> usize {
        match self {
            SideInput::Floats(x) => x.len(),
            SideInput::Seen(x) => x.len(),
        }
    }
}

/// The exact side of judging `patch`'s float program of `precision` running `algorithm` at
/// `input` with `tolerance`: the checks, then the exact value at the input as seen, the exact
/// value at the `intended` input, the condition numbers and the bound. The one path of
/// [`judge_input`] and of `eval` claims with a precision ([`crate::claims`]).
pub(crate) fn exact_side(
    patch: &Patch,
    algorithm: Algorithm,
    input: SideInput<'_>,
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
    let program = float
        .float_program(precision)
        .map_err(|e| (Part::Patch, e.into()))?;
    let bounds = program.error_bound().ok_or((
        Part::Patch,
        Refusal::Unsupported {
            kind: described,
            what: Lacks::ErrorBound,
        },
    ))?;
    let seen = match input {
        SideInput::Floats(input) => {
            let exact_input = exact_floats(input)?;
            let seen_input = program
                .round_input(&exact_input)
                .map_err(|e| (Part::Input, e.into()))?;
            bounds.seen(algorithm, &seen_input)
        }
        SideInput::Seen(input) => bounds.seen_exact(algorithm, input),
    };
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

/// The exact values of floats; an error naming the first that is not finite.
fn exact_floats(xs: &[f64]) -> Result<Vec<BigRational>, (Part, Refusal)> {
    xs.iter()
        .map(|&x| {
            crate::number::exact_f64(x).ok_or((
                Part::Input,
                Refusal::NotFinite {
                    what: "input",
                    value: x,
                },
            ))
        })
        .collect()
}

/// A Cartesian point of a patch over a simplex, as the program saw it: its floats rounded to
/// `precision`, then converted exactly to barycentric coordinates with the patch's domain. Also
/// converts the `intended` exact Cartesian point. (`None`: an S-patch, whose input is Cartesian.)
#[allow(clippy::type_complexity)]
fn cartesian_seen(
    patch: &Patch,
    point: &[f64],
    precision: Precision,
    intended: Option<&[BigRational]>,
) -> Result<Option<(Vec<BigRational>, Option<Vec<BigRational>>)>, Refusal> {
    let InputSpace::Barycentric { m } = patch.shape().input else {
        return Ok(None);
    };
    let size = |what, found| Refusal::Size {
        what,
        expected: m,
        found,
    };
    if point.len() != m {
        return Err(size("Cartesian coordinates of the input", point.len()));
    }
    if let Some(i) = intended.filter(|i| i.len() != m) {
        return Err(size("Cartesian coordinates of the intended input", i.len()));
    }
    let rounded = exact_floats(point)
        .map_err(|(_, e)| e)?
        .iter()
        .map(|q| crate::certify::measures::as_float(q, precision))
        .collect::<Option<Vec<_>>>()
        .ok_or(Refusal::Core(crate::error::CoreError::Overflows {
            what: "an input",
            precision: precision.name(),
        }))?;
    let exact = patch.exact();
    let lambda = exact.cartesian_input(&rounded)?;
    let intended = intended.map(|i| exact.cartesian_input(i)).transpose()?;
    Ok(Some((lambda, intended)))
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
    judge_input(
        patch,
        algorithm,
        JudgeInput::Native(input),
        claimed,
        tolerance,
        precision,
        intended,
    )
}

/// The judge with every choice: the float `algorithm`, the `input` in the kind's own
/// coordinates or as a Cartesian point of the patch's domain ([`JudgeInput`]), and the
/// `intended` exact input in the same coordinates as `input` (a Cartesian point for
/// [`JudgeInput::Cartesian`]), whose exact value the claim is also measured against.
pub fn judge_input(
    patch: &Patch,
    algorithm: Algorithm,
    input: JudgeInput<'_>,
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
    let cartesian = match input {
        JudgeInput::Cartesian(point) => cartesian_seen(patch, point, precision, intended)?,
        JudgeInput::Native(_) => None,
    };
    let side = match (&cartesian, input) {
        (Some((lambda, intended)), _) => exact_side(
            patch,
            algorithm,
            SideInput::Seen(lambda),
            tolerance,
            precision,
            intended.as_deref(),
        ),
        (None, JudgeInput::Native(x) | JudgeInput::Cartesian(x)) => exact_side(
            patch,
            algorithm,
            SideInput::Floats(x),
            tolerance,
            precision,
            intended,
        ),
    }
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
