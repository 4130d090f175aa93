//! One module per command; [`main`] dispatches and maps outcomes to exit statuses.

pub mod baseline;
pub mod batch;
pub mod blossom;
pub mod certify;
pub mod check;
pub mod construct;
pub mod derivative;
pub mod elevate;
pub mod eval;
pub mod graph;
pub mod halve;
pub mod join;
pub mod matrix;
pub mod output;
pub mod reproduce;
pub mod subdivide;
pub mod subpatch;
pub mod symbolic;
pub mod tangent;

use std::io::Write;
use std::path::Path;

use num_rational::BigRational;

use crate::cli::{Cli, Command, OutputArgs};
use crate::report::{Format, Render, render};
use tribez::error::CoreError;
use tribez::io::InputError;
use tribez::number::parse_rational;

/// Why a command could not run: bad input or usage (exit status 2).
#[derive(Debug, thiserror::Error)]
pub enum CliError {
    /// A file or argument with a located problem.
    #[error(transparent)]
    Input(#[from] InputError),
    /// A mathematical precondition that the input violates, with what it concerns.
    #[error("{context}: {source}")]
    Core {
        /// The file or argument concerned.
        context: String,
        /// What is wrong.
        #[source]
        source: CoreError,
    },
    /// Wrong use of the command line.
    #[error("{0}")]
    Usage(String),
}

impl CliError {
    /// A core error about `context`.
    pub fn core(context: impl Into<String>, source: CoreError) -> Self {
        CliError::Core {
            context: context.into(),
            source,
        }
    }
}

/// What a command produced: its rendered output and whether every claim held.
pub struct Outcome {
    /// Rendered output.
    pub output: String,
    /// False when some claim failed (exit status 1).
    pub success: bool,
}

impl Outcome {
    /// Render a result in the requested format; formats that do not apply are a usage error.
    pub fn rendered(r: &dyn Render, format: Format, success: bool) -> Result<Self, CliError> {
        let output = render(r, format).ok_or_else(|| {
            CliError::Usage(
                format!("--format {format:?} is not available for this command").to_lowercase(),
            )
        })?;
        Ok(Outcome { output, success })
    }
}

/// Run the command line; returns the exit status.
///
/// The output files a command staged (see [`output`]) are committed only when it ran to the end
/// (exit status 0 or 1) and its report was written; a run that exits 2 leaves none.
pub fn main(cli: Cli) -> i32 {
    let (result, out) = match &cli.command {
        Command::Reproduce(a) => (reproduce::run(a), &a.out),
        Command::Eval(a) => (eval::run(a), &a.out),
        Command::Symbolic(a) => (symbolic::run(a), &a.out),
        Command::Graph(a) => (graph::run(a), &a.out),
        Command::Check(a) => (check::run(a), &a.out),
        Command::Certify(a) => (certify::run(a), &a.out),
        Command::Blossom(a) => (blossom::run(a), &a.out),
        Command::Subpatch(a) => (subpatch::run(a), &a.out),
        Command::Subdivide(a) => (subdivide::run(a), &a.out),
        Command::Halve(a) => (halve::run(a), &a.out),
        Command::Elevate(a) => (elevate::run(a), &a.out),
        Command::Matrix(a) => (matrix::run(a), &a.out),
        Command::Derivative(a) => (derivative::run(a), &a.out),
        Command::Tangent(a) => (tangent::run(a), &a.out),
        Command::Join(a) => (join::run(a), &a.out),
    };
    let finished = result.and_then(|o| {
        emit(&o, out)?;
        output::commit_all()?;
        Ok(o.success)
    });
    match finished {
        Ok(true) => 0,
        Ok(false) => 1,
        Err(e) => {
            output::discard_all();
            let _ = writeln!(std::io::stderr(), "tribez: {e}");
            2
        }
    }
}

/// Write the output to standard output, or stage it for `--output FILE` (written whole or not at
/// all when the run ends, see [`output`]).
pub fn emit(outcome: &Outcome, out: &OutputArgs) -> Result<(), CliError> {
    match &out.output {
        None => output::write_stdout(outcome.output.as_bytes()),
        Some(path) => output::stage(path, outcome.output.as_bytes()),
    }
}

/// Stage `bytes` as the new content of `path` (see [`output::stage`]): the file is written whole
/// when the run ends with exit status 0 or 1, and not at all otherwise.
pub fn write_atomically(path: &Path, bytes: &[u8]) -> Result<(), CliError> {
    output::stage(path, bytes)
}

/// Parse a comma-separated list of exact numbers from the command line (`1/2,1/3,1/6`).
pub fn parse_list(text: &str, what: &str) -> Result<Vec<BigRational>, CliError> {
    text.split(',')
        .enumerate()
        .map(|(i, t)| {
            parse_rational(t).map_err(|e| InputError {
                file: "<command line>".into(),
                line: None,
                column: None,
                key: Some(format!("{what} `{text}`, coordinate {}", i + 1)),
                message: e.to_string(),
            })
        })
        .collect::<Result<_, _>>()
        .map_err(CliError::from)
}

pub use tribez::domain::{check_barycentric, check_direction};

/// The barycentric point of `--at TEXT`: checked to sum to 1 on the `m`-simplex, or with
/// `cartesian` converted by `domain` (Cramer's rule). Errors name `--at TEXT`.
pub fn at_point(
    text: &str,
    cartesian: bool,
    domain: &tribez::domain::Domain,
    m: usize,
) -> Result<Vec<BigRational>, CliError> {
    let p = parse_list(text, "--at")?;
    let what = format!("--at {text}");
    if cartesian {
        domain.barycentric(&p).map_err(|e| CliError::core(&what, e))
    } else {
        check_barycentric(&p, m, "point").map_err(|e| CliError::core(&what, e))?;
        Ok(p)
    }
}

/// A patch for the commands that take polynomial and rational patches alike: its points patch,
/// and the rational patch when it is one. S-patches are a usage error naming `command`.
pub fn points_patch(
    file: &str,
    command: &str,
    any: tribez::any_patch::AnyPatch,
) -> Result<(tribez::patch::BezierPatch, Option<tribez::rational::RationalPatch>), CliError> {
    use tribez::any_patch::AnyPatch;
    match any {
        AnyPatch::Bezier(p) | AnyPatch::Functional(p) => Ok((p, None)),
        AnyPatch::Rational(r) => Ok((r.patch.clone(), Some(r))),
        AnyPatch::SPatch(_) => Err(CliError::Usage(format!(
            "{file}: `tribez {command}` does not take S-patches"
        ))),
    }
}
