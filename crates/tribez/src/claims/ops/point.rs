//! Operations at one point: `eval` (and its float view), `derivative`, `tangent`, `wachspress`;
//! and the coordinates of a point in a simplex: `barycentric`, `direction`.

use std::borrow::Cow;

use num_rational::BigRational;
use num_traits::Zero;

use super::inputs::{Inputs, Point, select_part};
use super::{OpName, Value, seen};
use crate::any_patch::AnyPatch;
use crate::domain::Domain;
use crate::exact::Algorithm;
use crate::io::{ClaimProblem, InputError, NeededKind, Problem};
use crate::patch_type::Patch;
use crate::spatch::SPatch;

type Q = BigRational;

/// An operation at one point, with its parsed inputs.
#[derive(Clone, Debug)]
pub enum PointOp<'a> {
    /// `eval`: the patch (any kind) at a point; `algorithm` names the float path of `bound`.
    Eval {
        /// The patch.
        patch: Cow<'a, Patch>,
        /// The point (Cartesian only, `at` empty, for an S-patch).
        point: Point,
        /// The float algorithm whose a-priori bound `tolerance = "bound"` uses.
        algorithm: Algorithm,
    },
    /// `derivative`: `D_{d_1} ⋯ D_{d_r} p` at a point (polynomial or rational patch).
    Derivative {
        /// The patch.
        patch: Cow<'a, AnyPatch>,
        /// The point.
        point: Point,
        /// Barycentric directions (each summing to 0).
        dirs: Vec<Vec<Q>>,
        /// Cartesian directions (converted with the patch's domain).
        vectors: Vec<Vec<Q>>,
    },
    /// `tangent`: the tangent frame at a point (polynomial or rational patch).
    Tangent {
        /// The patch.
        patch: Cow<'a, AnyPatch>,
        /// The point.
        point: Point,
        /// The part of the frame claimed, if one.
        part: Option<String>,
    },
    /// `wachspress`: an S-patch polygon's Wachspress data at a Cartesian point.
    Wachspress {
        /// The S-patch.
        patch: Cow<'a, SPatch>,
        /// The Cartesian point.
        cartesian: Vec<Q>,
    },
    /// `barycentric` (`direction = false`) or `direction` coordinates in a simplex.
    Coordinates {
        /// The simplex.
        domain: Domain,
        /// The Cartesian point (or vector).
        x: Vec<Q>,
        /// A vector (directional coordinates) rather than a point.
        direction: bool,
    },
}

fn parse_algorithm(inputs: &Inputs<'_>) -> Result<Algorithm, InputError> {
    match inputs.opt_string("algorithm")? {
        None => Ok(Algorithm::Casteljau),
        Some(text) => text.parse().map_err(|e| inputs.error("algorithm", e)),
    }
}

/// The point of a polynomial or rational patch (`at` or `cartesian`).
fn patch_point(inputs: &Inputs<'_>, patch: &AnyPatch) -> Result<Point, InputError> {
    match patch {
        AnyPatch::Bezier(p) | AnyPatch::Functional(p) => inputs.point(p),
        AnyPatch::Rational(r) => inputs.point(&r.patch),
        AnyPatch::SPatch(_) => {
            if inputs.get("at").is_some() {
                return Err(inputs.error("at", ClaimProblem::CartesianOnly { kind: "an S-patch" }));
            }
            Ok(Point {
                at: Vec::new(),
                cartesian: Some(inputs.rationals("cartesian")?),
            })
        }
    }
}

/// A polynomial or rational patch (an S-patch is an error for the claim's operation).
fn polynomial_or_rational<'a>(inputs: &Inputs<'a>) -> Result<Cow<'a, AnyPatch>, InputError> {
    let any = inputs.any_patch()?;
    if let AnyPatch::SPatch(_) = any.as_ref() {
        inputs.patch()?; // the located error "operation `…` does not take a S-patch patch"
    }
    Ok(any)
}

fn domain_of(patch: &AnyPatch) -> Option<Domain> {
    match patch {
        AnyPatch::Bezier(p) | AnyPatch::Functional(p) => Some(p.domain_or_reference()),
        AnyPatch::Rational(r) => Some(r.patch.domain_or_reference()),
        AnyPatch::SPatch(_) => None,
    }
}

impl<'a> PointOp<'a> {
    /// Parse the inputs of `name` (one of this module's operations).
    pub fn parse(inputs: &Inputs<'a>, name: OpName) -> Result<Self, InputError> {
        Ok(match name {
            OpName::Eval => {
                let patch = inputs.file.patch_for(inputs.claim)?;
                let point = inputs.point_of(patch)?;
                PointOp::Eval {
                    algorithm: parse_algorithm(inputs)?,
                    patch: Cow::Borrowed(patch),
                    point,
                }
            }
            OpName::Derivative => {
                let patch = polynomial_or_rational(inputs)?;
                let point = patch_point(inputs, &patch)?;
                let m = point.at.len() - 1;
                let dirs = inputs.rational_rows("dirs")?;
                for (i, d) in dirs.iter().enumerate() {
                    crate::domain::check_direction(d, m, "direction").map_err(|error| {
                        inputs.error(
                            "dirs",
                            Problem::Item {
                                what: "direction",
                                index: i + 1,
                                error,
                            },
                        )
                    })?;
                }
                let vectors = inputs.rational_rows("vectors")?;
                let op = PointOp::Derivative {
                    patch,
                    point,
                    dirs,
                    vectors,
                };
                // the Cartesian directions convert, and the order is possible
                op.directions(inputs)?;
                op
            }
            OpName::Tangent => {
                let patch = polynomial_or_rational(inputs)?;
                let point = patch_point(inputs, &patch)?;
                PointOp::Tangent {
                    patch,
                    point,
                    part: inputs.part()?,
                }
            }
            OpName::Wachspress => {
                let AnyPatch::SPatch(s) = inputs.file.patch_for(inputs.claim)?.as_any() else {
                    return Err(inputs.error(
                        "patch",
                        ClaimProblem::NeedsKind {
                            op: "wachspress",
                            needs: NeededKind::SPatch,
                        },
                    ));
                };
                let cartesian = inputs.rationals("cartesian")?;
                PointOp::Wachspress {
                    patch: Cow::Borrowed(s),
                    cartesian,
                }
            }
            OpName::Barycentric | OpName::Direction => {
                let direction = name == OpName::Direction;
                let key = if direction { "vector" } else { "point" };
                PointOp::Coordinates {
                    domain: inputs.domain("domain")?,
                    x: inputs.rationals(key)?,
                    direction,
                }
            }
            // invariant: the caller dispatches only the point operations here
            other => unreachable!("`{}` is not a point operation", other.name()),
        })
    }

    /// The derivative's barycentric directions: `dirs`, then `vectors` converted with the
    /// patch's domain; an error if there are none or more than the degree.
    fn directions(&self, inputs: &Inputs<'_>) -> Result<Vec<Vec<Q>>, InputError> {
        let PointOp::Derivative {
            patch,
            dirs,
            vectors,
            ..
        } = self
        else {
            // invariant: called for `derivative` operations only
            unreachable!("derivative only")
        };
        // invariant: parsing refused kinds without a simplex domain for a derivative
        let domain = domain_of(patch).expect("a polynomial or rational patch");
        let mut out = dirs.clone();
        for (i, v) in vectors.iter().enumerate() {
            out.push(domain.direction(v).map_err(|error| {
                inputs.error(
                    "vectors",
                    Problem::Item {
                        what: "vector",
                        index: i + 1,
                        error,
                    },
                )
            })?);
        }
        if out.is_empty() {
            return Err(inputs.error("dirs", ClaimProblem::NoDirections));
        }
        if let Some(p) = patch.polynomial() {
            crate::derivative::check_order(out.len(), p.net.degree())
                .map_err(|e| inputs.error("dirs", e))?;
        }
        Ok(out)
    }

    /// The operation on the inputs as seen in precision `p` (module doc of `ops`).
    pub fn seen(
        &self,
        inputs: &Inputs<'_>,
        p: crate::float::Precision,
    ) -> Result<Self, InputError> {
        Ok(match self {
            PointOp::Eval {
                patch,
                point,
                algorithm,
            } => PointOp::Eval {
                point: seen::input(inputs, point, patch, p)?,
                patch: Cow::Owned(seen::any_patch(inputs, patch.as_any(), p)?.into()),
                algorithm: *algorithm,
            },
            PointOp::Derivative {
                patch,
                point,
                dirs,
                vectors,
            } => PointOp::Derivative {
                point: seen::point(inputs, point, domain_of(patch).as_ref(), p)?,
                patch: Cow::Owned(seen::any_patch(inputs, patch, p)?),
                dirs: seen::rows(inputs, "dirs", dirs, p)?,
                vectors: seen::rows(inputs, "vectors", vectors, p)?,
            },
            PointOp::Tangent { patch, point, part } => PointOp::Tangent {
                point: seen::point(inputs, point, domain_of(patch).as_ref(), p)?,
                patch: Cow::Owned(seen::any_patch(inputs, patch, p)?),
                part: part.clone(),
            },
            PointOp::Wachspress { patch, cartesian } => PointOp::Wachspress {
                patch: Cow::Owned(seen::spatch(inputs, patch, p)?),
                cartesian: seen::numbers(inputs, "cartesian", cartesian, p)?,
            },
            PointOp::Coordinates {
                domain,
                x,
                direction,
            } => PointOp::Coordinates {
                domain: seen::domain(inputs, "domain", domain, p)?,
                x: seen::numbers(inputs, if *direction { "vector" } else { "point" }, x, p)?,
                direction: *direction,
            },
        })
    }

    /// The exact value.
    pub fn compute(&self, inputs: &Inputs<'_>) -> Result<Value, InputError> {
        match self {
            PointOp::Eval { patch, point, .. } => patch
                .exact()
                .exact_evaluator()
                .evaluate(point.input())
                .map(|v| Value::numbers(&v))
                .map_err(|e| inputs.error(point.key(), e)),
            PointOp::Derivative { patch, point, .. } => {
                let dirs = self.directions(inputs)?;
                let refs: Vec<&[Q]> = dirs.iter().map(Vec::as_slice).collect();
                match patch.as_ref() {
                    // rational patches: any order, by Leibniz's rule on the homogeneous net
                    AnyPatch::Rational(r) => r
                        .derivative_of_order(&point.at, &refs)
                        .map(|v| Value::numbers(&v))
                        .map_err(|e| inputs.error(point.key(), e)),
                    other => {
                        // invariant: the rational kind is matched above; parsing refused kinds without a polynomial net
                        let p = other.polynomial().expect("checked when parsed");
                        Ok(Value::numbers(&crate::derivative::directional_derivative(
                            &p.net, &refs, &point.at,
                        )))
                    }
                }
            }
            PointOp::Tangent { patch, point, part } => {
                let f = match patch.as_ref() {
                    AnyPatch::Rational(r) => {
                        r.tangent_frame(&r.patch.domain_or_reference(), &point.at)
                    }
                    other => {
                        // invariant: the rational kind is matched above; parsing refused kinds without a polynomial net
                        let p = other.polynomial().expect("checked when parsed");
                        crate::derivative::tangent_frame(
                            &p.net,
                            &p.domain_or_reference(),
                            &point.at,
                        )
                    }
                }
                .map_err(|e| inputs.error("at", e))?;
                select_part(inputs, part.as_deref(), tangent_value(&f))
            }
            PointOp::Wachspress { patch, cartesian } => {
                let lambda = patch
                    .polygon
                    .wachspress(cartesian)
                    .map_err(|e| inputs.error("cartesian", e))?;
                let x = [cartesian[0].clone(), cartesian[1].clone()]; // checked by `wachspress`
                Ok(Value::Map(vec![
                    ("A".into(), Value::numbers(&patch.polygon.areas(&x))),
                    ("C".into(), Value::numbers(&patch.polygon.corner_areas())),
                    ("lambda".into(), Value::numbers(&lambda)),
                ]))
            }
            PointOp::Coordinates {
                domain,
                x,
                direction,
            } => {
                let (name, result) = if *direction {
                    ("vector", domain.direction(x))
                } else {
                    ("point", domain.barycentric(x))
                };
                Ok(Value::numbers(&result.map_err(|e| inputs.error(name, e))?))
            }
        }
    }
}

/// The tangent frame as a map value.
fn tangent_value(f: &crate::derivative::TangentFrame) -> Value {
    let rows = |v: &[Vec<Q>]| Value::List(v.iter().map(|p| Value::numbers(p)).collect());
    let mut kv = vec![
        ("point".to_string(), Value::numbers(&f.point)),
        ("intermediate".to_string(), rows(&f.intermediate)),
        ("partials".to_string(), rows(&f.partials)),
        ("regular".to_string(), Value::Bool(f.regular)),
    ];
    if let Some(nrm) = &f.normal {
        kv.push(("normal".into(), Value::numbers(nrm)));
        // the plane through the intermediate points contains the point and has normal ∥ p_x × p_y
        let c = &f.intermediate;
        let d = |a: &[Q], b: &[Q]| a.iter().zip(b).map(|(x, y)| x - y).collect::<Vec<_>>();
        let plane = crate::derivative::cross(&d(&c[1], &c[0]), &d(&c[2], &c[0]));
        let parallel = crate::derivative::cross(&plane, nrm)
            .iter()
            .all(Zero::is_zero)
            && plane.iter().any(|x| !x.is_zero());
        let on: Q = d(&f.point, &c[0])
            .iter()
            .zip(&plane)
            .map(|(a, b)| a * b)
            .sum();
        kv.push((
            "spans_tangent_plane".into(),
            Value::Bool(parallel && on.is_zero()),
        ));
    }
    Value::Map(kv)
}

/// A float evaluation claim's exact values both ways, its condition numbers and bounds.
pub struct FloatEval {
    /// The exact values of the inputs as the code saw them (rounded to the precision).
    pub seen_inputs: Vec<Q>,
    /// `P` at those inputs, with the patch's numbers rounded to the precision too.
    pub exact_seen: Vec<Q>,
    /// `P` at the intended inputs (the exact text, the exact patch).
    pub exact_intended: Vec<Q>,
    /// The condition number per coordinate, at the inputs as seen.
    pub condition: Vec<Q>,
    /// The a-priori bound of the claim's `algorithm` per coordinate.
    pub bound: Vec<Option<Q>>,
    /// Does `cond=K` mean anything for this kind of patch?
    pub cond_tolerance: bool,
    /// `(m, n)`: the simplex dimension and degree of the net evaluated (what `cond` without `K`
    /// resolves against, [`crate::certify::measures::Tolerance::for_patch`]).
    pub simplex_degree: (usize, usize),
}

/// The float view of an `eval` claim in precision `p`: the exact side of the library's judge
/// ([`crate::judge_input`]), for any kind of patch through its capabilities. The input is
/// rounded to `p` (a Cartesian point of a simplex is rounded, then converted to barycentric
/// coordinates exactly, and judged at those exact coordinates, as
/// [`crate::JudgeInput::Cartesian`] and `check --results --cartesian` batches judge it), and the kind's float program holds its numbers rounded to `p` (for a
/// rational patch its homogeneous net `(w c, w)`; for an S-patch its polygon too); `bound` is
/// the proven bound of that program, and `cond=K` is refused where the program adds an error
/// the condition number does not measure (S-patches: the float Wachspress coordinates).
pub fn eval_float(
    inputs: &Inputs<'_>,
    op: &PointOp<'_>,
    p: crate::float::Precision,
) -> Result<FloatEval, InputError> {
    let PointOp::Eval {
        patch,
        point,
        algorithm,
    } = op
    else {
        // invariant: the float view is asked of `eval` operations only
        unreachable!("the float view is of `eval`")
    };
    // `at` rounded to p, or the Cartesian point rounded to p and then converted exactly to
    // barycentric coordinates (not floats in general: never rounded again)
    let seen = seen::input(inputs, point, patch, p)?;
    let (tolerance, _) = inputs.file.tolerance_of(inputs.claim)?;
    let side = crate::judge::exact_side(
        patch,
        *algorithm,
        crate::judge::SideInput::Seen(seen.input()),
        &tolerance,
        p,
        Some(point.input()),
    )
    .map_err(|(part, e)| {
        use crate::judge::Part;
        use crate::judge_refusal::Refusal;
        let problem = |e: Refusal| -> Problem {
            match e {
                Refusal::Core(core) => core.into(),
                e => ClaimProblem::Judge(e).into(),
            }
        };
        match (part, e) {
            (Part::Patch, e) => inputs.error("patch", problem(e)),
            (Part::Algorithm, e) => inputs.error("algorithm", problem(e)),
            (Part::Input, e) => inputs.error(point.key(), problem(e)),
            (Part::Tolerance, Refusal::Unsupported { what, .. }) => {
                inputs.error("tolerance", ClaimProblem::Lacks(what))
            }
            (Part::Tolerance, e) => inputs.error("tolerance", problem(e)),
        }
    })?;
    let d = side.exact.len();
    let condition = side
        .condition
        .ok_or_else(|| inputs.error(point.key(), ClaimProblem::ConditionUndefined))?;
    Ok(FloatEval {
        seen_inputs: side.input_seen,
        exact_seen: side.exact,
        exact_intended: side.exact_intended.unwrap_or_default(),
        condition,
        bound: side
            .bound
            .map_or_else(|| vec![None; d], |b| b.into_iter().map(Some).collect()),
        cond_tolerance: side.cond_tolerance,
        simplex_degree: (patch.simplex_dim(), patch.degree()),
    })
}
