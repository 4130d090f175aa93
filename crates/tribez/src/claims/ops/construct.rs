//! The constructions: `blossom`, `subpatch`, `subdivide`, `halve`, `elevate`, `matrix`,
//! `edge_curve`. Each result is control points keyed like a patch file ([`super::net_value`]),
//! or a list of such tables, or a point (`blossom`), or matrix rows (`matrix`).

use std::borrow::Cow;

use num_rational::BigRational;

use super::inputs::Inputs;
use super::{OpName, Value, keyed, net_value, seen};
use crate::any_patch::AnyPatch;
use crate::io::patch_file::{MAX_CONTROL_POINTS, MAX_DEGREE, MAX_SIMPLEX_DIMENSION};
use crate::io::{ClaimProblem, InputError};
use crate::patch::BezierPatch;
use crate::subdivide::HalvingOrder;

type Q = BigRational;

/// How `subdivide` splits.
#[derive(Clone, Debug, PartialEq)]
pub enum SubdivideMode {
    /// Into `m + 1` pieces at a barycentric point.
    At(Vec<Q>),
    /// Into `2^m` pieces at the edge midpoints.
    Midpoints,
}

/// How `halve` computes the halves.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum HalveMethod {
    /// By the blossom (the subpatch over each half).
    Blossom,
    /// By repeated adding and halving (Wolfe's blog), in the given order.
    AddAndHalve(HalvingOrder),
}

/// Which matrix `matrix` prints.
#[derive(Clone, Debug, PartialEq)]
pub enum MatrixKind {
    /// A half of the `m`-simplex cut at the midpoint of edge `(i, j)` (0-based): `piece` 1 or 2.
    Halve {
        /// Simplex dimension.
        m: usize,
        /// The edge, 0-based.
        edge: (usize, usize),
        /// 1 or 2.
        piece: usize,
    },
    /// The subpatch over these barycentric vertices (`m + 1` of them).
    Subpatch {
        /// The vertices.
        vertices: Vec<Vec<Q>>,
    },
}

/// A construction with its parsed inputs.
#[derive(Clone, Debug)]
pub enum Construction<'a> {
    /// `blossom`: `b[args]` (a polynomial or rational patch; `n` barycentric points).
    Blossom {
        /// The patch.
        patch: Cow<'a, AnyPatch>,
        /// The arguments.
        args: Vec<Vec<Q>>,
    },
    /// `subpatch`: the same patch over the sub-simplex of `vertices` (polynomial or rational).
    Subpatch {
        /// The patch.
        patch: Cow<'a, AnyPatch>,
        /// `m + 1` barycentric points of the parent.
        vertices: Vec<Vec<Q>>,
    },
    /// `subdivide`.
    Subdivide {
        /// The patch.
        patch: Cow<'a, BezierPatch>,
        /// At a point, or at the midpoints.
        mode: SubdivideMode,
    },
    /// `halve` at the midpoint of `edge` (0-based).
    Halve {
        /// The patch.
        patch: Cow<'a, BezierPatch>,
        /// The edge, 0-based.
        edge: (usize, usize),
        /// The method.
        method: HalveMethod,
    },
    /// `elevate` by `by >= 1`, the degree reached at most [`MAX_DEGREE`].
    Elevate {
        /// The patch.
        patch: Cow<'a, BezierPatch>,
        /// How many degrees.
        by: usize,
    },
    /// `matrix` of degree `degree` (at most [`crate::blossom::MAX_MATRIX_ROWS`] rows).
    Matrix {
        /// The degree.
        degree: usize,
        /// Halving or subpatch.
        kind: MatrixKind,
    },
    /// `edge_curve` from corner `from` to corner `to` (0-based).
    EdgeCurve {
        /// The patch.
        patch: Cow<'a, BezierPatch>,
        /// Corner, 0-based.
        from: usize,
        /// Corner, 0-based.
        to: usize,
    },
}

/// An error unless degree `n` on the `m`-simplex has at most [`MAX_CONTROL_POINTS`] control
/// points (checked before anything of that size is allocated).
pub(super) fn check_count(
    inputs: &Inputs<'_>,
    key: &str,
    m: usize,
    n: usize,
) -> Result<(), InputError> {
    let total = crate::simplex::binomial(n as u64 + m as u64, m as u64);
    if total > MAX_CONTROL_POINTS as u128 {
        return Err(inputs.error(
            key,
            ClaimProblem::TooManyControlPoints {
                degree: n,
                m,
                count: total,
                limit: MAX_CONTROL_POINTS,
            },
        ));
    }
    Ok(())
}

/// A polynomial or rational patch (an S-patch is an error for the claim's operation).
fn polynomial_or_rational<'a>(inputs: &Inputs<'a>) -> Result<Cow<'a, AnyPatch>, InputError> {
    let any = inputs.any_patch()?;
    if let AnyPatch::SPatch(_) = any.as_ref() {
        inputs.patch()?;
    }
    Ok(any)
}

fn simplex_m(patch: &AnyPatch) -> usize {
    match patch {
        AnyPatch::Bezier(p) | AnyPatch::Functional(p) => p.net.m(),
        AnyPatch::Rational(r) => r.patch.net.m(),
        AnyPatch::SPatch(s) => s.net.m(),
    }
}

fn parse_matrix(inputs: &Inputs<'_>) -> Result<Construction<'static>, InputError> {
    let degree = inputs.usize("degree")?;
    let kind = match inputs.opt_string("kind")?.as_deref() {
        Some("halve") => {
            let m = inputs.opt_usize("simplex")?.unwrap_or(2);
            if !(1..=MAX_SIMPLEX_DIMENSION).contains(&m) {
                return Err(inputs.error(
                    "simplex",
                    ClaimProblem::SimplexDimension {
                        limit: MAX_SIMPLEX_DIMENSION,
                    },
                ));
            }
            let edge = if inputs.get("edge").is_some() {
                inputs.edge(m)?
            } else {
                (0, 1)
            };
            let piece = inputs.opt_usize("piece")?.unwrap_or(1);
            if !(1..=2).contains(&piece) {
                return Err(inputs.error("piece", ClaimProblem::PieceNumber));
            }
            MatrixKind::Halve { m, edge, piece }
        }
        Some("subpatch") => {
            let count = inputs.array_len("vertices")?;
            if inputs.get("vertices").is_none() {
                return Err(inputs.error(
                    "vertices",
                    ClaimProblem::MissingInput {
                        name: "vertices".into(),
                        hint: None,
                    },
                ));
            }
            if count < 2 {
                return Err(inputs.error("vertices", ClaimProblem::TooFewVertices));
            }
            if count - 1 > MAX_SIMPLEX_DIMENSION {
                return Err(inputs.error(
                    "vertices",
                    ClaimProblem::VertexCount {
                        count,
                        limit: MAX_SIMPLEX_DIMENSION,
                    },
                ));
            }
            MatrixKind::Subpatch {
                vertices: inputs.bary_points("vertices", count - 1)?,
            }
        }
        _ => {
            return Err(inputs.error(
                "kind",
                ClaimProblem::MustBeOneOf {
                    name: "kind",
                    choices: &["halve", "subpatch"],
                },
            ));
        }
    };
    let m = match &kind {
        MatrixKind::Halve { m, .. } => *m,
        MatrixKind::Subpatch { vertices } => vertices.len() - 1,
    };
    // checked before `n + m` is formed: a huge degree must not wrap past the row limit
    if degree > MAX_DEGREE
        || crate::simplex::binomial(degree as u64 + m as u64, m as u64)
            > crate::blossom::MAX_MATRIX_ROWS as u128
    {
        return Err(inputs.error(
            "degree",
            ClaimProblem::MatrixTooLarge {
                limit: crate::blossom::MAX_MATRIX_ROWS,
            },
        ));
    }
    Ok(Construction::Matrix { degree, kind })
}

impl<'a> Construction<'a> {
    /// Parse the inputs of `name` (one of this module's operations).
    pub fn parse(inputs: &Inputs<'a>, name: OpName) -> Result<Self, InputError> {
        Ok(match name {
            OpName::Blossom => {
                let patch = polynomial_or_rational(inputs)?;
                let args = inputs.bary_points("args", simplex_m(&patch))?;
                Construction::Blossom { patch, args }
            }
            OpName::Subpatch => {
                let patch = polynomial_or_rational(inputs)?;
                let vertices = inputs.bary_points("vertices", simplex_m(&patch))?;
                Construction::Subpatch { patch, vertices }
            }
            OpName::Subdivide => {
                let patch = inputs.patch()?;
                let m = patch.net.m();
                let midpoints = inputs.opt_bool("midpoints")?.unwrap_or(false);
                let mode = match (inputs.opt_rationals("at")?, midpoints) {
                    (Some(t), false) => {
                        crate::domain::check_barycentric(&t, m, "point `at`")
                            .map_err(|e| inputs.error("at", e))?;
                        SubdivideMode::At(t)
                    }
                    (None, true) => SubdivideMode::Midpoints,
                    _ => {
                        return Err(inputs.error("at", ClaimProblem::AtOrMidpoints));
                    }
                };
                Construction::Subdivide { patch, mode }
            }
            OpName::Halve => {
                let patch = inputs.patch()?;
                let edge = inputs.edge(patch.net.m())?;
                let method = match inputs.opt_string("method")?.as_deref() {
                    None | Some("blossom") => HalveMethod::Blossom,
                    Some("add-and-halve") => HalveMethod::AddAndHalve(HalvingOrder::TopDown),
                    Some("add-and-halve-bottom-first") => {
                        HalveMethod::AddAndHalve(HalvingOrder::BottomFirst)
                    }
                    Some(other) => {
                        return Err(inputs.error(
                            "method",
                            ClaimProblem::NotOneOf {
                                text: other.to_string(),
                                choices: &[
                                    "blossom",
                                    "add-and-halve",
                                    "add-and-halve-bottom-first",
                                ],
                            },
                        ));
                    }
                };
                Construction::Halve {
                    patch,
                    edge,
                    method,
                }
            }
            OpName::Elevate => {
                let patch = inputs.patch()?;
                let (m, n) = (patch.net.m(), patch.net.degree());
                let by = inputs.opt_usize("by")?.unwrap_or(1);
                // checked sum: `by` near usize::MAX must not wrap below the limit
                let Some(to) = n.checked_add(by).filter(|&t| by > 0 && t <= MAX_DEGREE) else {
                    return Err(inputs.error(
                        "by",
                        ClaimProblem::ElevateBy {
                            most: MAX_DEGREE.saturating_sub(n),
                            limit: MAX_DEGREE,
                        },
                    ));
                };
                check_count(inputs, "by", m, to)?;
                Construction::Elevate { patch, by }
            }
            OpName::Matrix => parse_matrix(inputs)?,
            OpName::EdgeCurve => {
                let patch = inputs.patch()?;
                let m = patch.net.m();
                let corner = |name: &str| -> Result<usize, InputError> {
                    let k = inputs.opt_usize(name)?.ok_or_else(|| {
                        inputs.error(
                            name,
                            ClaimProblem::MissingCorner {
                                name: name.to_string(),
                                corners: m + 1,
                            },
                        )
                    })?;
                    if !(1..=m + 1).contains(&k) {
                        return Err(inputs.error(
                            name,
                            ClaimProblem::NoSuchCorner {
                                corner: k,
                                corners: m + 1,
                            },
                        ));
                    }
                    Ok(k - 1)
                };
                let (from, to) = (corner("from")?, corner("to")?);
                if from == to {
                    return Err(inputs.error("to", ClaimProblem::SameCorners));
                }
                Construction::EdgeCurve { patch, from, to }
            }
            // invariant: the caller dispatches only the construction operations here
            other => unreachable!("`{}` is not a construction", other.name()),
        })
    }

    /// The construction on the inputs as seen in precision `p` (module doc of `ops`).
    pub fn seen(
        &self,
        inputs: &Inputs<'_>,
        p: crate::float::Precision,
    ) -> Result<Self, InputError> {
        let patch = |x: &BezierPatch| seen::patch(inputs, x, p).map(Cow::Owned);
        Ok(match self {
            Construction::Blossom { patch: x, args } => Construction::Blossom {
                patch: Cow::Owned(seen::any_patch(inputs, x, p)?),
                args: seen::rows(inputs, "args", args, p)?,
            },
            Construction::Subpatch { patch: x, vertices } => Construction::Subpatch {
                patch: Cow::Owned(seen::any_patch(inputs, x, p)?),
                vertices: seen::rows(inputs, "vertices", vertices, p)?,
            },
            Construction::Subdivide { patch: x, mode } => Construction::Subdivide {
                patch: patch(x)?,
                mode: match mode {
                    SubdivideMode::At(t) => SubdivideMode::At(seen::numbers(inputs, "at", t, p)?),
                    SubdivideMode::Midpoints => SubdivideMode::Midpoints,
                },
            },
            Construction::Halve {
                patch: x,
                edge,
                method,
            } => Construction::Halve {
                patch: patch(x)?,
                edge: *edge,
                method: *method,
            },
            Construction::Elevate { patch: x, by } => Construction::Elevate {
                patch: patch(x)?,
                by: *by,
            },
            Construction::Matrix { degree, kind } => Construction::Matrix {
                degree: *degree,
                kind: match kind {
                    MatrixKind::Subpatch { vertices } => MatrixKind::Subpatch {
                        vertices: seen::rows(inputs, "vertices", vertices, p)?,
                    },
                    halve => halve.clone(),
                },
            },
            Construction::EdgeCurve { patch: x, from, to } => Construction::EdgeCurve {
                patch: patch(x)?,
                from: *from,
                to: *to,
            },
        })
    }

    /// The exact value.
    pub fn compute(&self, inputs: &Inputs<'_>) -> Result<Value, InputError> {
        use crate::subdivide::{add_and_halve, halve, midpoint_split, split_at_pieces};
        let pieces = |ps: Vec<crate::subdivide::Piece<Q>>| {
            Value::List(ps.iter().map(|p| net_value(&p.net)).collect())
        };
        Ok(match self {
            Construction::Blossom { patch, args } => match patch.as_ref() {
                AnyPatch::Rational(r) => {
                    Value::numbers(&r.blossom(args).map_err(|e| inputs.error("args", e))?)
                }
                other => {
                    // invariant: parsing refused kinds without a polynomial net for a blossom
                    let p = other.polynomial().expect("checked when parsed");
                    Value::numbers(
                        &crate::blossom::blossom(&p.net, args)
                            .map_err(|e| inputs.error("args", e))?,
                    )
                }
            },
            Construction::Subpatch { patch, vertices } => {
                let constructions =
                    // invariant: parsing refused kinds without constructions for a subpatch
                    crate::capability::constructions(patch).expect("checked when parsed");
                match constructions
                    .subpatch(vertices)
                    .map_err(|e| inputs.error("vertices", e))?
                {
                    // a rational subpatch (of the homogeneous net (w c, w)), with its place in
                    // the parent
                    AnyPatch::Rational(sub) => Value::Map(vec![
                        ("control_points".into(), net_value(&sub.patch.net)),
                        (
                            "weights".into(),
                            keyed(
                                sub.patch.net.simplex(),
                                sub.weights.iter().cloned().map(Value::Number),
                            ),
                        ),
                        (
                            "domain_in_parent".into(),
                            Value::List(vertices.iter().map(|v| Value::numbers(v)).collect()),
                        ),
                    ]),
                    // invariant: the rational kind is matched above; parsing refused kinds without a polynomial net
                    other => net_value(&other.polynomial().expect("a polynomial kind").net),
                }
            }
            Construction::Subdivide { patch, mode } => match mode {
                SubdivideMode::At(t) => {
                    pieces(split_at_pieces(&patch.net, t).map_err(|e| inputs.error("at", e))?)
                }
                SubdivideMode::Midpoints => {
                    pieces(midpoint_split(&patch.net).map_err(|e| inputs.error("midpoints", e))?)
                }
            },
            Construction::Halve {
                patch,
                edge: (i, j),
                method,
            } => match method {
                HalveMethod::Blossom => pieces(halve(&patch.net, *i, *j).to_vec()),
                HalveMethod::AddAndHalve(order) => Value::List(vec![
                    net_value(&add_and_halve(&patch.net, *i, *j, *order)),
                    net_value(&add_and_halve(&patch.net, *j, *i, *order)),
                ]),
            },
            Construction::Elevate { patch, by } => {
                net_value(&crate::elevate::elevate(&patch.net, *by))
            }
            Construction::Matrix { degree, kind } => {
                let (m, f) = match kind {
                    MatrixKind::Halve { m, edge, piece } => {
                        let [a, b] = crate::subdivide::halve_domains(*m, edge.0, edge.1);
                        (*m, if *piece == 1 { a } else { b })
                    }
                    MatrixKind::Subpatch { vertices } => (vertices.len() - 1, vertices.clone()),
                };
                let rows = crate::blossom::subpatch_matrix(m, *degree, &f)
                    .map_err(|e| inputs.error("vertices", e))?;
                Value::List(rows.iter().map(|r| Value::numbers(r)).collect())
            }
            Construction::EdgeCurve { patch, from, to } => {
                let face = patch.net.face(&[*from, *to]);
                Value::List(face.points().map(Value::numbers).collect())
            }
        })
    }
}
