//! `join`: smoothness of two named patches across their common domain edge
//! ([`crate::join::analyse`], docs/theory.md §8).

use std::borrow::Cow;

use super::inputs::{Inputs, select_part};
use super::{Value, seen};
use crate::io::patch_file::index_key;
use crate::io::{ClaimProblem, InputError};
use crate::patch::BezierPatch;

/// `join` with its parsed inputs.
#[derive(Clone, Debug)]
pub struct JoinOp<'a> {
    /// The first patch (A) and its name under `[patches]`.
    pub a: Cow<'a, BezierPatch>,
    /// The second patch (B).
    pub b: Cow<'a, BezierPatch>,
    /// The part of the analysis claimed, if one.
    pub part: Option<String>,
}

impl<'a> JoinOp<'a> {
    /// Parse `patches = ["a", "b"]` (names under `[patches]`, polynomial patches) and `part`.
    pub fn parse(inputs: &Inputs<'a>) -> Result<Self, InputError> {
        let names = inputs.opt_strings("patches")?.ok_or_else(|| {
            inputs.error(
                "patches",
                ClaimProblem::MissingInput {
                    name: "patches".into(),
                    hint: Some("two names under [patches]"),
                },
            )
        })?;
        if names.len() != 2 {
            return Err(inputs.error("patches", ClaimProblem::JoinCount { named: names.len() }));
        }
        let find = |name: &str| -> Result<&'a BezierPatch, InputError> {
            let any = inputs
                .file
                .patches
                .iter()
                .find(|(n, _)| n == name)
                .map(|(_, p)| p.as_any())
                .ok_or_else(|| {
                    inputs.error(
                        "patches",
                        ClaimProblem::NoSuchPatch {
                            name: name.to_string(),
                        },
                    )
                })?;
            any.polynomial().ok_or_else(|| {
                inputs.error(
                    "patches",
                    ClaimProblem::JoinKind {
                        kind: any.kind_name(),
                        name: name.to_string(),
                    },
                )
            })
        };
        Ok(JoinOp {
            a: Cow::Borrowed(find(&names[0])?),
            b: Cow::Borrowed(find(&names[1])?),
            part: inputs.part()?,
        })
    }

    /// Both patches as seen in precision `p`.
    pub fn seen(
        &self,
        inputs: &Inputs<'_>,
        p: crate::float::Precision,
    ) -> Result<Self, InputError> {
        Ok(JoinOp {
            a: Cow::Owned(seen::patch(inputs, &self.a, p)?),
            b: Cow::Owned(seen::patch(inputs, &self.b, p)?),
            part: self.part.clone(),
        })
    }

    /// `{c0, c1, max_smoothness, mu, g1?, coplanarity?, g1_determinant?, violations}` (or the
    /// claimed part). Violations are keyed `"C1 1,0,1"` (row ρ at B's index, the difference)
    /// and `"coplanarity 0,1,1"` (the volume).
    pub fn compute(&self, inputs: &Inputs<'_>) -> Result<Value, InputError> {
        let j = crate::join::analyse(&self.a, &self.b).map_err(|e| inputs.error("patches", e))?;
        let mut kv = vec![
            ("c0".to_string(), Value::Bool(j.c0)),
            ("c1".to_string(), Value::Bool(j.c1)),
            (
                "max_smoothness".to_string(),
                Value::Integer(j.max_smoothness),
            ),
            ("mu".to_string(), Value::numbers(&j.mu)),
        ];
        if let Some(g) = j.g1 {
            kv.push(("g1".into(), Value::Bool(g)));
        }
        if let Some(c) = j.coplanarity {
            kv.push(("coplanarity".into(), Value::Bool(c)));
        }
        if j.g1_minors.len() == 1 {
            kv.push((
                "g1_determinant".into(),
                Value::Poly(j.g1_minors[0].clone(), vec!["t".into()]),
            ));
        }
        let mut viol = Vec::new();
        for v in &j.violations {
            match v {
                crate::join::Violation::Row {
                    rho,
                    index,
                    difference,
                    ..
                } => viol.push((
                    format!("C{rho} {}", index_key(index)),
                    Value::numbers(difference),
                )),
                crate::join::Violation::Coplanarity { index, volume, .. } => viol.push((
                    format!("coplanarity {}", index_key(index)),
                    Value::Number(volume.clone()),
                )),
                crate::join::Violation::G1 { .. } => {}
            }
        }
        kv.push(("violations".into(), Value::Map(viol)));
        select_part(inputs, self.part.as_deref(), Value::Map(kv))
    }
}
