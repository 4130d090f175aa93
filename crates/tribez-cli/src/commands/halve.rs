//! `tribez halve`: cut a patch in two from the midpoint of the edge between corners I and J to
//! the opposite corner (docs/theory.md §5.2). The first piece is the parent with corner J replaced by
//! the midpoint, the second with corner I replaced, each keeping the parent's vertex order.
//! A rational patch is halved through its homogeneous net (points and weights).

use std::path::PathBuf;

use super::construct::{PiecesReport, child_patch, construction_net, parse_edge, rational_pieces};
use super::{CliError, Outcome};
use crate::cli::OutputArgs;
use tribez::hazmat::io::patch_file::read_any_patch;
use tribez::hazmat::subdivide::{HalvingOrder, Piece, add_and_halve, halve, halve_domains};

/// Arguments of `tribez halve`.
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
    let (parent, rational) = construction_net(&file, "halve", read_any_patch(&args.patch)?)?;
    let (i, j) = parse_edge(&args.edge, parent.net.m())?;
    let halves = if args.add_and_halve {
        let [a, b] = halve_domains(parent.net.m(), i, j);
        [
            Piece {
                domain_in_parent: a,
                net: add_and_halve(&parent.net, i, j, HalvingOrder::TopDown),
            },
            Piece {
                domain_in_parent: b,
                net: add_and_halve(&parent.net, j, i, HalvingOrder::TopDown),
            },
        ]
    } else {
        halve(&parent.net, i, j)
    };
    let label = |k: usize| format!("half {} of edge {}", k + 1, args.edge);
    if let Some(r) = rational {
        let report = rational_pieces(&file, &r, halves.into(), label)?;
        return Outcome::rendered(&report, args.out.format, true);
    }
    let pieces = halves
        .into_iter()
        .enumerate()
        .map(|(k, p)| {
            let patch = child_patch(&parent, p.net, Some(&p.domain_in_parent), &label(k))?;
            Ok((p.domain_in_parent, patch))
        })
        .collect::<Result<_, CliError>>()?;
    Outcome::rendered(&PiecesReport { pieces }, args.out.format, true)
}
