//! `tribez check --patch PATCH --results FILE`: the batch mode of `check`. The engine is the
//! library's [`tribez::batch`]; this file turns the arguments into [`BatchOptions`], shows
//! progress, renders the report (text, JSON, JUnit) and handles baselines.

use std::io::{IsTerminal, Write};

use serde_json::Value as Json;

use super::check::Args;
use super::{CliError, Outcome};
use crate::report::{JunitCase, JunitSuite, Render, to_json};
use tribez::Precision;
use tribez::ResultsChecker;
use tribez::Tolerance;
use tribez::batch::{BatchChecker, BatchError, BatchOptions, BatchReport};
use tribez::files::read_bezier_patch as read_patch;

/// The batch options of `tribez check`'s arguments.
pub fn options(args: &Args) -> Result<BatchOptions, CliError> {
    let tolerance = match &args.tolerance {
        Some(t) => Tolerance::parse(t).map_err(|e| CliError::about("--tolerance", e))?,
        None => Tolerance::Exact,
    };
    let precision = match &args.precision {
        Some(p) => Some(
            p.parse::<Precision>()
                .map_err(|e| CliError::about("--precision", e))?,
        ),
        None => None,
    };
    let Some(algorithm) = args.algorithm.algorithm() else {
        return Err(CliError::Usage(format!(
            "--algorithm {}: give one algorithm (casteljau or bernstein)",
            args.algorithm
        )));
    };
    Ok(BatchOptions {
        tolerance,
        precision,
        algorithm,
        cartesian: args.cartesian,
        row_detail: false,
    })
}

impl From<BatchError> for CliError {
    fn from(e: BatchError) -> Self {
        match e {
            BatchError::Input(e) => CliError::Input(e),
            BatchError::ToleranceNeedsPrecision { tolerance } => CliError::Usage(format!(
                "--tolerance {tolerance} needs --precision f64 or f32"
            )),
            e => CliError::Batch(e),
        }
    }
}

/// Run the batch mode of `tribez check` (`--patch PATCH --results FILE`).
pub fn run(args: &Args) -> Result<Outcome, CliError> {
    if !args.paths.is_empty() {
        return Err(CliError::Usage(
            "give either claim files or --patch/--results, not both".into(),
        ));
    }
    let patch_path = args
        .patch
        .as_ref()
        .ok_or_else(|| CliError::Usage("--results needs --patch PATCH or --mesh MESH".into()))?;
    let results = args.results.as_ref().expect("checked by the caller");
    let pictures = crate::picture::reports::Pictures {
        plot: args.plot.clone(),
        html: args.html.clone(),
    };
    pictures.check_names()?;
    let patch = read_patch(patch_path)?;
    let mut map = if pictures.any() {
        let outline = crate::picture::reports::outline(
            &tribez::Patch::from(patch.clone()),
            if args.plot.is_some() {
                "--plot"
            } else {
                "--html"
            },
        )?;
        Some(crate::picture::errmap::MapBuilder::new(outline))
    } else {
        None
    };
    let options = options(args)?;
    let checker = BatchChecker::new(patch, &options)?;
    let show = std::io::stderr().is_terminal();
    let mut progress = |rows: u64, failed: u64| {
        if show {
            eprint!("\rtribez check: {rows} rows, {failed} failed");
            let _ = std::io::stderr().flush();
        }
    };
    let name = patch_path.display().to_string();
    let mut smallest = crate::picture::reports::Smallest::new();
    let report = match &mut map {
        None => checker.check_file(results, &name, &mut progress),
        Some(map) => {
            let cartesian = args.cartesian;
            let outline = map.outline().to_vec();
            checker.check_file_each_row(results, &name, &mut progress, &mut |r| {
                let at = if cartesian {
                    [r.inputs[0], r.inputs[1]]
                } else {
                    crate::picture::reports::position(&outline, &r.inputs)
                };
                map.add(r.row, at, r.ulps, r.ulps_lower, r.pass);
                smallest.add(&r);
            })
        }
    };
    if show {
        eprintln!();
    }
    let mut report = report?;
    let worst = worst_errors(&report);
    report.baseline_regressions = super::baseline::regressions(args.baseline.as_deref(), &worst)?;
    let success = report.failed == 0 && report.baseline_regressions.is_empty();
    if let Some(path) = &args.junit {
        super::write_junit(path, &report)?;
    }
    if let Some(map) = map {
        let command = crate::picture::reports::batch_command(
            patch_path,
            results,
            args.tolerance.as_deref(),
            args.precision.as_deref(),
            args.cartesian,
            args.algorithm.name(),
        );
        let min_ulps = smallest.settle(&checker);
        crate::picture::reports::batch(&pictures, &report, map.finish(), min_ulps, &command)?;
    }
    super::baseline::record_if_clean(args.record_baseline.as_deref(), &worst, success)?;
    Outcome::rendered(&report, args.out.format, success)
}

/// The worst error for baselines: (eval, claimed, precision).
fn worst_errors(report: &BatchReport) -> Vec<super::baseline::Worst> {
    report
        .worst
        .iter()
        .map(|w| super::baseline::Worst {
            op: "eval".into(),
            algorithm: "claimed".into(),
            precision: report.precision.map_or("exact", |p| p.name()).into(),
            ulps: w.ulps,
            at: format!("{}:{}", report.file, w.line),
        })
        .collect()
}

impl Render for BatchReport {
    fn text(&self) -> String {
        BatchReport::text(self)
    }

    fn json(&self) -> Json {
        to_json(self)
    }

    fn junit(&self) -> Option<JunitSuite> {
        let mut failures: Vec<String> = self
            .failures
            .iter()
            .map(|f| format!("line {}: {}", f.line, f.reason))
            .collect();
        if self.failed as usize > self.failures.len() {
            failures.push(format!(
                "… and {} more",
                self.failed as usize - self.failures.len()
            ));
        }
        let mut cases = vec![JunitCase {
            name: self.file.clone(),
            checks: self.checked as usize,
            failures,
        }];
        cases.extend(super::baseline::junit_case(&self.baseline_regressions));
        Some(JunitSuite {
            suite: "check",
            cases,
        })
    }
}
