//! Baselines of worst errors (like a libm's table of known worst cases): `--record-baseline FILE`
//! writes the worst error in ULPs per operation, algorithm and precision; `--baseline FILE`
//! fails the run when any of them got worse, even inside a loose tolerance.
//!
//! The file is JSON: `{"tribez_baseline": 1, "worst": [{"op": "eval", "algorithm": "casteljau",
//! "precision": "f64", "ulps": 0.75, "at": "…"}]}`.

use std::path::Path;

use super::CliError;
use tribez::{InputError, Problem};

pub use tribez::report::WorstError as Worst;

/// A baseline file as written.
#[derive(serde::Serialize)]
struct BaselineFile<'a> {
    tribez_baseline: u32,
    worst: &'a [Worst],
}

/// The regressions against `--baseline FILE`: read and compared before anything is written,
/// so `--baseline` and `--record-baseline` may name the same file.
pub fn regressions(baseline: Option<&Path>, worst: &[Worst]) -> Result<Vec<String>, CliError> {
    match baseline {
        Some(path) => compare(path, worst),
        None => Ok(Vec::new()),
    }
}

/// Write `--record-baseline FILE` when the run succeeded (`success`: every claim holds and
/// nothing regressed), so a regression never raises the baseline. Called after every other
/// output file is written, so a run that ends with exit status 2 leaves no new baseline.
pub fn record_if_clean(
    record_baseline: Option<&Path>,
    worst: &[Worst],
    success: bool,
) -> Result<(), CliError> {
    match record_baseline {
        Some(path) if success => record(path, worst),
        _ => Ok(()),
    }
}

/// A JUnit case of the baseline regressions (none when nothing regressed).
pub fn junit_case(regressions: &[String]) -> Option<crate::report::JunitCase> {
    (!regressions.is_empty()).then(|| crate::report::JunitCase {
        name: "baseline".into(),
        checks: regressions.len(),
        failures: regressions.to_vec(),
    })
}

/// Write the baseline file (whole or not at all).
pub fn record(path: &Path, worst: &[Worst]) -> Result<(), CliError> {
    let file = BaselineFile {
        tribez_baseline: 1,
        worst,
    };
    let text = crate::report::pretty_json(&file);
    super::write_atomically(path, text.as_bytes())
}

/// Compare against a baseline file: one line per (op, algorithm, precision) that got worse.
pub fn compare(path: &Path, worst: &[Worst]) -> Result<Vec<String>, CliError> {
    let file = path.display().to_string();
    let text = std::fs::read_to_string(path).map_err(|e| {
        InputError::file(
            &file,
            Problem::CannotRead {
                reason: e.to_string(),
            },
        )
    })?;
    let doc: serde_json::Value = serde_json::from_str(&text).map_err(|e| {
        CliError::check(
            format!("{file}:{}:{}", e.line(), e.column()),
            format!("not a baseline file: {e}"),
        )
    })?;
    let entries = doc
        .get("worst")
        .and_then(|w| w.as_array())
        .ok_or_else(|| CliError::check(&file, "not a baseline file: no `worst` array"))?;
    let mut out = Vec::new();
    for (i, e) in entries.iter().enumerate() {
        let field = |k: &str| e.get(k).and_then(|v| v.as_str()).map(str::to_string);
        let (Some(op), Some(alg), Some(prec), Some(ulps)) = (
            field("op"),
            field("algorithm"),
            field("precision"),
            e.get("ulps").and_then(|v| v.as_f64()),
        ) else {
            return Err(CliError::check(
                &file,
                format!("worst[{i}]: needs op, algorithm, precision (strings) and ulps (a number)"),
            ));
        };
        if let Some(w) = worst
            .iter()
            .find(|w| w.op == op && w.algorithm == alg && w.precision == prec)
            && w.ulps > ulps
        {
            out.push(format!(
                "{op} {alg} {prec}: worst error {} ulp, baseline {ulps} ulp (at {})",
                w.ulps, w.at
            ));
        }
    }
    Ok(out)
}
