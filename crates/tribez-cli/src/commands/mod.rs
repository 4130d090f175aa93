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
pub mod fit;
pub mod graph;
pub mod halve;
pub mod hunt;
pub mod intersect;
pub mod inverse;
pub mod inverse_batch;
pub mod join;
pub mod matrix;
pub mod mesh;
pub mod plot;
pub mod reproduce;
pub mod subdivide;
pub mod subpatch;
pub mod symbolic;
pub mod tangent;

use std::io::Write;
use std::path::Path;

use num_rational::BigRational;

use std::path::PathBuf;

use clap::Parser;

use crate::cli::{LatexOutputArgs, OutputArgs, examples};
pub use crate::error::CliError;
pub(crate) use crate::output;
use crate::report::{Exporter, Format, JunitExporter, Render, render};
use tribez::InputError;
use tribez::format::parse_rational;

/// Exact computations on Bézier triangles (and simplices), used to certify floating-point code.
#[derive(Debug, Parser)]
#[command(name = "tribez", version, about, long_about = None, propagate_version = true)]
pub struct Cli {
    /// What to do.
    #[command(subcommand)]
    pub command: Command,
}

/// The subcommands; each maps to one function in `src/commands/<name>.rs`, and each `--help`
/// ends with examples ([`crate::cli::examples`]).
///
/// Each subcommand's arguments are built only when that subcommand is parsed or its help shown
/// (`defer`), not all of them at every start (about 0.2 ms of every run). clap then applies the
/// arguments after the variant's description, so a doc comment on an `Args` struct, or on a
/// struct flattened into one, would replace the description in that subcommand's `--help`: those
/// structs carry plain `//` comments (the test `every_help_starts_with_its_listed_description`
/// guards this).
#[derive(Debug, clap::Subcommand)]
#[command(defer = true)]
pub enum Command {
    /// Check every claim of the built-in fixtures (or of DIR) and list errata separately.
    #[command(after_help = examples::REPRODUCE)]
    Reproduce(reproduce::Args),
    /// Evaluate a patch exactly at barycentric (or Cartesian) points; optionally show f64/f32 results and their errors.
    #[command(after_help = examples::EVAL)]
    Eval(eval::Args),
    /// Print a patch as polynomials in the barycentric (or Cartesian) variables.
    #[command(after_help = examples::SYMBOLIC)]
    Symbolic(symbolic::Args),
    /// Write the graph (x, y, f(x, y)) of a functional patch as a parametric patch file.
    #[command(after_help = examples::GRAPH)]
    Graph(graph::Args),
    /// Judge claim files (or a batch of evaluation results with --patch/--results) against exact values.
    #[command(after_help = examples::CHECK)]
    Check(check::Args),
    /// Run tribez's own float algorithms (Bézier, rational, S-patch) and judge their errors against proven bounds.
    #[command(after_help = examples::CERTIFY)]
    Certify(certify::Args),
    /// Search for the inputs where another program is least accurate: it answers rows over a pipe, each judged exactly.
    #[command(after_help = examples::HUNT)]
    Hunt(hunt::Args),
    /// The blossom (polar form) b[u1, ..., un] of a patch (rational: X[..]/W[..]): exactly n barycentric arguments.
    #[command(after_help = examples::BLOSSOM)]
    Blossom(blossom::Args),
    /// The same polynomial over any sub-triangle (sub-simplex), as a patch file.
    #[command(after_help = examples::SUBPATCH)]
    Subpatch(subpatch::Args),
    /// Split a patch at a point (m+1 pieces) or at the edge midpoints (four pieces).
    #[command(after_help = examples::SUBDIVIDE)]
    Subdivide(subdivide::Args),
    /// Cut a patch in two from the midpoint of an edge to the opposite corner.
    #[command(after_help = examples::HALVE)]
    Halve(halve::Args),
    /// Raise the degree of a patch (the same surface), as a patch file.
    #[command(after_help = examples::ELEVATE)]
    Elevate(elevate::Args),
    /// The exact matrix mapping parent control points to a half's or a subpatch's.
    #[command(after_help = examples::MATRIX)]
    Matrix(matrix::Args),
    /// Directional derivative of any order r <= n at a point (barycentric --dir or Cartesian --vector directions).
    #[command(after_help = examples::DERIVATIVE)]
    Derivative(derivative::Args),
    /// Tangent plane at a point: the de Casteljau intermediate points, the partial derivatives and the normal.
    #[command(after_help = examples::TANGENT)]
    Tangent(tangent::Args),
    /// Draw a patch with its control net (SVG or PNG): shaded surfaces, planar images with iso-parameter lines, curves, graphs.
    #[command(after_help = examples::PLOT)]
    Plot(plot::Args),
    /// Smoothness of two patches across their common domain edge (C0, C1, C^r, G1, Finn's coplanarity), or build a C1 neighbour.
    #[command(after_help = examples::JOIN)]
    Join(join::Args),
    /// Every intersection of two planar curves, exactly: parameters as real algebraic numbers, tangency, overlaps.
    #[command(after_help = examples::INTERSECT)]
    Intersect(intersect::Args),
    /// Every parameter point of a planar triangle patch that maps to a given point, exactly (Jacobian zeros flagged).
    #[command(after_help = examples::LOCATE)]
    Locate(inverse::LocateArgs),
    /// Every hit of a ray on a patch in R^3 (or a functional patch's graph), in order, exactly; --height for a data lookup.
    #[command(after_help = examples::RAY)]
    Ray(inverse::RayArgs),
    /// Meshes of functional Bézier triangles sharing their ordinates (C0): `mesh check`, `mesh patch`.
    #[command(after_help = examples::MESH)]
    Mesh(mesh::Args),
    /// The triangle(s) of a mesh containing a point and the exact value there; --float for the GPU path's errors.
    #[command(after_help = examples::LOOKUP)]
    Lookup(mesh::LookupArgs),
    /// The exact least-squares fit of data x,y,value by a mesh (C0 or C1): the fitted mesh, the residuals exact and as decimals.
    #[command(after_help = examples::FIT)]
    Fit(fit::Args),
}

/// Where a command's output goes: `-o FILE`, or standard output.
pub trait OutputTarget {
    /// The `-o FILE` given, if any.
    fn output(&self) -> Option<&PathBuf>;
}

impl OutputTarget for OutputArgs {
    fn output(&self) -> Option<&PathBuf> {
        self.output.as_ref()
    }
}

impl OutputTarget for LatexOutputArgs {
    fn output(&self) -> Option<&PathBuf> {
        self.output.as_ref()
    }
}

/// What a command produced: its rendered output and whether every claim held.
pub struct Outcome {
    /// Rendered output, in parts written one after another (a large report is rendered in
    /// parts on all cores, and they are written without being joined).
    pub output: Vec<String>,
    /// False when some claim failed (exit status 1).
    pub success: bool,
}

impl Outcome {
    /// Render a result in the requested format; formats that do not apply are a usage error.
    pub fn rendered(
        r: &dyn Render,
        format: impl Into<Format>,
        success: bool,
    ) -> Result<Self, CliError> {
        let format = format.into();
        let output = render(r, format).ok_or_else(|| {
            CliError::Usage(
                format!("--format {format:?} is not available for this command").to_lowercase(),
            )
        })?;
        Ok(Outcome {
            output: vec![output],
            success,
        })
    }
}

/// Run the command line; returns the exit status.
///
/// The output files a command staged (see [`output`]) are committed only when it ran to the end
/// (exit status 0 or 1) and its report was written; a run that exits 2 leaves none.
pub fn main(cli: Cli) -> i32 {
    let (result, out): (_, &dyn OutputTarget) = match &cli.command {
        Command::Reproduce(a) => (reproduce::run(a), &a.out),
        Command::Eval(a) => (eval::run(a), a),
        Command::Symbolic(a) => (symbolic::run(a), &a.out),
        Command::Graph(a) => (graph::run(a), &a.out),
        Command::Check(a) if a.results.is_some() && a.mesh.is_some() => {
            (mesh::run_batch(a), &a.out)
        }
        Command::Check(a) if a.results.is_some() => (batch::run(a), &a.out),
        Command::Check(a) if a.locate_results.is_some() || a.ray_results.is_some() => {
            (inverse_batch::run(a), &a.out)
        }
        Command::Check(a) if a.fit.is_some() => (fit::run_check(a), &a.out),
        Command::Check(a) => (check::run(a), &a.out),
        Command::Certify(a) => (certify::run(a), &a.out),
        Command::Hunt(a) => (hunt::run(a), &a.out),
        Command::Blossom(a) => (blossom::run(a), &a.out),
        Command::Subpatch(a) => (subpatch::run(a), &a.out),
        Command::Subdivide(a) => (subdivide::run(a), &a.out),
        Command::Halve(a) => (halve::run(a), &a.out),
        Command::Elevate(a) => (elevate::run(a), &a.out),
        Command::Matrix(a) => (matrix::run(a), &a.out),
        Command::Derivative(a) => (derivative::run(a), &a.out),
        Command::Tangent(a) => (tangent::run(a), &a.out),
        Command::Join(a) => (join::run(a), &a.out),
        Command::Intersect(a) => (intersect::run(a), &a.out),
        Command::Locate(a) => (inverse::run_locate(a), &a.out),
        Command::Ray(a) => (inverse::run_ray(a), &a.out),
        Command::Mesh(a) => (mesh::run(a), mesh::output(a)),
        Command::Lookup(a) => (mesh::run_lookup(a), &a.out),
        Command::Fit(a) => (fit::run(a), a),
        Command::Plot(a) => (plot::run(a), a),
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
pub fn emit(outcome: &Outcome, out: &dyn OutputTarget) -> Result<(), CliError> {
    match out.output() {
        None => output::write_stdout_parts(&outcome.output),
        Some(path) => output::stage_parts(path, &outcome.output),
    }
}

/// Stage `bytes` as the new content of `path` (see [`output::stage`]): the file is written whole
/// when the run ends with exit status 0 or 1, and not at all otherwise.
pub fn write_atomically(path: &Path, bytes: &[u8]) -> Result<(), CliError> {
    output::stage(path, bytes)
}

/// Stage the JUnit XML of `report` as `path` (see [`write_atomically`]).
pub fn write_junit(path: &Path, report: &dyn Render) -> Result<(), CliError> {
    let xml = JunitExporter
        .export(report)
        .ok_or_else(|| CliError::Usage("--junit is not available for this command".into()))?;
    output::stage(path, xml.as_bytes())
}

/// Parse a comma-separated list of exact numbers from the command line (`1/2,1/3,1/6`).
pub fn parse_list(text: &str, what: &str) -> Result<Vec<BigRational>, CliError> {
    text.split(',')
        .enumerate()
        .map(|(i, t)| {
            parse_rational(t).map_err(|e| {
                InputError::file("<command line>", e)
                    .with_key(format!("{what} `{text}`, coordinate {}", i + 1))
            })
        })
        .collect::<Result<_, _>>()
        .map_err(CliError::from)
}

pub use tribez::constructions::{check_barycentric, check_direction};

/// The barycentric point of `--at TEXT`: checked to sum to 1 on the `m`-simplex, or with
/// `cartesian` converted by `domain` (Cramer's rule). Errors name `--at TEXT`.
pub fn at_point(
    text: &str,
    cartesian: bool,
    domain: &tribez::constructions::Domain,
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

/// The constructions of `patch` (read from `file`) for `tribez {command}`; a kind without them
/// (S-patches) is a usage error naming the command.
pub fn constructions<'a>(
    patch: &'a tribez::Patch,
    file: &str,
    command: &str,
) -> Result<Box<dyn tribez::Constructions + 'a>, CliError> {
    patch.constructions().ok_or_else(|| {
        CliError::Usage(format!(
            "{file}: `tribez {command}` does not take {}",
            patch.kind().plural()
        ))
    })
}
