//! Reading a claim's claimed value (`expect`), guided by the shape of the exact value.

use num_rational::BigRational;

use super::Value;
use crate::io::tree::{Document, Node, Value as NodeValue};
use crate::io::{ClaimProblem, InputError};
use crate::symbolic::Polynomial;

/// Read the claimed value at `node`, guided by the shape of the exact value.
pub fn read_claimed(
    doc: &Document,
    node: &Node,
    exact: &Value,
    key: &str,
) -> Result<Value, InputError> {
    Ok(match (exact, &node.value) {
        (Value::Number(_), _) => Value::Number(doc.rational(node, key)?),
        (Value::Poly(_, names), NodeValue::String(s) | NodeValue::Number(s)) => {
            let n: Vec<&str> = names.iter().map(String::as_str).collect();
            let p = Polynomial::parse(s, &n).map_err(|reason| {
                doc.error(
                    node,
                    key,
                    ClaimProblem::BadPolynomial {
                        text: s.clone(),
                        reason,
                    },
                )
            })?;
            Value::Poly(p, names.clone())
        }
        (Value::Bool(_), NodeValue::Bool(b)) => Value::Bool(*b),
        (Value::Integer(_), NodeValue::Number(t)) => {
            Value::Integer(t.parse().map_err(|_| {
                doc.error(node, key, ClaimProblem::NotAnInteger { text: t.clone() })
            })?)
        }
        (Value::List(xs), NodeValue::Array(items)) => {
            let fallback = xs
                .first()
                .cloned()
                .unwrap_or(Value::Number(BigRational::default()));
            Value::List(
                items
                    .iter()
                    .enumerate()
                    .map(|(i, it)| {
                        read_claimed(
                            doc,
                            it,
                            xs.get(i).unwrap_or(&fallback),
                            &format!("{key}[{i}]"),
                        )
                    })
                    .collect::<Result<_, _>>()?,
            )
        }
        (Value::Map(kv), NodeValue::Table(items)) => Value::Map(
            items
                .iter()
                .map(|(k, it)| {
                    let like = kv
                        .iter()
                        .find(|(ek, _)| ek == k)
                        .map(|(_, v)| v)
                        .or_else(|| kv.first().map(|(_, v)| v));
                    let like =
                        like.ok_or_else(|| doc.error(it, key, ClaimProblem::UnexpectedKey))?;
                    Ok((
                        k.clone(),
                        read_claimed(doc, it, like, &format!("{key}.\"{k}\""))?,
                    ))
                })
                .collect::<Result<_, InputError>>()?,
        ),
        (want, _) => {
            let kind = match want {
                Value::Poly(..) => "a polynomial (string)",
                Value::Bool(_) => "true or false",
                Value::Integer(_) => "an integer",
                Value::List(_) => "an array",
                Value::Map(_) => "a table",
                Value::Number(_) => "a number",
            };
            return Err(doc.error(
                node,
                key,
                ClaimProblem::ClaimedShape {
                    expected: kind,
                    found: node.value.kind(),
                },
            ));
        }
    })
}
