//! `tribez halve`: cut a patch in two from the midpoint of the edge between corners I and J to
//! the opposite corner (docs/theory.md §5.2). The first piece is the parent with corner J replaced by
//! the midpoint, the second with corner I replaced, each keeping the parent's vertex order.
//! A rational patch is halved through its homogeneous net (points and weights).

use std::path::PathBuf;

use super::construct::{PiecesReport, constructions, parse_edge};
use super::{CliError, Outcome};
use crate::cli::OutputArgs;
use tribez::{HalvingOrder, Split};

// Arguments of `tribez halve` (a plain comment: see `Command`).
#[derive(Debug, clap::Args)]
pub struct Args {
    /// The patch file (.toml or .json).
    pub patch: PathBuf,
    /// The edge to cut, as two corner numbers (1 to m+1), e.g. `1,2`.
    #[arg(long, value_name = "I,J", allow_hyphen_values = true)]
    pub edge: String,
    /// Compute with the Wikipedia article's additions and divisions by two only (in place, row by row), instead of blossoms; the result is the same.
    #[arg(long)]
    pub add_and_halve: bool,
    #[command(flatten)]
    pub out: OutputArgs,
}

/// Run `tribez halve`.
pub fn run(args: &Args) -> Result<Outcome, CliError> {
    let file = args.patch.display().to_string();
    let patch = tribez::Patch::from_file(&args.patch)?;
    let c = constructions(&file, "halve", &patch)?;
    let edge = parse_edge(&args.edge, patch.simplex_dim())?;
    let split = Split::Halve {
        edge,
        add_and_halve: args.add_and_halve.then_some(HalvingOrder::TopDown),
    };
    let halves = c.pieces(&split).map_err(|e| CliError::core(&file, e))?;
    let halves =
        PiecesReport::relabelled(halves, |i| format!("half {} of edge {}", i + 1, args.edge));
    Outcome::rendered(&halves, args.out.format, true)
}
