//! A hunt's report as text, as JSON and as a claim file: one renderer behind `tribez hunt` and
//! Python's `tribez.hunt`, which differ only in how they name the program and the way to repeat
//! the hunt ([`HuntLabels`]).

use serde::Serialize;

use super::{HuntReport, HuntRow, decimal, hex};
use crate::float::Precision;

/// How a report names what was hunted.
#[derive(Clone, Copy, Debug)]
pub struct HuntLabels<'a> {
    /// The front end, as the header and the claim file name it (`tribez hunt`, `tribez.hunt`).
    pub tool: &'a str,
    /// The patch as given (its file name).
    pub patch: &'a str,
    /// The program on one line (a shell command line, a function's name).
    pub program: &'a str,
    /// How to repeat the hunt, on one line (a shell command line, a Python call).
    pub reproduce: &'a str,
}

/// An error in ULPs as reports print it: `0`; 4 decimals without trailing zeros from 0.001 to
/// 10^6; else 4 significant digits in exponent form; `not finite` for an infinite (or NaN)
/// figure.
///
/// ```
/// use tribez::hunt::ulps_text;
/// assert_eq!(ulps_text(0.0), "0");
/// assert_eq!(ulps_text(0.5), "0.5");
/// assert_eq!(ulps_text(1.0 / 3.0), "0.3333");
/// assert_eq!(ulps_text(1.5e7), "1.500e7");
/// assert_eq!(ulps_text(f64::INFINITY), "not finite");
/// ```
pub fn ulps_text(u: f64) -> String {
    if u == 0.0 {
        "0".into()
    } else if !u.is_finite() {
        "not finite".into()
    } else if (1e-3..1e6).contains(&u.abs()) {
        format!("{u:.4}")
            .trim_end_matches('0')
            .trim_end_matches('.')
            .to_string()
    } else {
        format!("{u:.3e}")
    }
}

/// A row's error in ULPs as the text report prints it: [`ulps_text`], except that an error
/// too large for an `f64` of a finite answer (any error above about `10^-15` against an exact
/// 0, whose ulp is `2^-1074`) reads `more than 1.798e308` rather than `not finite`, which is
/// left to answers that are not finite.
fn row_ulps_text(r: &HuntRow) -> String {
    if r.ulps.is_infinite() && r.claimed.iter().all(|x| x.is_finite()) {
        format!("more than {}", ulps_text(f64::MAX))
    } else {
        ulps_text(r.ulps)
    }
}

/// Numbers as hex floats of the precision.
pub fn hexes(precision: Precision, xs: &[f64]) -> Vec<String> {
    xs.iter().map(|&x| hex(precision, x)).collect()
}

/// A string as a TOML basic string (JSON's escapes are TOML's).
fn toml_str(s: &str) -> String {
    serde_json::to_string(s).expect("a string serialises")
}

/// The JSON of a hunt's report (the keys of `tribez hunt --format json`); `P` and `R` are how
/// the front end gives the program and the way to repeat the hunt (words of a command line, or
/// a name and a call).
#[derive(Clone, Debug, Serialize)]
pub struct HuntJson<'a, P: Serialize, R: Serialize> {
    /// Always `hunt`.
    pub command: &'static str,
    /// The patch as given.
    pub patch: &'a str,
    /// The program.
    pub program: P,
    /// `f64` or `f32`.
    pub precision: &'static str,
    /// The tolerance.
    pub tolerance: String,
    /// Rows were Cartesian.
    pub cartesian: bool,
    /// The seed.
    pub seed: u64,
    /// The budget.
    pub budget: u64,
    /// Rows given to the target and judged.
    pub evaluated: u64,
    /// Rows that broke the tolerance.
    pub broke: u64,
    /// Rows of each kind of the search: uniform points, the special places, local search.
    pub uniform: u64,
    /// See `uniform`.
    pub special: u64,
    /// See `uniform`.
    pub local: u64,
    /// No row broke the tolerance.
    pub passed: bool,
    /// The worst rows, worst first.
    pub worst: Vec<HuntRowJson<'a>>,
    /// How to repeat the hunt.
    pub reproduce: R,
}

/// One of the worst rows in [`HuntJson`].
#[derive(Clone, Debug, Serialize)]
pub struct HuntRowJson<'a> {
    /// Its number (from 1).
    pub row: u64,
    /// The input, as hex floats.
    pub input: Vec<String>,
    /// The answer, as hex floats (`inf`, `-inf`, `nan` as the program said).
    pub claimed: Vec<String>,
    /// The exact values as `p/q`.
    pub exact: Vec<String>,
    /// The exact values as decimals of 17 significant digits.
    pub exact_decimal: Vec<String>,
    /// The error in ULPs; `null` when it is not finite.
    pub ulps: Option<f64>,
    /// It breaks the tolerance.
    pub breaks: bool,
    /// Why.
    pub reason: Option<&'a str>,
}

impl HuntReport {
    /// The text report: a header naming the program, the patch, the kind of rows, the precision
    /// and the tolerance; the counts; the seed; each worst row (input, answer, exact value, its
    /// error in ULPs and the verdict); and how to repeat the hunt.
    pub fn text(&self, labels: &HuntLabels<'_>) -> String {
        let p = self.precision;
        let mut out = format!(
            "{}: {} on {} ({} {}, tolerance {})\n",
            labels.tool,
            labels.program,
            labels.patch,
            if self.cartesian {
                "Cartesian"
            } else {
                "barycentric"
            },
            p.name(),
            self.tolerance
        );
        out += &format!(
            "{} rows evaluated ({} uniform, {} at the places floats fail, {} local moves); {} broke the tolerance\n",
            self.evaluated, self.by_kind[0], self.by_kind[1], self.by_kind[2], self.broke
        );
        out += &format!("seed: {}\n", self.seed);
        out += &match self.worst.len() {
            0 => String::new(),
            1 => "the worst row:\n".to_string(),
            k => format!("the {k} worst rows:\n"),
        };
        for (i, r) in self.worst.iter().enumerate() {
            out += &format!(
                "{:>3}. row {}: {} ulp, {} the tolerance{}\n",
                i + 1,
                r.row,
                row_ulps_text(r),
                if r.passed { "within" } else { "breaks" },
                r.reason
                    .as_ref()
                    .map(|s| format!(" ({s})"))
                    .unwrap_or_default()
            );
            out += &format!("     input    {}\n", hexes(p, &r.input).join(", "));
            out += &format!("     claimed  {}\n", hexes(p, &r.claimed).join(", "));
            let exact: Vec<String> = r.exact.iter().map(|q| decimal(q, 17)).collect();
            out += &format!("     exact    {}\n", exact.join(", "));
        }
        out += &format!("reproduce: {}\n", labels.reproduce);
        out
    }

    /// The JSON report (serialise it with serde_json).
    pub fn json<'a, P: Serialize, R: Serialize>(
        &'a self,
        patch: &'a str,
        program: P,
        reproduce: R,
    ) -> HuntJson<'a, P, R> {
        HuntJson {
            command: "hunt",
            patch,
            program,
            precision: self.precision.name(),
            tolerance: self.tolerance.to_string(),
            cartesian: self.cartesian,
            seed: self.seed,
            budget: self.budget,
            evaluated: self.evaluated,
            broke: self.broke,
            uniform: self.by_kind[0],
            special: self.by_kind[1],
            local: self.by_kind[2],
            passed: self.broke == 0,
            worst: self.worst.iter().map(|r| self.row_json(r)).collect(),
            reproduce,
        }
    }

    fn row_json<'a>(&self, r: &'a HuntRow) -> HuntRowJson<'a> {
        let p = self.precision;
        HuntRowJson {
            row: r.row,
            input: hexes(p, &r.input),
            claimed: hexes(p, &r.claimed),
            exact: r.exact.iter().map(ToString::to_string).collect(),
            exact_decimal: r.exact.iter().map(|q| decimal(q, 17)).collect(),
            ulps: r.ulps.is_finite().then_some(r.ulps),
            breaks: !r.passed,
            reason: r.reason.as_deref(),
        }
    }

    /// The claim file of the worst rows: one `eval` claim per row, its answer as the expected
    /// value, which `tribez check FILE` judges again. `patch_toml` is the file's patch entry
    /// (`patch = "…"\n`, or an inline `[patch]` table), written after the header.
    pub fn claims_file(&self, labels: &HuntLabels<'_>, patch_toml: &str) -> String {
        let p = self.precision;
        let mut s = format!(
            "# The worst rows `{}` found (seed {}): `tribez check` judges them again.\n# {}\nsource = {}\n{}",
            labels.tool,
            self.seed,
            labels.reproduce,
            toml_str(&format!("{} of {}", labels.tool, labels.program)),
            patch_toml
        );
        let list = |xs: &[f64]| {
            format!(
                "[{}]",
                hexes(p, xs)
                    .iter()
                    .map(|x| toml_str(x))
                    .collect::<Vec<_>>()
                    .join(", ")
            )
        };
        for r in &self.worst {
            s += &format!(
                "\n[[claim]]\nid = \"hunt-row-{}\"\nop = \"eval\"\nprecision = \"{}\"\ntolerance = {}\n{} = {}\nexpect = {}\n",
                r.row,
                p.name(),
                toml_str(&self.tolerance.to_string()),
                if self.cartesian { "cartesian" } else { "at" },
                list(&r.input),
                list(&r.claimed)
            );
        }
        s
    }

    /// A TOML string entry `key = "value"` with its line end, for [`HuntReport::claims_file`].
    pub fn toml_entry(key: &str, value: &str) -> String {
        format!("{key} = {}\n", toml_str(value))
    }
}
