//! `intersect`, `locate` and `ray` claims: parameters that another implementation claims for an
//! inverse problem, judged against the exact answer (real algebraic numbers, docs/theory.md
//! §16).
//!
//! ```toml
//! [patches]
//! a = "cubic_a.toml"
//! b = "cubic_b.toml"
//!
//! [[claim]]
//! op = "intersect"
//! patches = ["a", "b"]                  # two planar curves (m = 1, d = 2)
//! expect = [["0.5", "0.5"], ["0.01667137744899777", "0.01667137744899777"]]   # (s, t) pairs
//! precision = "f64"
//! tolerance = "ulps=4"
//!
//! [[claim]]
//! op = "locate"
//! patch = "tri"                         # a planar triangle patch (m = 2, d = 2)
//! point = ["1", "1"]
//! expect = [["0.22938350177230987", "0.30306699912009033"]]   # (s, t) pairs
//!
//! [[claim]]
//! op = "ray"
//! patch = "surface"                     # a triangle patch in ℝ³, or a functional patch
//! origin = ["1/5", "1/5", "3"]
//! direction = ["1/10", "1/20", "-1"]
//! expect = [["2.5", "0.2", "0.3"]]      # (τ, s, t) triples
//!
//! [[claim]]
//! op = "ray"
//! patch = "hill"                        # a functional patch over a triangle
//! height = ["1/4", "1/4"]               # the vertical line through (x, y): the data lookup
//! expect = [["0.625", "0.25", "0.25"]]  # (z, s, t): the height f(x, y), (x, y)'s parameters
//! ```
//!
//! `expect` is a list of parameter tuples (its length is the claimed count; `[]` claims there is
//! none) or a bare integer (a claimed count only). Tuples may come in any order. A claimed tuple
//! and an exact solution *accept* each other when every coordinate lies within [`MATCH_RADIUS`]
//! of the solution's (relative to the value's size above 1) and the claim's tolerance accepts
//! every coordinate against the algebraic value itself (enclosures narrowed until both ends get
//! the same verdict; the tolerances' acceptance sets are intervals, so the verdict is the
//! algebraic value's). The claim holds when there is a perfect matching of this bipartite
//! relation: every claimed tuple paired with a distinct exact solution that accepts it, and
//! every solution paired (so the counts agree). It is found by Hopcroft and Karp's maximum
//! matching ([`findings`]), not greedily: with roots 1/2 and 1/2 + 2e-7, the claim
//! (0.50000011, 0.5000003) holds at `abs=1.5e-7` although both claims are nearest the second root.
//! When there is none, what a maximum matching leaves unpaired is reported:
//!
//! * an unpaired tuple is compared with the nearest unpaired solution within the radius, and the
//!   coordinates that break the tolerance are shown; where some solutions accept it but every
//!   pairing gives them to other tuples, the message names that Hall violator (tuples accepted,
//!   together, by fewer solutions than there are tuples);
//! * an exact solution left unpaired is *missed*: the message shows it exactly (its
//!   polynomial, isolating interval and decimal value);
//! * a tuple with no unpaired solution within the radius is *extra*;
//! * curves that share a piece, and points that a whole curve of parameters maps to, cannot be
//!   claimed as points: the claim fails and says so.
//!
//! With `precision`, every number of the claim denotes the float nearest its text, and the exact
//! answer is that of the inputs as the float code saw them (patches and query rounded).

use std::borrow::Cow;

use num_rational::BigRational;
use num_traits::Zero;

use super::super::value::{Mismatch, Value};
use super::super::{Claim, ClaimFile, Judged, Verdict};
use super::inputs::Inputs;
use super::seen;
use crate::algebraic::{AlgebraicError, Curve};
use crate::any_patch::AnyPatch;
use crate::certify::measures::{Tolerance, ToleranceNeeds};
use crate::float::Precision;
use crate::io::tree::{Document, Value as NodeValue};
use crate::io::{ClaimProblem, InputError, InverseProblem};
use crate::judge_inverse;
pub use crate::judge_inverse::{
    Blocked, ExactNumber, InverseAnswer, InverseFinding, InverseQuery, MATCH_RADIUS,
    MATCH_RADIUS_LOG2, MAX_CLAIMED, accepts, findings,
};
use crate::patch_type::Patch;

type Q = BigRational;

/// An `intersect`, `locate` or `ray` claim's operation with its parsed inputs.
#[derive(Clone, Debug)]
pub struct InverseOp<'a> {
    /// The query.
    pub query: InverseQuery<'a>,
}

impl<'a> InverseOp<'a> {
    /// Parse the inputs of `intersect` (`patches`), `locate` (`point`, `anywhere`) or `ray`
    /// (`origin`, `direction`).
    pub fn parse(inputs: &Inputs<'a>, name: super::OpName) -> Result<Self, InputError> {
        use super::OpName as N;
        let query = match name {
            N::Intersect => {
                let names = inputs.opt_strings("patches")?.ok_or_else(|| {
                    inputs.error(
                        "patches",
                        ClaimProblem::MissingInput {
                            name: "patches".into(),
                            hint: Some("two curve names under [patches]"),
                        },
                    )
                })?;
                let [na, nb]: [String; 2] = names.try_into().map_err(|v: Vec<String>| {
                    inputs.error("patches", InverseProblem::CurveCount { named: v.len() })
                })?;
                let find = |name: &str| -> Result<&'a Patch, InputError> {
                    inputs
                        .file
                        .patches
                        .iter()
                        .find(|(n, _)| n == name)
                        .map(|(_, p)| p)
                        .ok_or_else(|| {
                            inputs.error(
                                "patches",
                                ClaimProblem::NoSuchPatch {
                                    name: name.to_string(),
                                },
                            )
                        })
                };
                let (a, b) = (find(&na)?, find(&nb)?);
                for (p, n) in [(a, &na), (b, &nb)] {
                    Curve::from_patch(p, n)
                        .map_err(|e| inputs.error("patches", InverseProblem::from(e)))?;
                }
                InverseQuery::Intersect {
                    names: [na, nb],
                    a: Cow::Borrowed(a),
                    b: Cow::Borrowed(b),
                }
            }
            N::Locate => {
                let point = fixed::<2>(inputs, "point")?;
                InverseQuery::Locate {
                    patch: Cow::Borrowed(inputs.file.patch_for(inputs.claim)?),
                    point,
                    anywhere: inputs.opt_bool("anywhere")?.unwrap_or(false),
                }
            }
            _ if inputs.get("height").is_some() => {
                if let Some(k) = ["origin", "direction"]
                    .into_iter()
                    .find(|k| inputs.get(k).is_some())
                {
                    return Err(inputs.error(k, InverseProblem::HeightAndRay));
                }
                let at = fixed::<2>(inputs, "height")?;
                let patch = inputs.file.patch_for(inputs.claim)?;
                match patch.as_any() {
                    AnyPatch::Functional(f) if f.net.m() == 2 => {}
                    other => {
                        return Err(inputs.error(
                            "height",
                            InverseProblem::HeightNotFunctional {
                                what: other.described().to_string(),
                            },
                        ));
                    }
                }
                InverseQuery::Height {
                    patch: Cow::Borrowed(patch),
                    at,
                }
            }
            _ => {
                let origin = fixed::<3>(inputs, "origin")?;
                let direction = fixed::<3>(inputs, "direction")?;
                if direction.iter().all(Zero::is_zero) {
                    return Err(inputs.error("direction", InverseProblem::ZeroDirection));
                }
                InverseQuery::Ray {
                    patch: Cow::Borrowed(inputs.file.patch_for(inputs.claim)?),
                    origin,
                    direction,
                }
            }
        };
        Ok(InverseOp { query })
    }

    /// The same query on the inputs as the float code saw them (patches and numbers rounded).
    pub fn seen(&self, inputs: &Inputs<'_>, p: Precision) -> Result<Self, InputError> {
        let patch = |x: &Patch| -> Result<Cow<'a, Patch>, InputError> {
            seen::any_patch(inputs, x.as_any(), p).map(|a| Cow::Owned(Patch::from(a)))
        };
        let nums = |key: &str, xs: &[Q]| seen::numbers(inputs, key, xs, p);
        let query = match &self.query {
            InverseQuery::Intersect { names, a, b } => InverseQuery::Intersect {
                names: names.clone(),
                a: patch(a)?,
                b: patch(b)?,
            },
            InverseQuery::Locate {
                patch: x,
                point,
                anywhere,
            } => InverseQuery::Locate {
                patch: patch(x)?,
                point: to_array(nums("point", point)?),
                anywhere: *anywhere,
            },
            InverseQuery::Ray {
                patch: x,
                origin,
                direction,
            } => InverseQuery::Ray {
                patch: patch(x)?,
                origin: to_array(nums("origin", origin)?),
                direction: to_array(nums("direction", direction)?),
            },
            InverseQuery::Height { patch: x, at } => InverseQuery::Height {
                patch: patch(x)?,
                at: to_array(nums("height", at)?),
            },
        };
        Ok(InverseOp { query })
    }

    /// The exact answer ([`InverseQuery::answer`]).
    pub fn answer(&self) -> Result<InverseAnswer, AlgebraicError> {
        self.query.answer()
    }

    /// The exact value as a claim [`Value`]: `{count, solutions}` with every coordinate exact
    /// when rational, else its nearest `f64` (the mismatches of a judged claim give irrational
    /// coordinates exactly).
    pub fn compute(&self, inputs: &Inputs<'_>) -> Result<Value, InputError> {
        let answer = self
            .answer()
            .map_err(|e| inputs.error("op", InverseProblem::from(e)))?;
        Ok(answer_value(&answer))
    }
}

fn answer_value(answer: &InverseAnswer) -> Value {
    let num = |x: &ExactNumber| -> Value {
        Value::Number(x.rational().unwrap_or_else(|| {
            crate::number::exact_f64(x.to_f64()).unwrap_or_else(BigRational::zero)
        }))
    };
    Value::Map(vec![
        (
            "count".into(),
            Value::Integer(i64::try_from(answer.solutions.len()).unwrap_or(i64::MAX)),
        ),
        (
            "solutions".into(),
            Value::List(
                answer
                    .solutions
                    .iter()
                    .map(|s| Value::List(s.iter().map(num).collect()))
                    .collect(),
            ),
        ),
    ])
}

fn to_array<const N: usize>(v: Vec<Q>) -> [Q; N] {
    // invariant: tuple lengths are checked when the claim is parsed
    v.try_into()
        .unwrap_or_else(|_| unreachable!("lengths checked at parsing"))
}

/// A required list of exactly `N` rationals.
fn fixed<const N: usize>(inputs: &Inputs<'_>, name: &str) -> Result<[Q; N], InputError> {
    let v = inputs.rationals(name)?;
    let n = v.len();
    v.try_into().map_err(|_| {
        inputs.error(
            name,
            crate::io::Problem::FieldCount {
                found: n,
                expected: N,
            },
        )
    })
}

/// What the claim says: tuples, or a bare count.
enum Claimed {
    Tuples(Vec<Vec<Q>>),
    Count(usize),
}

fn read_claimed(
    file: &ClaimFile,
    claim: &Claim,
    names: &'static str,
    precision: Option<Precision>,
) -> Result<Claimed, InputError> {
    let width = names.split(", ").count();
    let doc = &file.doc;
    let t = doc.table(&claim.node, &claim.id)?;
    let key = format!("{}.expect", claim.id);
    let expect = Document::get(t, "expect")
        .ok_or_else(|| doc.error(&claim.node, &claim.id, ClaimProblem::MissingExpect))?;
    if let NodeValue::Number(_) = &expect.value {
        return Ok(Claimed::Count(doc.usize(expect, &key)?));
    }
    let rows = doc.array(expect, &key)?;
    if rows.len() > MAX_CLAIMED {
        return Err(doc.error(
            expect,
            &key,
            InverseProblem::TooManyClaimed {
                count: rows.len(),
                limit: MAX_CLAIMED,
            },
        ));
    }
    let mut out = Vec::with_capacity(rows.len());
    for (i, n) in rows.iter().enumerate() {
        let k = format!("{key}[{i}]");
        let mut xs = doc.rationals(n, &k)?;
        if xs.len() != width {
            return Err(doc.error(
                n,
                &k,
                InverseProblem::TupleWidth {
                    found: xs.len(),
                    expected: width,
                    names,
                },
            ));
        }
        if let Some(p) = precision {
            xs = xs
                .iter()
                .map(|x| crate::certify::measures::as_float(x, p))
                .collect::<Option<Vec<_>>>()
                .ok_or_else(|| {
                    doc.error(
                        n,
                        &k,
                        crate::io::Problem::Overflows {
                            what: "a claimed parameter",
                            precision: p,
                        },
                    )
                })?;
        }
        out.push(xs);
    }
    Ok(Claimed::Tuples(out))
}

/// Judge claimed tuples (or, with `claimed_tuples` `None`, a bare claimed count) against the
/// exact answer: every finding with its mismatch (the exact solution shown in full). What an
/// inverse claim ([`judge`]) and a row of an inverse batch ([`crate::batch::inverse`]) both
/// judge by. `Err` when the tolerance needs what an inverse answer lacks (`cond`,
/// `bound`).
pub fn judge_answer(
    claimed_tuples: Option<&[Vec<Q>]>,
    claimed_count: usize,
    answer: &InverseAnswer,
    tolerance: &Tolerance,
    precision: Option<Precision>,
) -> Result<Vec<(InverseFinding, Mismatch)>, ToleranceNeeds> {
    let found =
        judge_inverse::judge_answer(claimed_tuples, claimed_count, answer, tolerance, precision)?;
    Ok(found
        .into_iter()
        .map(|(f, t)| {
            let m = Mismatch {
                path: t.path,
                claimed: t.claimed,
                exact: t.exact,
                reason: t.reason,
            };
            (f, m)
        })
        .collect())
}

/// Judge an inverse claim (called by [`ClaimFile::judge`] for `intersect`, `locate`, `ray`).
pub fn judge(
    file: &ClaimFile,
    claim: &Claim,
    inputs: &Inputs<'_>,
    op: &InverseOp<'_>,
) -> Result<Judged, InputError> {
    let (tolerance, precision) = file.tolerance_of(claim)?;
    let seen_op;
    let op = match precision {
        Some(p) => {
            seen_op = op.seen(inputs, p)?;
            &seen_op
        }
        None => op,
    };
    let answer = op
        .answer()
        .map_err(|e| inputs.error("op", InverseProblem::from(e)))?;
    let names = match answer.names {
        ["z", ..] => "z, s, t",
        [_, _, _] => "tau, s, t",
        _ => "s, t",
    };
    let claimed = read_claimed(file, claim, names, precision)?;
    let (tuples, count) = match &claimed {
        Claimed::Tuples(t) => (Some(t.as_slice()), t.len()),
        Claimed::Count(n) => (None, *n),
    };
    let mismatches: Vec<Mismatch> = judge_answer(tuples, count, &answer, &tolerance, precision)
        .map_err(|e| inputs.error("tolerance", e))?
        .into_iter()
        .map(|(_, m)| m)
        .collect();
    let claimed_value = match &claimed {
        Claimed::Tuples(t) => Value::Map(vec![
            (
                "count".into(),
                Value::Integer(i64::try_from(t.len()).unwrap_or(i64::MAX)),
            ),
            (
                "solutions".into(),
                Value::List(t.iter().map(|x| Value::numbers(x)).collect()),
            ),
        ]),
        Claimed::Count(n) => Value::Integer(i64::try_from(*n).unwrap_or(i64::MAX)),
    };
    let verdict = Verdict::of(mismatches, claim.erratum.is_some());
    Ok(Judged {
        file: file.path.display().to_string(),
        id: claim.id.clone(),
        op: claim.op.clone(),
        source: claim.source.clone().or_else(|| file.source.clone()),
        erratum: claim.erratum.clone(),
        exact: answer_value(&answer),
        claimed: claimed_value,
        verdict,
        tolerance,
        precision,
        floats: Vec::new(),
    })
}
