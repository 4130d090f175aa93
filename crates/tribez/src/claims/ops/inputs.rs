//! Typed, located access to one claim's inputs: every reader names the claim and key in its
//! error ([`Inputs::error`]: `file:line: id.key: what is wrong`).

use std::borrow::Cow;

use num_rational::BigRational;

use super::super::{Claim, ClaimFile};
use crate::any_patch::AnyPatch;
use crate::capability::InputSpace;
use crate::io::tree::{Document, Node, Value as NodeValue};
use crate::io::{ClaimProblem, InputError, Problem};
use crate::patch::BezierPatch;

type Q = BigRational;

/// Cartesian to barycentric coordinates.
type Convert<'c> = dyn Fn(&[Q]) -> Result<Vec<Q>, crate::error::CoreError> + 'c;

/// Typed access to one claim's inputs.
pub struct Inputs<'a> {
    /// The claim file.
    pub file: &'a ClaimFile,
    /// The claim.
    pub claim: &'a Claim,
    pub(super) table: &'a [(String, Node)],
}

/// A point of a patch's domain: barycentric (`at`, or converted from `cartesian`), with the
/// Cartesian text kept (a float program rounds the Cartesian point, not its conversion).
#[derive(Clone, Debug, PartialEq)]
pub struct Point {
    /// Barycentric coordinates (empty for an S-patch, whose points are Cartesian only).
    pub at: Vec<Q>,
    /// The Cartesian point, if the claim gave `cartesian`.
    pub cartesian: Option<Vec<Q>>,
}

impl Point {
    /// The point in the kind's own coordinates: barycentric, or Cartesian for an S-patch.
    pub fn input(&self) -> &[Q] {
        match &self.cartesian {
            Some(x) if self.at.is_empty() => x,
            _ => &self.at,
        }
    }

    /// The key the point was given under.
    pub fn key(&self) -> &'static str {
        if self.cartesian.is_some() {
            "cartesian"
        } else {
            "at"
        }
    }
}

impl<'a> Inputs<'a> {
    /// The inputs of `claim` (its table).
    pub fn new(file: &'a ClaimFile, claim: &'a Claim) -> Result<Self, InputError> {
        let table = file.doc.table(&claim.node, &claim.id)?;
        Ok(Inputs { file, claim, table })
    }

    /// `id.name`, the key errors name.
    pub fn key(&self, name: &str) -> String {
        format!("{}.{name}", self.claim.id)
    }

    /// The node of input `name`, if present.
    pub fn get(&self, name: &str) -> Option<&'a Node> {
        Document::get(self.table, name)
    }

    /// An error at this claim's input `name` (at the claim if the input is absent).
    pub fn error(&self, name: &str, problem: impl Into<Problem>) -> InputError {
        let node = self.get(name).unwrap_or(&self.claim.node);
        self.file.doc.error(node, &self.key(name), problem)
    }

    /// The error of a required input that is absent.
    pub fn missing(&self, name: &str) -> InputError {
        self.error(
            name,
            ClaimProblem::MissingInput {
                name: name.to_string(),
                hint: None,
            },
        )
    }

    /// A required input's node.
    pub fn required(&self, name: &str) -> Result<&'a Node, InputError> {
        self.get(name).ok_or_else(|| self.missing(name))
    }

    /// A required list of rationals.
    pub fn rationals(&self, name: &str) -> Result<Vec<Q>, InputError> {
        let node = self.required(name)?;
        self.file.doc.rationals(node, &self.key(name))
    }

    /// An optional list of rationals.
    pub fn opt_rationals(&self, name: &str) -> Result<Option<Vec<Q>>, InputError> {
        self.get(name).map(|_| self.rationals(name)).transpose()
    }

    /// An optional string.
    pub fn opt_string(&self, name: &str) -> Result<Option<String>, InputError> {
        self.get(name)
            .map(|n| self.file.doc.string(n, &self.key(name)).map(str::to_string))
            .transpose()
    }

    /// An optional non-negative integer.
    pub fn opt_usize(&self, name: &str) -> Result<Option<usize>, InputError> {
        self.get(name)
            .map(|n| self.file.doc.usize(n, &self.key(name)))
            .transpose()
    }

    /// A required non-negative integer (`what` completes "missing input `name`").
    pub fn usize(&self, name: &str) -> Result<usize, InputError> {
        self.opt_usize(name)?.ok_or_else(|| self.missing(name))
    }

    /// An optional boolean.
    pub fn opt_bool(&self, name: &str) -> Result<Option<bool>, InputError> {
        match self.get(name) {
            None => Ok(None),
            Some(n) => match &n.value {
                NodeValue::Bool(b) => Ok(Some(*b)),
                _ => Err(self.error(name, ClaimProblem::NotABool)),
            },
        }
    }

    /// An optional list of strings.
    pub fn opt_strings(&self, name: &str) -> Result<Option<Vec<String>>, InputError> {
        let Some(node) = self.get(name) else {
            return Ok(None);
        };
        let items = self.file.doc.array(node, &self.key(name))?;
        items
            .iter()
            .map(|n| self.file.doc.string(n, &self.key(name)).map(str::to_string))
            .collect::<Result<Vec<_>, _>>()
            .map(Some)
    }

    /// A list of lists of rationals (`dirs = [["1", "0", "-1"], …]`), empty if absent.
    pub fn rational_rows(&self, name: &str) -> Result<Vec<Vec<Q>>, InputError> {
        let Some(node) = self.get(name) else {
            return Ok(Vec::new());
        };
        let key = self.key(name);
        let items = self.file.doc.array(node, &key)?;
        items
            .iter()
            .enumerate()
            .map(|(i, n)| self.file.doc.rationals(n, &format!("{key}[{i}]")))
            .collect()
    }

    /// A required list of barycentric points (each with `m + 1` coordinates summing to one).
    pub fn bary_points(&self, name: &str, m: usize) -> Result<Vec<Vec<Q>>, InputError> {
        let node = self.required(name)?;
        let items = self.file.doc.array(node, &self.key(name))?;
        items
            .iter()
            .enumerate()
            .map(|(i, n)| {
                let key = format!("{}[{i}]", self.key(name));
                let p = self.file.doc.rationals(n, &key)?;
                crate::domain::check_barycentric(&p, m, "point")
                    .map_err(|e| self.file.doc.error(n, &key, e))?;
                Ok(p)
            })
            .collect()
    }

    /// The number of items of the array input `name` (0 if absent).
    pub fn array_len(&self, name: &str) -> Result<usize, InputError> {
        match self.get(name) {
            None => Ok(0),
            Some(node) => Ok(self.file.doc.array(node, &self.key(name))?.len()),
        }
    }

    /// The domain simplex of input `name` (`m + 1` Cartesian vertices).
    pub fn domain(&self, name: &str) -> Result<crate::domain::Domain, InputError> {
        let node = self.required(name)?;
        let key = self.key(name);
        let rows = self.file.doc.array(node, &key)?;
        crate::io::patch_file::domain(&self.file.doc, node, rows.len().saturating_sub(1), &key)
    }

    /// An edge `[I, J]` (corners numbered from 1), returned 0-based.
    pub fn edge(&self, m: usize) -> Result<(usize, usize), InputError> {
        let node = self.get("edge").ok_or_else(|| {
            self.error(
                "edge",
                ClaimProblem::MissingInput {
                    name: "edge".into(),
                    hint: Some("two corner numbers, like [1, 2]"),
                },
            )
        })?;
        let items = self.file.doc.array(node, &self.key("edge"))?;
        let nums = items
            .iter()
            .map(|n| self.file.doc.usize(n, &self.key("edge")))
            .collect::<Result<Vec<_>, _>>()?;
        match nums.as_slice() {
            [i, j] => crate::subdivide::check_edge(m, *i, *j).map_err(|e| self.error("edge", e)),
            _ => Err(self.error("edge", ClaimProblem::EdgeShape)),
        }
    }

    /// The claim's patch, of any kind, by its representation.
    pub fn any_patch(&self) -> Result<Cow<'a, AnyPatch>, InputError> {
        self.file
            .patch_for(self.claim)
            .map(|p| Cow::Borrowed(p.as_any()))
    }

    /// The claim's patch, which must be polynomial (Bézier or functional).
    pub fn patch(&self) -> Result<Cow<'a, BezierPatch>, InputError> {
        self.file.polynomial_for(self.claim).map(Cow::Borrowed)
    }

    /// A point of `patch`'s domain in its kind's coordinates ([`InputSpace`]): for a simplex
    /// as [`Inputs::point`]; for a polygon (an S-patch) a Cartesian point from `cartesian`.
    pub fn point_of(&self, patch: &crate::patch_type::Patch) -> Result<Point, InputError> {
        match patch.shape().input {
            InputSpace::Barycentric { m } => {
                self.point_in(m, &|x: &[Q]| patch.exact().cartesian_input(x))
            }
            InputSpace::Polygon { .. } => {
                if self.get("at").is_some() {
                    return Err(self.error(
                        "at",
                        ClaimProblem::CartesianOnly {
                            kind: patch.as_any().described(),
                        },
                    ));
                }
                Ok(Point {
                    at: Vec::new(),
                    cartesian: Some(self.rationals("cartesian")?),
                })
            }
        }
    }

    /// A barycentric point from `at` (checked to sum to one, except for float claims: what a
    /// float program uses need not), or a Cartesian one from `cartesian`.
    pub fn point(&self, patch: &BezierPatch) -> Result<Point, InputError> {
        let domain = patch.domain_or_reference();
        self.point_in(patch.net.m(), &|x: &[Q]| domain.barycentric(x))
    }

    /// [`Inputs::point`] over the `m`-simplex, `cartesian` converted by `convert`.
    fn point_in(&self, m: usize, convert: &Convert<'_>) -> Result<Point, InputError> {
        match (self.opt_rationals("at")?, self.opt_rationals("cartesian")?) {
            (Some(at), None) if self.get("precision").is_some() => {
                if at.len() != m + 1 {
                    return Err(self.error(
                        "at",
                        ClaimProblem::CoordinateCount {
                            found: at.len(),
                            expected: m + 1,
                        },
                    ));
                }
                Ok(Point {
                    at,
                    cartesian: None,
                })
            }
            (Some(at), None) => {
                crate::domain::check_barycentric(&at, m, "point `at`")
                    .map_err(|e| self.error("at", e))?;
                Ok(Point {
                    at,
                    cartesian: None,
                })
            }
            (None, Some(x)) => Ok(Point {
                at: convert(&x).map_err(|e| self.error("cartesian", e))?,
                cartesian: Some(x),
            }),
            _ => Err(self.error("at", ClaimProblem::AtOrCartesian)),
        }
    }

    /// Variable names: `names` if given (checked against the count), else `default`.
    pub fn names(&self, default: Vec<String>) -> Result<Vec<String>, InputError> {
        match self.opt_strings("names")? {
            Some(n) if n.len() != default.len() => Err(self.error(
                "names",
                ClaimProblem::VariableNames {
                    given: n.len(),
                    needed: default.len(),
                },
            )),
            Some(n) => Ok(n),
            None => Ok(default),
        }
    }

    /// An optional `part` of a map value.
    pub fn part(&self) -> Result<Option<String>, InputError> {
        self.opt_string("part")
    }
}

/// Select `part` of a map value (an error naming the parts available).
pub fn select_part(
    inputs: &Inputs<'_>,
    part: Option<&str>,
    value: super::Value,
) -> Result<super::Value, InputError> {
    let Some(part) = part else {
        return Ok(value);
    };
    let super::Value::Map(kv) = value else {
        return Ok(value);
    };
    let known: Vec<String> = kv.iter().map(|(k, _)| k.clone()).collect();
    kv.into_iter()
        .find(|(k, _)| k == part)
        .map(|(_, v)| v)
        .ok_or_else(|| {
            inputs.error(
                "part",
                ClaimProblem::UnknownPart {
                    part: part.to_string(),
                    known,
                },
            )
        })
}
