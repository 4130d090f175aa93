//! `tribez fit`: the exact least-squares fit of scattered data `x, y, value` by a mesh of
//! functional Bézier triangles (docs/theory.md §18, docs/guide.md "Meshes"), and
//! `tribez check --mesh FITTED --fit DATA`: a fit computed in floating point by other code,
//! judged against the exact one.

use std::path::{Path, PathBuf};

use serde_json::Value as Json;

use super::{CliError, Outcome};
use crate::cli::{TextOrJson, whole_number};
use crate::report::{JunitCase, JunitSuite, Render, to_json};
use tribez::fit::{
    FitError, FitOptions, FitReport, FloatFitOptions, FloatFitReport, Smoothness, fit,
    judge_float_fit, read_data,
};
use tribez::mesh::{MAX_MESH_DEGREE, Mesh, MeshLines, read_mesh};

// Arguments of `tribez fit` (a plain comment: see `Command`).
#[derive(Debug, clap::Args)]
pub struct Args {
    /// The data: CSV rows `x,y,value` in the exact number syntax of patch files (a header line,
    /// blank lines and `#` comments allowed).
    #[arg(value_name = "DATA")]
    pub data: PathBuf,
    /// The mesh whose vertices and triangles the fit keeps (.toml or .json; its ordinates, if
    /// any, are ignored).
    #[arg(long, value_name = "MESH")]
    pub mesh: PathBuf,
    /// Fit at this degree instead of the mesh file's.
    #[arg(long, value_name = "N", value_parser = whole_number::<usize>(1, MAX_MESH_DEGREE as u64))]
    pub degree: Option<usize>,
    /// The function space: c0 (every ordinate free) or c1 (the μ rule across every interior edge).
    #[arg(long, value_name = "c0|c1", default_value = "c0")]
    pub smoothness: Smoothness,
    /// When the data do not determine every ordinate, give the least-squares fit of least
    /// Euclidean norm instead of an error naming the undetermined ordinates.
    #[arg(long)]
    pub regularize: bool,
    /// Write the fitted mesh (every ordinate, exact) to FITTED: JSON if its name ends in .json,
    /// else TOML. Without it the fitted ordinates appear only in the report (17 significant
    /// digits in text, exact in --format json).
    #[arg(long, short = 'o', value_name = "FITTED")]
    pub output: Option<PathBuf>,
    /// The format of the report (standard output).
    #[arg(long, value_enum, default_value_t = TextOrJson::Text)]
    pub format: TextOrJson,
}

/// The report always goes to standard output (`-o` is the fitted mesh, staged by [`run`]).
impl super::OutputTarget for Args {
    fn output(&self) -> Option<&PathBuf> {
        None
    }
}

/// Read a mesh file for a fit: its geometry must be a valid triangulation (the first problem,
/// located in the file, is the error); ordinates may be absent.
fn read_geometry(path: &Path) -> Result<(Mesh, MeshLines), CliError> {
    let (mesh, lines) = read_mesh(path)?;
    let mut problems = Vec::new();
    mesh.check_geometry(&mut problems);
    if let Some(p) = problems.into_iter().next() {
        return Err(lines.locate(p).into());
    }
    Ok((mesh, lines))
}

/// A fit's error as one line naming the file concerned.
fn fit_error(e: FitError, data: &str, lines: &MeshLines) -> CliError {
    match e {
        // names the data file and line already
        e @ FitError::Outside { .. } => CliError::Library(e.into()),
        e @ (FitError::RankDeficient { .. } | FitError::Solver(_)) => CliError::about(data, e),
        FitError::Mesh(p) => lines.locate(p).into(),
        // names the mesh file already
        e @ FitError::MissingOrdinate { .. } => CliError::Library(e.into()),
        e => CliError::about(&lines.file, e),
    }
}

/// The report of `tribez fit`: the library's [`FitReport`], and the fitted mesh file written.
struct FitOutcome {
    report: FitReport,
    written: Option<String>,
}

impl Render for FitOutcome {
    fn text(&self) -> String {
        let mut s = self.report.text();
        match &self.written {
            Some(f) => s += &format!("fitted mesh written to {f}\n"),
            None => s += "(no fitted mesh file: give -o FITTED to write one)\n",
        }
        s
    }

    fn json(&self) -> Json {
        let mut j = to_json(&self.report);
        if let Json::Object(o) = &mut j {
            o.insert(
                "fitted_mesh_file".into(),
                self.written.clone().map_or(Json::Null, Json::String),
            );
        }
        j
    }
}

/// Run `tribez fit`.
pub fn run(args: &Args) -> Result<Outcome, CliError> {
    let data_file = args.data.display().to_string();
    let (mesh, lines) = read_geometry(&args.mesh)?;
    let data = read_data(&args.data)?;
    let options = FitOptions {
        degree: args.degree,
        smoothness: args.smoothness,
        regularize: args.regularize,
    };
    let f =
        fit(&mesh, &data, &data_file, &options).map_err(|e| fit_error(e, &data_file, &lines))?;
    let written = match &args.output {
        Some(path) => {
            let json = path
                .extension()
                .is_some_and(|e| e.eq_ignore_ascii_case("json"));
            let text = if json {
                crate::report::pretty_json(&f.mesh.to_json())
            } else {
                f.mesh.to_toml()
            };
            super::write_atomically(path, text.as_bytes())?;
            Some(path.display().to_string())
        }
        None => None,
    };
    let report = FitOutcome {
        report: f.report(&data_file, &lines.file),
        written,
    };
    Outcome::rendered(&report, args.format, true)
}

impl Render for FloatFitReport {
    fn text(&self) -> String {
        FloatFitReport::text(self)
    }

    fn json(&self) -> Json {
        to_json(self)
    }

    fn junit(&self) -> Option<JunitSuite> {
        let failures = if self.passed {
            Vec::new()
        } else {
            vec![format!(
                "error ‖x̂ − x*‖₂ = {:.3e}, {} × the allowed error (tolerance {}); largest |x̂_k − x*_k| = {}",
                self.error_norm,
                self.error_ratio
                    .map_or_else(|| "none".to_string(), |r| format!("{r:.3e}")),
                self.tolerance,
                self.max_abs_error.decimal
            )]
        };
        Some(JunitSuite {
            suite: "check",
            cases: vec![JunitCase {
                name: format!("{} fit of {}", self.mesh, self.data),
                checks: 1,
                failures,
            }],
        })
    }
}

/// Run `tribez check --mesh FITTED --fit DATA`: a float fit judged against the exact
/// least-squares fit (exit status 0 if it passes the tolerance, 1 if not).
pub fn run_check(args: &super::check::Args) -> Result<Outcome, CliError> {
    if !args.paths.is_empty() {
        return Err(CliError::Usage(
            "give either claim files or --mesh/--fit, not both".into(),
        ));
    }
    args.refuse(&super::check::EVALUATION_ONLY, |flag| {
        format!("{flag} is not available with --fit (one judgement of a whole fit)")
    })?;
    let mesh_path = args
        .mesh
        .as_ref()
        .ok_or_else(|| CliError::Usage("--fit needs --mesh FITTED".into()))?;
    let data_path = args.fit.as_ref().expect("checked by the caller");
    let tolerance = match &args.tolerance {
        Some(t) => tribez::Tolerance::parse(t).map_err(|e| CliError::about("--tolerance", e))?,
        None => FloatFitOptions::default().tolerance,
    };
    let precision = match &args.precision {
        Some(p) => p
            .parse::<tribez::Precision>()
            .map_err(|e| CliError::about("--precision", e))?,
        None => FloatFitOptions::default().precision,
    };
    let (mesh, lines) = read_geometry(mesh_path)?;
    let data_file = data_path.display().to_string();
    let data = read_data(data_path)?;
    let options = FloatFitOptions {
        tolerance,
        precision,
    };
    let report =
        judge_float_fit(&mesh, &data, &lines.file, &data_file, &options).map_err(|e| match e {
            e @ FitError::Tolerance { .. } => CliError::about("--tolerance", e),
            e => fit_error(e, &data_file, &lines),
        })?;
    if let Some(path) = &args.junit {
        super::write_junit(path, &report)?;
    }
    let passed = report.passed;
    Outcome::rendered(&report, args.out.format, passed)
}
