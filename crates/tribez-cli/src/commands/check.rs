//! `tribez check`: judge claim files (and directories of them), or a batch of evaluation results
//! from another implementation (`--patch PATCH --results FILE`, see [`super::batch`]).

use std::path::PathBuf;

use serde_json::Value as Json;

use super::{CliError, Outcome};
use crate::cli::{AlgorithmChoice, OutputArgs};
use crate::report::{JunitCase, JunitSuite, Render, to_json};
use tribez::claims::{self, ClaimsOptions, ClaimsReport};

// Arguments of `tribez check` (a plain comment: see `Command`).
#[derive(Debug, clap::Args)]
#[command(group(clap::ArgGroup::new("mesh_input").args(["results", "fit"]).multiple(false)))]
pub struct Args {
    /// Claim files (`*.claims.toml`, `*.claims.json`) or directories searched recursively.
    #[arg(value_name = "FILE_OR_DIR")]
    pub paths: Vec<PathBuf>,
    /// Batch mode: the patch the results are about.
    #[arg(long, value_name = "PATCH")]
    pub patch: Option<PathBuf>,
    /// Batch mode: CSV, JSON-lines or JSON-array-of-rows results (input coordinates, then the
    /// claimed coordinates).
    #[arg(long, value_name = "FILE")]
    pub results: Option<PathBuf>,
    /// Batch mode: answers to `tribez locate` from another implementation, one row per point:
    /// `x, y`, then the claimed (s, t) pairs (`x, y, s, t` for one), or `none`; each row
    /// judged against every exact parameter point of the closed triangle.
    #[arg(
        long,
        value_name = "FILE",
        requires = "patch",
        conflicts_with_all = ["results", "mesh", "fit", "ray_results"]
    )]
    pub locate_results: Option<PathBuf>,
    /// Batch mode: answers to `tribez ray` from another implementation, one row per ray:
    /// `ox, oy, oz, dx, dy, dz`, then the claimed first hit `tau, s, t`, or `none`.
    #[arg(
        long,
        value_name = "FILE",
        requires = "patch",
        conflicts_with_all = ["results", "mesh", "fit"]
    )]
    pub ray_results: Option<PathBuf>,
    /// With --locate-results: the exact answer is every parameter point of the whole plane that
    /// maps to the point (as `tribez locate --anywhere`), not only those of the closed triangle;
    /// for code that extrapolates.
    #[arg(
        long,
        requires = "locate_results",
        conflicts_with_all = ["results", "mesh", "fit", "ray_results"]
    )]
    pub anywhere: bool,
    /// A mesh file: with --results, the results are lookups `x, y, value` in it (each row judged
    /// in the triangle containing its point as seen); with --fit, it is a fit computed in
    /// floating point by other code, judged against the exact least-squares fit.
    #[arg(
        long,
        value_name = "MESH",
        requires = "mesh_input",
        conflicts_with = "patch"
    )]
    pub mesh: Option<PathBuf>,
    /// Judge the fitted mesh given with --mesh against the exact least-squares fit of this data
    /// file (CSV rows `x,y,value`); --tolerance `cond=K` (default `cond`, K = 1: the error within
    /// K times what the conditioning of the fit allows at the unit roundoff of --precision,
    /// default f64), `abs=E`, `rel=E` or `exact`.
    #[arg(long, value_name = "DATA", requires = "mesh", conflicts_with = "patch")]
    pub fit: Option<PathBuf>,
    /// Batch mode: the tolerance every row is judged with (default `exact`): `exact`, `ulps=N`,
    /// `abs=E`, `rel=E`, `correctly_rounded`, `faithful`, `cond=K` (|y − q| ≤ K·ε·Σ|c|B(|λ|)),
    /// `cond` (K = (m+1)·n for this patch: de Casteljau's own constant, n = 3 on a triangle gives
    /// K = 9) or `bound`.
    #[arg(long, value_name = "T")]
    pub tolerance: Option<String>,
    /// Batch mode: each number denotes the nearest float of this precision (f64 or f32).
    #[arg(long, value_name = "f64|f32")]
    pub precision: Option<String>,
    /// Batch mode: the input columns are Cartesian coordinates in the patch's domain.
    #[arg(long)]
    pub cartesian: bool,
    /// Batch mode: the algorithm whose a-priori bound `--tolerance bound` uses.
    #[arg(long, value_name = "casteljau|bernstein", default_value = "casteljau",
          value_parser = crate::cli::algorithm(AlgorithmChoice::ONE))]
    pub algorithm: AlgorithmChoice,
    /// Also write a JUnit XML report to FILE (one test case per claim file).
    #[arg(long, value_name = "FILE")]
    pub junit: Option<PathBuf>,
    /// Write the worst error per operation, algorithm and precision to FILE, when every claim
    /// holds and no worst error regressed against --baseline (which is read first, so both may
    /// name the same file).
    #[arg(long, value_name = "FILE")]
    pub record_baseline: Option<PathBuf>,
    /// Fail when any worst error is larger than recorded in FILE.
    #[arg(long, value_name = "FILE")]
    pub baseline: Option<PathBuf>,
    /// Batch mode: also draw the error map (every row at its place in the domain, coloured by
    /// its error in ULPs; failed and worst rows marked; the histogram beside it) to FILE (.svg
    /// or .png).
    #[arg(long, value_name = "FILE")]
    pub plot: Option<PathBuf>,
    /// Also write a self-contained HTML report to FILE: the summary, the histogram, the failures
    /// with exact values, the command to reproduce (batch mode: with the error map and the worst
    /// row).
    #[arg(long, value_name = "FILE")]
    pub html: Option<PathBuf>,
    #[command(flatten)]
    pub out: OutputArgs,
}

impl Args {
    /// Refuse the first of `flags` given on the command line (of `--plot`, `--html`,
    /// `--cartesian`, `--baseline`, `--record-baseline`: the options of evaluation batches), with
    /// the usage error `message(flag)`.
    pub fn refuse(&self, flags: &[&str], message: impl Fn(&str) -> String) -> Result<(), CliError> {
        let given = |flag: &str| match flag {
            "--plot" => self.plot.is_some(),
            "--html" => self.html.is_some(),
            "--cartesian" => self.cartesian,
            "--baseline" => self.baseline.is_some(),
            "--record-baseline" => self.record_baseline.is_some(),
            _ => false,
        };
        match flags.iter().find(|f| given(f)) {
            Some(flag) => Err(CliError::Usage(message(flag))),
            None => Ok(()),
        }
    }
}

/// The options of evaluation batches that other kinds of check refuse.
pub const EVALUATION_ONLY: [&str; 5] = [
    "--plot",
    "--html",
    "--cartesian",
    "--baseline",
    "--record-baseline",
];

/// Judge every claim file under `paths` (files or directories); notes on skipped entries of
/// the directories go to standard error first.
pub fn judge_paths(paths: &[PathBuf], options: &ClaimsOptions) -> Result<ClaimsReport, CliError> {
    let found = claims::claim_files_of(paths)?;
    for note in &found.notes {
        eprintln!("note: {note}");
    }
    Ok(claims::check_files(&found.files, options)?)
}

/// Run `tribez check` on claim files (the dispatcher sends `--results` to [`super::batch`]).
pub fn run(args: &Args) -> Result<Outcome, CliError> {
    for (flag, given) in [
        ("--tolerance", args.tolerance.is_some()),
        ("--precision", args.precision.is_some()),
        ("--cartesian", args.cartesian),
    ] {
        if given {
            return Err(CliError::Usage(format!(
                "{flag} applies to batches (--patch PATCH --results FILE) and fits (--mesh FITTED --fit DATA); claim files state it per claim"
            )));
        }
    }
    if args.patch.is_some() {
        return Err(CliError::Usage(
            "--patch needs --results FILE, --locate-results FILE or --ray-results FILE".into(),
        ));
    }
    if args.paths.is_empty() {
        return Err(CliError::Usage(
            "give claim files or directories, or --patch PATCH --results FILE".into(),
        ));
    }
    if args.plot.is_some() {
        return Err(CliError::Usage(
            "--plot draws the error map of a batch (--patch PATCH --results FILE); claim files concern many patches (--html reports them)".into(),
        ));
    }
    if let Some(html) = &args.html {
        crate::picture::check_html_name(html)?;
    }
    let mut report = judge_paths(&args.paths, &ClaimsOptions::default())?;
    let worst = report.worst_errors();
    report.baseline_regressions = super::baseline::regressions(args.baseline.as_deref(), &worst)?;
    let success = report.success();
    if let Some(path) = &args.junit {
        super::write_junit(path, &report)?;
    }
    if let Some(path) = &args.html {
        crate::picture::reports::claims(path, &report, &args.paths)?;
    }
    super::baseline::record_if_clean(args.record_baseline.as_deref(), &worst, success)?;
    Outcome::rendered(&report, args.out.format, success)
}

impl Render for ClaimsReport {
    fn text(&self) -> String {
        ClaimsReport::text(self)
    }

    fn json(&self) -> Json {
        to_json(self)
    }

    fn junit(&self) -> Option<JunitSuite> {
        let mut cases: Vec<JunitCase> = self
            .files
            .iter()
            .map(|f| JunitCase {
                name: f.file.clone(),
                checks: f.claims.len(),
                failures: f
                    .claims
                    .iter()
                    .filter(|j| j.verdict.fails_run())
                    .map(|j| {
                        format!(
                            "{}: claimed {}, exact {} (tolerance {})",
                            j.id,
                            j.claimed.to_text(),
                            j.exact.to_text(),
                            j.tolerance
                        )
                    })
                    .collect(),
            })
            .collect();
        cases.extend(super::baseline::junit_case(&self.baseline_regressions));
        Some(JunitSuite {
            suite: "check",
            cases,
        })
    }
}
