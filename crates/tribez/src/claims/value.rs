//! Values that claims are about, and their comparison.
//!
//! An operation computes an exact [`Value`]: a number, a polynomial, a boolean, a list or a
//! keyed map of those. The claimed value is read from the file guided by the shape of the exact
//! one, and compared leaf by leaf.

use num_rational::BigRational;

use crate::certify::measures::{Leaf, Measures, Tolerance, ToleranceNeeds};
use crate::symbolic::Polynomial;

/// An exact (or claimed) value.
#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    /// An exact rational.
    Number(BigRational),
    /// A polynomial, with its variable names.
    Poly(Polynomial, Vec<String>),
    /// A yes/no verdict (e.g. "the pair is C1").
    Bool(bool),
    /// An integer count or order (e.g. the highest r with C^r).
    Integer(i64),
    /// A list (points, rows, …).
    List(Vec<Value>),
    /// Keyed entries (control points by multi-index, named fields).
    Map(Vec<(String, Value)>),
}

impl Value {
    /// A list of numbers.
    pub fn numbers(xs: &[BigRational]) -> Self {
        Value::List(xs.iter().cloned().map(Value::Number).collect())
    }

    /// Compact text: numbers in lowest terms, polynomials as text, lists in brackets.
    pub fn to_text(&self) -> String {
        match self {
            Value::Number(q) => q.to_string(),
            Value::Poly(p, names) => {
                p.to_text(&names.iter().map(String::as_str).collect::<Vec<_>>())
            }
            Value::Bool(b) => b.to_string(),
            Value::Integer(i) => i.to_string(),
            Value::List(xs) => format!(
                "[{}]",
                xs.iter().map(Value::to_text).collect::<Vec<_>>().join(", ")
            ),
            Value::Map(kv) => format!(
                "{{{}}}",
                kv.iter()
                    .map(|(k, v)| format!("{k}: {}", v.to_text()))
                    .collect::<Vec<_>>()
                    .join(", ")
            ),
        }
    }

    /// JSON with exact numbers as strings.
    pub fn to_json(&self) -> serde_json::Value {
        use serde_json::Value as J;
        match self {
            Value::Number(q) => J::String(q.to_string()),
            Value::Poly(..) => J::String(self.to_text()),
            Value::Bool(b) => J::Bool(*b),
            Value::Integer(i) => J::from(*i),
            Value::List(xs) => J::Array(xs.iter().map(Value::to_json).collect()),
            Value::Map(kv) => J::Object(kv.iter().map(|(k, v)| (k.clone(), v.to_json())).collect()),
        }
    }
}

/// A disagreement at one leaf of a value.
#[derive(Clone, Debug, PartialEq)]
pub struct Mismatch {
    /// Where, e.g. `[2]` or `"1,1,0"[0]`.
    pub path: String,
    /// The claimed leaf, as text.
    pub claimed: String,
    /// The exact leaf, as text.
    pub exact: String,
    /// Why it is not accepted (the difference, or the broken tolerance).
    pub reason: String,
}

/// Compare two values exactly; collect every mismatching leaf.
pub fn compare_exact(claimed: &Value, exact: &Value, path: &str, out: &mut Vec<Mismatch>) {
    compare(
        claimed,
        exact,
        &Tolerance::Exact,
        &|_| Leaf::default(),
        &mut 0,
        path,
        out,
        // invariant: the exact tolerance needs no condition number or bound
    )
    .expect("the exact tolerance needs nothing");
}

/// Compare two values leaf by leaf under a tolerance; collect every leaf it rejects.
///
/// Numbers are judged by [`Tolerance::accepts`] (`exact` is simply the tolerance that accepts
/// no difference); `leaf(k)` gives what the tolerance may need at the `k`-th number (in
/// traversal order: the precision, the condition number, the algorithm's bound). Polynomials,
/// booleans and integers are always compared exactly. `Err` when the tolerance cannot apply.
pub fn compare(
    claimed: &Value,
    exact: &Value,
    tolerance: &Tolerance,
    leaf: &dyn Fn(usize) -> Leaf,
    counter: &mut usize,
    path: &str,
    out: &mut Vec<Mismatch>,
) -> Result<(), ToleranceNeeds> {
    let mismatch = |reason: String| Mismatch {
        path: path.into(),
        claimed: claimed.to_text(),
        exact: exact.to_text(),
        reason,
    };
    match (claimed, exact) {
        (Value::List(a), Value::List(b)) if a.len() == b.len() => {
            for (i, (x, y)) in a.iter().zip(b).enumerate() {
                compare(x, y, tolerance, leaf, counter, &format!("{path}[{i}]"), out)?;
            }
        }
        (Value::Map(a), Value::Map(b))
            if a.len() == b.len() && b.iter().all(|(k, _)| a.iter().any(|(j, _)| j == k)) =>
        {
            // Keys are matched by name: a file may list them in any order.
            for (k, y) in b {
                // invariant: the guard checked that every key of b is in a
                let x = &a.iter().find(|(j, _)| j == k).expect("checked above").1;
                compare(
                    x,
                    y,
                    tolerance,
                    leaf,
                    counter,
                    &format!("{path}.\"{k}\""),
                    out,
                )?;
            }
        }
        (Value::List(a), Value::List(b)) => out.push(mismatch(format!(
            "{} values claimed, {} exact",
            a.len(),
            b.len()
        ))),
        (Value::Map(_), Value::Map(_)) => out.push(mismatch(
            "the claimed keys differ from the exact ones".into(),
        )),
        (Value::Number(a), Value::Number(b)) => {
            let l = leaf(*counter);
            *counter += 1;
            if !tolerance.accepts(a, b, &l)? {
                out.push(mismatch(match tolerance {
                    Tolerance::Exact => format!("differs by {}", crate::number::q_sub(a, b)),
                    t => format!(
                        "breaks tolerance `{t}`: {}",
                        Measures::new(a, b, l.precision).text()
                    ),
                }));
            }
        }
        (Value::Poly(a, names), Value::Poly(b, _)) if a != b => {
            let n: Vec<&str> = names.iter().map(String::as_str).collect();
            out.push(mismatch(format!(
                "claimed − exact = {}",
                a.sub(b).to_text(&n)
            )));
        }
        (a, b) if a == b => {}
        (Value::Bool(_), Value::Bool(_)) | (Value::Integer(_), Value::Integer(_)) => {
            out.push(mismatch("differs".into()))
        }
        _ => out.push(mismatch("the claimed value has a different kind".into())),
    }
    Ok(())
}

/// Replace every number of `v` by the exact value of the float of precision `p` nearest it
/// (`None` if some number overflows).
pub fn round_numbers(v: &Value, p: crate::float::Precision) -> Option<Value> {
    Some(match v {
        Value::Number(q) => Value::Number(crate::certify::measures::as_float(q, p)?),
        Value::List(xs) => Value::List(
            xs.iter()
                .map(|x| round_numbers(x, p))
                .collect::<Option<_>>()?,
        ),
        Value::Map(kv) => Value::Map(
            kv.iter()
                .map(|(k, x)| round_numbers(x, p).map(|y| (k.clone(), y)))
                .collect::<Option<_>>()?,
        ),
        other => other.clone(),
    })
}
