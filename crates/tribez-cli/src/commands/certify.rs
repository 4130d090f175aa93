//! `tribez certify`: run the float program of a patch of any kind in f64 and f32 and judge it
//! against the exact values and its proven error bound. The run is the library's
//! [`tribez::certify()`]; this file turns the arguments into [`CertifyOptions`], reads the
//! points, handles baselines and JUnit.

use std::path::PathBuf;

use super::{CliError, Outcome};
use crate::cli::{AlgorithmChoice, OutputArgs};
use crate::report::{JunitCase, JunitSuite, Render, to_json};
use serde_json::Value as Json;
use tribez::files::read_points;
use tribez::{Algorithm, Precision};
use tribez::{CertifyOptions, CertifyPoints, CertifyReport, Patch};

// Arguments of `tribez certify` (a plain comment: see `Command`).
#[derive(Debug, clap::Args)]
pub struct Args {
    /// The patch file.
    pub patch: PathBuf,
    /// Barycentric points (CSV or JSON, exact numbers; Cartesian x,y for an S-patch); they are
    /// rounded to the precision.
    #[arg(long, value_name = "FILE", conflicts_with = "random")]
    pub points: Option<PathBuf>,
    /// Certify at N random points (inside, near the edges and outside the triangle; for an
    /// S-patch inside the polygon, near its edges and vertices).
    #[arg(long, value_name = "N", value_parser = crate::cli::random_count, allow_negative_numbers = true)]
    pub random: Option<usize>,
    /// Seed of --random (printed, with the command that reproduces the run).
    #[arg(long, value_name = "S", default_value_t = 1, value_parser = crate::cli::seed, allow_negative_numbers = true)]
    pub seed: u64,
    /// Precision: f64, f32 or all.
    #[arg(long, value_name = "f64|f32|all", default_value = "all")]
    pub precision: String,
    /// The float algorithm to certify.
    #[arg(long, value_name = "casteljau|bernstein|all", default_value = "all",
          value_parser = crate::cli::algorithm(AlgorithmChoice::ANY))]
    pub algorithm: AlgorithmChoice,
    /// Write the worst error per algorithm and precision to FILE.
    #[arg(long, value_name = "FILE")]
    pub record_baseline: Option<PathBuf>,
    /// Fail when a worst error is larger than recorded in FILE.
    #[arg(long, value_name = "FILE")]
    pub baseline: Option<PathBuf>,
    /// Also write a JUnit XML report (one test case per algorithm and precision).
    #[arg(long, value_name = "FILE")]
    pub junit: Option<PathBuf>,
    /// Also draw the error maps (one per algorithm and precision: every point at its place,
    /// coloured by its error in ULPs, bound violations and the worst point marked, with the
    /// histogram) to FILE (.svg or .png).
    #[arg(long, value_name = "FILE")]
    pub plot: Option<PathBuf>,
    /// Also write a self-contained HTML report (summary, histograms, error maps, worst points
    /// with exact values, violations, the command to reproduce) to FILE.
    #[arg(long, value_name = "FILE")]
    pub html: Option<PathBuf>,
    #[command(flatten)]
    pub out: OutputArgs,
}

/// The algorithm of `--algorithm` (`None`: all), checked against those of the kind's float
/// program.
fn algorithm(args: &Args, patch: &Patch) -> Result<Option<Algorithm>, CliError> {
    let offered = patch.float().map_or(&[][..], |f| f.float_algorithms());
    if offered.len() == 1 && args.algorithm == AlgorithmChoice::Bernstein {
        return Err(CliError::Usage(format!(
            "--algorithm {}: {} are certified with de Casteljau only (--algorithm casteljau or all)",
            args.algorithm,
            patch.kind().plural()
        )));
    }
    Ok(args.algorithm.algorithm())
}

/// Run `tribez certify`.
pub fn run(args: &Args) -> Result<Outcome, CliError> {
    let pictures = crate::picture::reports::Pictures {
        plot: args.plot.clone(),
        html: args.html.clone(),
    };
    pictures.check_names()?;
    let patch = Patch::from_file(&args.patch)?;
    if pictures.any() {
        crate::picture::reports::outline(&patch, "--plot")?;
    }
    let precision = match args.precision.as_str() {
        "all" => None,
        p => Some(
            p.parse::<Precision>()
                .map_err(|e| CliError::about("--precision", e))?,
        ),
    };
    if patch.float().is_none() {
        return Err(CliError::Usage(format!(
            "{}: {} have no float program to certify",
            args.patch.display(),
            patch.kind().plural()
        )));
    }
    let algorithm = algorithm(args, &patch)?;
    let points = match (&args.points, args.random) {
        (Some(path), None) => CertifyPoints::Given {
            points: read_points(path, patch.shape().input.len())?,
            source: path.display().to_string(),
        },
        (None, Some(count)) => CertifyPoints::Random {
            count,
            seed: args.seed,
        },
        (None, None) => {
            return Err(CliError::Usage(
                "give --points FILE or --random N [--seed S]".into(),
            ));
        }
        (Some(_), Some(_)) => unreachable!("clap rejects --points with --random"),
    };
    let options = CertifyOptions {
        points,
        precision,
        algorithm,
        label: args.patch.display().to_string(),
    };
    let mut report = tribez::certify(&patch, &options)?;
    let worst = report.worst_errors();
    report.baseline_regressions = super::baseline::regressions(args.baseline.as_deref(), &worst)?;
    let success = report.success();
    if let Some(path) = &args.junit {
        super::write_junit(path, &report)?;
    }
    if pictures.any() {
        crate::picture::reports::certify(&pictures, &patch, &report, &reproduce(args))?;
    }
    super::baseline::record_if_clean(args.record_baseline.as_deref(), &worst, success)?;
    Outcome::rendered(&report, args.out.format, success)
}

/// The `tribez certify` arguments that reproduce a run (for the HTML report).
fn reproduce(args: &Args) -> Vec<String> {
    let mut c = vec![
        "tribez".into(),
        "certify".into(),
        args.patch.display().to_string(),
    ];
    match (&args.points, args.random) {
        (Some(p), _) => c.extend(["--points".into(), p.display().to_string()]),
        (None, Some(n)) => c.extend([
            "--random".into(),
            n.to_string(),
            "--seed".into(),
            args.seed.to_string(),
        ]),
        (None, None) => {}
    }
    c.extend([
        "--precision".into(),
        args.precision.clone(),
        "--algorithm".into(),
        args.algorithm.to_string(),
    ]);
    c
}

impl Render for CertifyReport {
    fn text(&self) -> String {
        CertifyReport::text(self)
    }

    fn json(&self) -> Json {
        to_json(self)
    }

    fn junit(&self) -> Option<JunitSuite> {
        let mut cases: Vec<JunitCase> = self
            .rows
            .iter()
            .map(|r| JunitCase {
                name: format!("{} {}", r.algorithm.name(), r.precision.name()),
                checks: r.coordinates,
                failures: r.violations.clone(),
            })
            .collect();
        cases.extend(super::baseline::junit_case(&self.baseline_regressions));
        Some(JunitSuite {
            suite: "certify",
            cases,
        })
    }
}
