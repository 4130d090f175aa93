//! Command-line arguments (clap derive). Each subcommand's arguments live beside its code in
//! [`crate::commands`].

use std::path::PathBuf;

use clap::{Parser, Subcommand};

use crate::commands;
use crate::report::Format;

/// Exact computations on Bézier triangles (and simplices), used to certify floating-point code.
#[derive(Debug, Parser)]
#[command(name = "tribez", version, about, long_about = None, propagate_version = true)]
pub struct Cli {
    /// What to do.
    #[command(subcommand)]
    pub command: Command,
}

/// The subcommands; each maps to one function in `src/commands/<name>.rs`.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Check every claim of the built-in fixtures (or of DIR) and list errata separately.
    Reproduce(commands::reproduce::Args),
    /// Evaluate a patch exactly at barycentric (or Cartesian) points; optionally show f64/f32 results and their errors.
    Eval(commands::eval::Args),
    /// Print a patch as polynomials in the barycentric (or Cartesian) variables.
    Symbolic(commands::symbolic::Args),
    /// Write the graph (x, y, f(x, y)) of a functional patch as a parametric patch file.
    Graph(commands::graph::Args),
    /// Judge claim files (or a batch of evaluation results with --patch/--results) against exact values.
    Check(commands::check::Args),
    /// Run tribez's own float algorithms (Bézier, rational, S-patch) and judge their errors against proven bounds.
    Certify(commands::certify::Args),
    /// The blossom (polar form) b[u1, ..., un] of a patch (rational: X[..]/W[..]): exactly n barycentric arguments.
    Blossom(commands::blossom::Args),
    /// The same polynomial over any sub-triangle (sub-simplex), as a patch file.
    Subpatch(commands::subpatch::Args),
    /// Split a patch at a point (m+1 pieces) or at the edge midpoints (four pieces).
    Subdivide(commands::subdivide::Args),
    /// Cut a patch in two from the midpoint of an edge to the opposite corner.
    Halve(commands::halve::Args),
    /// Raise the degree of a patch (the same surface), as a patch file.
    Elevate(commands::elevate::Args),
    /// The exact matrix mapping parent control points to a half's or a subpatch's.
    Matrix(commands::matrix::Args),
    /// Directional derivative of any order r <= n at a point (barycentric --dir or Cartesian --vector directions).
    Derivative(commands::derivative::Args),
    /// Tangent plane at a point: the de Casteljau intermediate points, the partial derivatives and the normal.
    Tangent(commands::tangent::Args),
    /// Smoothness of two patches across their common domain edge (C0, C1, C^r, G1, Finn's coplanarity), or build a C1 neighbour.
    Join(commands::join::Args),
}

/// Output options shared by every command.
#[derive(Debug, Clone, clap::Args)]
pub struct OutputArgs {
    /// Output format.
    #[arg(long, value_enum, default_value_t = Format::Text)]
    pub format: Format,
    /// Write the output to FILE (whole or not at all) instead of standard output.
    #[arg(long, short = 'o', value_name = "FILE")]
    pub output: Option<PathBuf>,
}
