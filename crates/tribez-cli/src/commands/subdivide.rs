//! `tribez subdivide`: split a patch at a point (m+1 pieces, docs/theory.md §5.1) or, for
//! triangles, at the edge midpoints (four pieces, §5.3).

use std::path::PathBuf;

use super::construct::{
    PiecesReport, barycentric_points, child_patch, construction_net, rational_pieces,
};
use super::{CliError, Outcome};
use crate::cli::OutputArgs;
use tribez::io::patch_file::read_any_patch;
use tribez::subdivide::{midpoint_split, split_at_pieces};

/// Arguments of `tribez subdivide`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// The patch file (.toml or .json).
    pub patch: PathBuf,
    /// Split at this barycentric point: piece k replaces corner k by the point.
    #[arg(
        long = "at",
        value_name = "POINT",
        conflicts_with = "midpoints",
        required_unless_present = "midpoints"
    )]
    pub at: Option<String>,
    /// Four-way split at the edge midpoints (triangles only).
    #[arg(long)]
    pub midpoints: bool,
    #[command(flatten)]
    pub out: OutputArgs,
}

/// Run `tribez subdivide`.
pub fn run(args: &Args) -> Result<Outcome, CliError> {
    let file = args.patch.display().to_string();
    let (parent, rational) = construction_net(&file, "subdivide", read_any_patch(&args.patch)?)?;
    let m = parent.net.m();
    let pieces = match &args.at {
        Some(text) => {
            let t = barycentric_points(std::slice::from_ref(text), "at", m)?.remove(0);
            split_at_pieces(&parent.net, &t)
                .map_err(|e| CliError::core(format!("--at {text}"), e))?
        }
        None => midpoint_split(&parent.net).map_err(|e| CliError::core(&file, e))?,
    };
    let total = pieces.len();
    if let Some(r) = rational {
        let report = rational_pieces(&file, &r, pieces, |k| format!("piece {} of {total}", k + 1))?;
        return Outcome::rendered(&report, args.out.format, true);
    }
    let pieces = pieces
        .into_iter()
        .enumerate()
        .map(|(k, p)| {
            let patch = child_patch(
                &parent,
                p.net,
                Some(&p.domain_in_parent),
                &format!("piece {} of {total}", k + 1),
            )?;
            Ok((p.domain_in_parent, patch))
        })
        .collect::<Result<_, CliError>>()?;
    Outcome::rendered(&PiecesReport { pieces }, args.out.format, true)
}
