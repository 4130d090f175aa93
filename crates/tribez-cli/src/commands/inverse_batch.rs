//! `tribez check --patch PATCH --locate-results FILE` and `--ray-results FILE`: batches of
//! another implementation's answers to `locate` and `ray` (the query, then the claimed
//! parameters), judged against the exact answers. The engine is the library's
//! [`tribez::batch::inverse`]; this file checks the arguments, shows progress and renders the
//! report (text, JSON, JUnit).

use std::io::{IsTerminal, Write};

use serde_json::Value as Json;

use super::check::Args;
use super::{CliError, Outcome};
use crate::report::{JunitCase, JunitSuite, Render, to_json};
use tribez::Patch;
use tribez::ResultsChecker;
use tribez::batch::{InverseBatchChecker, InverseBatchOptions, InverseBatchReport, InverseKind};

/// Run an inverse batch (the dispatcher calls this when `--locate-results` or `--ray-results`
/// is given).
pub fn run(args: &Args) -> Result<Outcome, CliError> {
    let (kind, results, flag) = match (&args.locate_results, &args.ray_results) {
        (Some(r), None) => (InverseKind::Locate, r, "--locate-results"),
        (None, Some(r)) => (InverseKind::Ray, r, "--ray-results"),
        _ => unreachable!("clap: exactly one, checked by the caller"),
    };
    if !args.paths.is_empty() {
        return Err(CliError::Usage(format!(
            "give either claim files or --patch/{flag}, not both"
        )));
    }
    args.refuse(&super::check::EVALUATION_ONLY, |other| {
        format!("{other} is not available with {flag} (it concerns evaluation batches)")
    })?;
    let patch_path = args
        .patch
        .as_ref()
        .ok_or_else(|| CliError::Usage(format!("{flag} needs --patch PATCH")))?;
    let base = super::batch::options(args)?;
    let options = InverseBatchOptions {
        kind,
        tolerance: base.tolerance,
        precision: base.precision,
        anywhere: args.anywhere,
    };
    let name = patch_path.display().to_string();
    let patch = Patch::from_file(patch_path)?;
    let checker = InverseBatchChecker::new(patch, &name, &options)?;
    let show = std::io::stderr().is_terminal();
    let mut progress = |rows: u64, failed: u64| {
        if show {
            eprint!("\rtribez check: {rows} rows, {failed} failed");
            let _ = std::io::stderr().flush();
        }
    };
    let report = checker.check_file(results, &name, &mut progress);
    if show {
        eprintln!();
    }
    let report = Rendered(report?);
    let success = report.0.failed == 0;
    if let Some(path) = &args.junit {
        super::write_junit(path, &report)?;
    }
    Outcome::rendered(&report, args.out.format, success)
}

/// The report, rendered.
struct Rendered(InverseBatchReport);

impl Render for Rendered {
    fn text(&self) -> String {
        self.0.text()
    }

    fn json(&self) -> Json {
        to_json(&self.0)
    }

    fn junit(&self) -> Option<JunitSuite> {
        let r = &self.0;
        let mut failures: Vec<String> = r
            .failures
            .iter()
            .map(|f| {
                let reasons: Vec<&str> = f.mismatches.iter().map(|m| m.reason.as_str()).collect();
                format!("line {}: {}", f.line, reasons.join("; "))
            })
            .collect();
        if r.failures_not_listed > 0 {
            failures.push(format!("… and {} more", r.failures_not_listed));
        }
        Some(JunitSuite {
            suite: "check",
            cases: vec![JunitCase {
                name: r.results.clone(),
                checks: usize::try_from(r.checked).unwrap_or(usize::MAX),
                failures,
            }],
        })
    }
}
