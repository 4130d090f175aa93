//! Tolerances and exact error measures.
//!
//! A claimed value `y` (for a float claim: the exact value of the float) is judged against the
//! exact value `q`:
//!
//! | tolerance | accepts when |
//! |---|---|
//! | `exact` | `y = q` |
//! | `ulps=N` | `|y − q| ≤ N · ulp_p(q)` (binade ulp of the claim's precision `p`, docs/theory.md §14.4) |
//! | `abs=E` | `|y − q| ≤ E` |
//! | `rel=E` | `|y − q| ≤ E · |q|` |
//! | `correctly_rounded` | `y = RN_p(q)` (nearest, ties to even) |
//! | `faithful` | `y` is one of the two floats of precision `p` bracketing `q` (`q` itself if it is one) |
//! | `cond=K` | `|y − q| ≤ K · ε_p · Σ_i |c_i| B_i(|λ|)` (ε_p = 2^-53 or 2^-24; the condition number of \[FR87\]) |
//! | `cond` | `cond=K` with `K = (m+1)·n` for a degree-`n` patch on the m-simplex ([`Tolerance::for_patch`]) |
//! | `bound` | `|y − q| ≤` the proven a-priori bound of the named algorithm ([`super::bound`]) |
//!
//! `exact` is the case `abs=0`: one comparison path for every tolerance.
//!
//! ```
//! use tribez::hazmat::certify::measures::{Tolerance, Leaf};
//! use tribez::hazmat::float::Precision;
//! use tribez::hazmat::number::{exact_f64, parse_rational as q};
//! let third = q("1/3").unwrap();
//! let y = exact_f64(1.0 / 3.0).unwrap();
//! let leaf = Leaf { precision: Some(Precision::F64), condition: None, bound: None };
//! assert!(Tolerance::parse("correctly_rounded").unwrap().accepts(&y, &third, &leaf).unwrap());
//! assert!(!Tolerance::parse("exact").unwrap().accepts(&y, &third, &leaf).unwrap());
//! assert!(Tolerance::parse("ulps=0.5").unwrap().accepts(&y, &third, &leaf).unwrap());
//! ```

use num_rational::BigRational;
use num_traits::{Signed, Zero};

use crate::float::Precision;
use crate::number::{
    NumberError, exact_f32, exact_f64, parse_rational, pow2, round_f32, round_f64, ulp_f32, ulp_f64,
};

/// What a claim accepts as agreement.
#[derive(Clone, Debug, PartialEq)]
pub enum Tolerance {
    /// Exactly equal (the default).
    Exact,
    /// At most `N` ulps of the claim's precision.
    Ulps(BigRational),
    /// Absolute error at most `E`.
    Abs(BigRational),
    /// Relative error at most `E`.
    Rel(BigRational),
    /// The nearest float (ties to even).
    CorrectlyRounded,
    /// One of the two bracketing floats.
    Faithful,
    /// At most `K · ε · Σ|c_i| B_i(|λ|)`.
    Cond(BigRational),
    /// `cond` without `K`: `Cond((m+1)·n)` once the patch is known ([`Tolerance::for_patch`]).
    CondDegree,
    /// Within the proven a-priori bound of the claim's algorithm.
    Bound,
}

/// The tolerance names, for messages.
pub const TOLERANCES: &str =
    "exact, ulps=N, abs=E, rel=E, correctly_rounded, faithful, cond=K, cond, bound";

/// Why a text is not a tolerance ([`Tolerance::from_str`](std::str::FromStr::from_str)).
/// `Display` is the one-line message the command line prints.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum ParseToleranceError {
    /// A name that takes a value written without one (`ulps`).
    #[error("tolerance `{text}` needs a value: `{name}=…`")]
    MissingValue {
        /// The text as written (trimmed).
        text: String,
        /// The tolerance's name.
        name: String,
    },
    /// The value after `=` is not an exact number.
    #[error("tolerance `{text}`: {error}")]
    Number {
        /// The text as written (trimmed).
        text: String,
        /// Why the value is not a number.
        error: NumberError,
    },
    /// A negative value.
    #[error("tolerance `{text}`: the value must not be negative")]
    Negative {
        /// The text as written (trimmed).
        text: String,
    },
    /// A value given to a tolerance without one (`exact=1`).
    #[error("tolerance `{name}` takes no value")]
    TakesNoValue {
        /// The tolerance's name.
        name: String,
    },
    /// No tolerance has this name.
    #[error("unknown tolerance `{text}` (known: {TOLERANCES})")]
    Unknown {
        /// The text as written (trimmed).
        text: String,
    },
}

/// What a tolerance lacks to judge a number ([`Tolerance::accepts`]).
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum ToleranceNeeds {
    /// A float tolerance without a precision.
    #[error("tolerance `{tolerance}` needs `precision` (f64 or f32)")]
    Precision {
        /// The tolerance as written.
        tolerance: String,
    },
    /// `cond=K` without a condition number.
    #[error("tolerance `cond` needs an evaluation claim (the condition number Σ|c_i|B_i)")]
    Condition,
    /// `cond` without `K` before [`Tolerance::for_patch`] gave it the patch's `K = (m+1)·n`.
    #[error("tolerance `cond` needs the patch's degree (K = (m+1)·n)")]
    Degree,
    /// `bound` without a proven bound.
    #[error(
        "tolerance `bound` needs an evaluation claim with an `algorithm` that has a proven bound"
    )]
    Bound,
}

/// Exactly the strings of the command line and of claim files: `exact`, `ulps=N`, `abs=E`,
/// `rel=E`, `correctly_rounded`, `faithful`, `cond=K`, `cond`, `bound` (surrounding whitespace
/// ignored). The number after `=` is exact (any syntax of [`crate::parse_rational`]) and
/// non-negative; [`Display`](std::fmt::Display) writes it back as `p/q`, and reading that gives
/// the same tolerance.
///
/// ```
/// use tribez::{Rational, Tolerance};
/// let t: Tolerance = "ulps=0.5".parse().unwrap();
/// assert_eq!(t, Tolerance::Ulps(Rational::new(1.into(), 2.into())));
/// assert_eq!(t.to_string(), "ulps=1/2");
/// assert_eq!(t.to_string().parse::<Tolerance>().unwrap(), t);
/// assert_eq!(" bound ".parse::<Tolerance>().unwrap(), Tolerance::Bound);
/// assert_eq!(
///     "ulps".parse::<Tolerance>().unwrap_err().to_string(),
///     "tolerance `ulps` needs a value: `ulps=…`"
/// );
/// assert_eq!(
///     "abs=-1".parse::<Tolerance>().unwrap_err().to_string(),
///     "tolerance `abs=-1`: the value must not be negative"
/// );
/// ```
impl std::str::FromStr for Tolerance {
    type Err = ParseToleranceError;

    fn from_str(text: &str) -> Result<Self, ParseToleranceError> {
        let t = text.trim();
        let (name, arg) = match t.split_once('=') {
            Some((n, a)) => (n.trim(), Some(a.trim())),
            None => (t, None),
        };
        let number = |a: Option<&str>| -> Result<BigRational, ParseToleranceError> {
            let a = a.ok_or_else(|| ParseToleranceError::MissingValue {
                text: t.into(),
                name: name.into(),
            })?;
            let q = parse_rational(a).map_err(|error| ParseToleranceError::Number {
                text: t.into(),
                error,
            })?;
            if q.is_negative() {
                return Err(ParseToleranceError::Negative { text: t.into() });
            }
            Ok(q)
        };
        let bare = |tol: Tolerance| {
            if arg.is_some() {
                Err(ParseToleranceError::TakesNoValue { name: name.into() })
            } else {
                Ok(tol)
            }
        };
        match name {
            "exact" => bare(Tolerance::Exact),
            "correctly_rounded" => bare(Tolerance::CorrectlyRounded),
            "faithful" => bare(Tolerance::Faithful),
            "bound" => bare(Tolerance::Bound),
            "ulps" => Ok(Tolerance::Ulps(number(arg)?)),
            "abs" => Ok(Tolerance::Abs(number(arg)?)),
            "rel" => Ok(Tolerance::Rel(number(arg)?)),
            "cond" if arg.is_none() => Ok(Tolerance::CondDegree),
            "cond" => Ok(Tolerance::Cond(number(arg)?)),
            _ => Err(ParseToleranceError::Unknown { text: t.into() }),
        }
    }
}

impl Tolerance {
    /// Parse `exact`, `ulps=2`, `abs=1e-12`, `rel=1e-9`, `correctly_rounded`, `faithful`,
    /// `cond=4`, `cond` or `bound` (the same as [`str::parse`]). The number after `=` is exact and
    /// non-negative.
    pub fn parse(text: &str) -> Result<Self, ParseToleranceError> {
        text.parse()
    }

    /// Does the tolerance need a precision (`f64`/`f32`) to mean anything?
    pub fn needs_precision(&self) -> bool {
        matches!(
            self,
            Tolerance::Ulps(_)
                | Tolerance::CorrectlyRounded
                | Tolerance::Faithful
                | Tolerance::Cond(_)
                | Tolerance::CondDegree
                | Tolerance::Bound
        )
    }

    /// Does it need the condition number `Σ|c_i|B_i(|λ|)` (only evaluation claims have one)?
    pub fn needs_condition(&self) -> bool {
        matches!(
            self,
            Tolerance::Cond(_) | Tolerance::CondDegree | Tolerance::Bound
        )
    }

    /// Is it `cond=K` or `cond` (relative to the condition number `Σ|c_i|B_i(|λ|)`)?
    pub fn is_cond(&self) -> bool {
        matches!(self, Tolerance::Cond(_) | Tolerance::CondDegree)
    }

    /// The tolerance for a degree-`n` patch on the m-simplex: `cond` becomes `cond=K` with
    /// `K = (m+1)·n`, the constant of de Casteljau's own bound `|fl(P) − P| ≤ γ_{(m+1)n} Σ|c_α|
    /// B_α(|λ|)` (docs/theory.md §14.1: n levels, each a sum of m+1 products); every other
    /// tolerance is returned unchanged.
    ///
    /// ```
    /// use tribez::hazmat::certify::measures::Tolerance;
    /// use tribez::hazmat::number::parse_rational as q;
    /// let t = Tolerance::parse("cond").unwrap();
    /// assert_eq!(t.for_patch(2, 3), Tolerance::Cond(q("9").unwrap()));
    /// assert_eq!(t.for_patch(3, 20), Tolerance::Cond(q("80").unwrap()));
    /// assert_eq!(Tolerance::Bound.for_patch(2, 3), Tolerance::Bound);
    /// ```
    pub fn for_patch(&self, m: usize, n: usize) -> Tolerance {
        match self {
            Tolerance::CondDegree => Tolerance::Cond(BigRational::from_integer(
                num_bigint::BigInt::from(m + 1) * num_bigint::BigInt::from(n),
            )),
            t => t.clone(),
        }
    }

    /// Judge one number. `Err` names what the tolerance lacks (a precision, a condition number).
    pub fn accepts(
        &self,
        claimed: &BigRational,
        exact: &BigRational,
        leaf: &Leaf,
    ) -> Result<bool, ToleranceNeeds> {
        let err = crate::number::q_sub(claimed, exact).abs();
        let precision = || {
            leaf.precision.ok_or_else(|| ToleranceNeeds::Precision {
                tolerance: self.text(),
            })
        };
        Ok(match self {
            Tolerance::Exact => err.is_zero(),
            Tolerance::Abs(e) => &err <= e,
            Tolerance::Rel(e) => err <= e * exact.abs(),
            Tolerance::Ulps(n) => err <= n * ulp(exact, precision()?),
            Tolerance::CorrectlyRounded => nearest(exact, precision()?).as_ref() == Some(claimed),
            Tolerance::Faithful => is_faithful(claimed, exact, precision()?),
            Tolerance::Cond(k) => {
                let s = leaf.condition.as_ref().ok_or(ToleranceNeeds::Condition)?;
                err <= k * unit_roundoff(precision()?) * s
            }
            Tolerance::CondDegree => {
                return Err(ToleranceNeeds::Degree);
            }
            Tolerance::Bound => {
                let b = leaf.bound.as_ref().ok_or(ToleranceNeeds::Bound)?;
                &err <= b
            }
        })
    }

    /// The tolerance as written.
    pub fn text(&self) -> String {
        match self {
            Tolerance::Exact => "exact".into(),
            Tolerance::Ulps(n) => format!("ulps={n}"),
            Tolerance::Abs(e) => format!("abs={e}"),
            Tolerance::Rel(e) => format!("rel={e}"),
            Tolerance::CorrectlyRounded => "correctly_rounded".into(),
            Tolerance::Faithful => "faithful".into(),
            Tolerance::Cond(k) => format!("cond={k}"),
            Tolerance::CondDegree => "cond".into(),
            Tolerance::Bound => "bound".into(),
        }
    }
}

impl std::fmt::Display for Tolerance {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.text())
    }
}

/// What a tolerance may need besides the two numbers.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Leaf {
    /// The claim's precision (float claims).
    pub precision: Option<Precision>,
    /// The condition number `Σ|c_i| B_i(|λ|)` of this coordinate (evaluation claims).
    pub condition: Option<BigRational>,
    /// The proven absolute error bound of the claim's algorithm at this coordinate.
    pub bound: Option<BigRational>,
}

/// Unit roundoff ε: `2^-53` (f64) or `2^-24` (f32).
pub fn unit_roundoff(p: Precision) -> BigRational {
    pow2(i64::from(p.unit_roundoff_log2()))
}

/// Binade ulp of `q` in precision `p` (docs/theory.md §14.4).
pub fn ulp(q: &BigRational, p: Precision) -> BigRational {
    match p {
        Precision::F64 => ulp_f64(q),
        Precision::F32 => ulp_f32(q),
    }
}

/// The exact value of `RN_p(q)`, `None` when it overflows.
pub fn nearest(q: &BigRational, p: Precision) -> Option<BigRational> {
    match p {
        Precision::F64 => exact_f64(round_f64(q)),
        Precision::F32 => exact_f32(round_f32(q)),
    }
}

/// The float of precision `p` nearest the exact value `q` (its text: the value `q` denotes
/// when the claim is a float claim), as its exact value; `None` if it overflows.
pub fn as_float(q: &BigRational, p: Precision) -> Option<BigRational> {
    nearest(q, p)
}

/// Is `claimed` (the exact value of a float) a faithful rounding of `q`?
pub fn is_faithful(claimed: &BigRational, q: &BigRational, p: Precision) -> bool {
    match p {
        Precision::F64 => {
            crate::number::is_faithful_f64(round_f64(claimed), q)
                && exact_f64(round_f64(claimed)).as_ref() == Some(claimed)
        }
        Precision::F32 => {
            crate::number::is_faithful_f32(round_f32(claimed), q)
                && exact_f32(round_f32(claimed)).as_ref() == Some(claimed)
        }
    }
}

/// The error of one claimed number against one exact number, every way it is measured.
#[derive(Clone, Debug, PartialEq)]
pub struct Measures {
    /// `|y − q|`.
    pub abs: BigRational,
    /// `|y − q| / |q|` (`None` when `q = 0`).
    pub rel: Option<BigRational>,
    /// `|y − q| / ulp_p(q)` (`None` without a precision).
    pub ulps: Option<BigRational>,
    /// `y = RN_p(q)` (`None` without a precision).
    pub correctly_rounded: Option<bool>,
}

impl Measures {
    /// Measure `claimed` against `exact`.
    pub fn new(claimed: &BigRational, exact: &BigRational, precision: Option<Precision>) -> Self {
        let abs = crate::number::q_sub(claimed, exact).abs();
        let rel = (!exact.is_zero()).then(|| &abs / exact.abs());
        let ulps = precision.map(|p| &abs / ulp(exact, p));
        let correctly_rounded = precision.map(|p| nearest(exact, p).as_ref() == Some(claimed));
        Measures {
            abs,
            rel,
            ulps,
            correctly_rounded,
        }
    }

    /// JSON, numbers as exact strings plus a short decimal (the [`serde::Serialize`] impl).
    pub fn to_json(&self) -> serde_json::Value {
        serde_json::to_value(self).unwrap_or(serde_json::Value::Null)
    }

    /// One line for people: `0.5 ulp, abs 1.1e-17, rel 5.5e-17, correctly rounded`.
    pub fn text(&self) -> String {
        let mut parts = Vec::new();
        if let Some(u) = &self.ulps {
            parts.push(format!("{} ulp", crate::number::ulps_decimal(u)));
        }
        parts.push(format!("abs {}", sci(&self.abs)));
        if let Some(r) = &self.rel {
            parts.push(format!("rel {}", sci(r)));
        }
        match self.correctly_rounded {
            Some(true) => parts.push("correctly rounded".into()),
            Some(false) => parts.push("not correctly rounded".into()),
            None => {}
        }
        parts.join(", ")
    }
}

/// A number in a report: exact (`p/q`) and as a short decimal (6 significant digits).
#[derive(serde::Serialize)]
struct Approx {
    exact: String,
    approx: String,
}

impl Approx {
    fn of(x: &BigRational) -> Self {
        Approx {
            exact: x.to_string(),
            approx: crate::number::to_decimal_string(x, 6),
        }
    }
}

impl serde::Serialize for Measures {
    /// `{"abs": {"exact", "approx"}, "rel": …, "ulps": …, "correctly_rounded": bool}`, `rel`,
    /// `ulps` and `correctly_rounded` null where undefined.
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        #[derive(serde::Serialize)]
        struct MeasuresJson {
            abs: Approx,
            rel: Option<Approx>,
            ulps: Option<Approx>,
            correctly_rounded: Option<bool>,
        }
        MeasuresJson {
            abs: Approx::of(&self.abs),
            rel: self.rel.as_ref().map(Approx::of),
            ulps: self.ulps.as_ref().map(Approx::of),
            correctly_rounded: self.correctly_rounded,
        }
        .serialize(s)
    }
}

/// A short scientific rendering of a non-negative rational (for people; JSON keeps it exact).
pub fn sci(q: &BigRational) -> String {
    if q.is_zero() {
        return "0".into();
    }
    let x = round_f64(q);
    if x.is_finite() && x != 0.0 {
        format!("{x:.3e}")
    } else {
        crate::number::to_decimal_string(q, 4)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::number::parse_rational as q;

    fn leaf(p: Option<Precision>) -> Leaf {
        Leaf {
            precision: p,
            condition: Some(q("3").unwrap()),
            bound: Some(q("1e-15").unwrap()),
        }
    }

    #[test]
    fn parses_every_tolerance_and_rejects_others() {
        for t in [
            "exact",
            "ulps=2",
            "abs=1e-12",
            "rel=1/3",
            "correctly_rounded",
            "faithful",
            "cond=4",
            "cond",
            "bound",
        ] {
            assert_eq!(
                Tolerance::parse(t).unwrap().text().split('=').next(),
                t.split('=').next()
            );
        }
        assert!(
            Tolerance::parse("ulp=2")
                .unwrap_err()
                .to_string()
                .contains("unknown tolerance")
        );
        assert!(
            Tolerance::parse("ulps")
                .unwrap_err()
                .to_string()
                .contains("needs a value")
        );
        assert!(
            Tolerance::parse("ulps=-1")
                .unwrap_err()
                .to_string()
                .contains("negative")
        );
        assert!(
            Tolerance::parse("exact=1")
                .unwrap_err()
                .to_string()
                .contains("takes no value")
        );
    }

    #[test]
    fn point_one_plus_point_two() {
        // docs/theory.md §14.4: (0.1 + 0.2) − 3/10 = 0.8 ulp(3/10), one step above RN(3/10) = 0.3.
        let y = exact_f64(0.1 + 0.2).unwrap();
        let x = q("3/10").unwrap();
        let l = leaf(Some(Precision::F64));
        let m = Measures::new(&y, &x, Some(Precision::F64));
        assert_eq!(m.ulps.unwrap(), q("4/5").unwrap());
        assert_eq!(m.correctly_rounded, Some(false));
        assert!(
            Tolerance::parse("ulps=0.8")
                .unwrap()
                .accepts(&y, &x, &l)
                .unwrap()
        );
        assert!(
            !Tolerance::parse("ulps=0.79")
                .unwrap()
                .accepts(&y, &x, &l)
                .unwrap()
        );
        assert!(
            Tolerance::parse("faithful")
                .unwrap()
                .accepts(&y, &x, &l)
                .unwrap()
        );
        assert!(
            !Tolerance::parse("correctly_rounded")
                .unwrap()
                .accepts(&y, &x, &l)
                .unwrap()
        );
        // 0.8 ulp of 3/10 (binade 2^-2): 0.8 · 2^-54 = 4.44e-17; ε·3 = 3.33e-16.
        assert!(
            Tolerance::parse("cond=1")
                .unwrap()
                .accepts(&y, &x, &l)
                .unwrap()
        );
        assert!(
            !Tolerance::parse("abs=4e-17")
                .unwrap()
                .accepts(&y, &x, &l)
                .unwrap()
        );
        assert!(
            Tolerance::parse("abs=5e-17")
                .unwrap()
                .accepts(&y, &x, &l)
                .unwrap()
        );
        assert!(
            Tolerance::parse("rel=2e-16")
                .unwrap()
                .accepts(&y, &x, &l)
                .unwrap()
        );
        assert!(
            Tolerance::parse("bound")
                .unwrap()
                .accepts(&y, &x, &l)
                .unwrap()
        );
    }

    #[test]
    fn cond_without_k_is_the_degree_constant() {
        // (m+1)·n by hand: a cubic triangle 3·3 = 9, a quadratic curve 2·2 = 4, a degree-20
        // triangle 3·20 = 60, a degree-10 tetrahedron 4·10 = 40, a linear 4-simplex 5·1 = 5.
        let t = Tolerance::parse("cond").unwrap();
        assert_eq!(t, Tolerance::CondDegree);
        assert!(t.needs_precision() && t.needs_condition() && t.is_cond());
        for (m, n, k) in [
            (2, 3, "9"),
            (1, 2, "4"),
            (2, 20, "60"),
            (3, 10, "40"),
            (4, 1, "5"),
        ] {
            assert_eq!(
                t.for_patch(m, n),
                Tolerance::Cond(q(k).unwrap()),
                "m={m} n={n}"
            );
            assert_eq!(t.for_patch(m, n).text(), format!("cond={k}"));
        }
        assert_eq!(
            Tolerance::parse(" cond = 9 ").unwrap().for_patch(2, 20),
            Tolerance::Cond(q("9").unwrap())
        );
        // unresolved, it cannot judge: it names what it lacks
        let one = q("1").unwrap();
        let e = t
            .accepts(&one, &one, &leaf(Some(Precision::F64)))
            .unwrap_err();
        assert_eq!(e, ToleranceNeeds::Degree);
        // `cond=` with an empty value is still an error, not the degree constant
        assert!(Tolerance::parse("cond=").is_err());
    }

    #[test]
    fn float_tolerances_need_a_precision() {
        let e = Tolerance::parse("ulps=1")
            .unwrap()
            .accepts(&q("1").unwrap(), &q("1").unwrap(), &leaf(None))
            .unwrap_err();
        assert_eq!(
            e.to_string(),
            "tolerance `ulps=1` needs `precision` (f64 or f32)"
        );
    }
}
