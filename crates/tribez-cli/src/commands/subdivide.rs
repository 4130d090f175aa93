//! `tribez subdivide`: split a patch at a point (m+1 pieces, docs/theory.md §5.1) or, for
//! triangles, at the edge midpoints (four pieces, §5.3).
//!
//! Piece k replaces corner k by the point. A point on a facet (`t_k = 0`: on an edge of a
//! triangle) makes piece k degenerate: the other pieces are given, piece k is omitted and a note
//! says so. A corner of the domain (one nonzero coordinate) splits nothing and is an error.

use std::path::PathBuf;

use num_rational::BigRational;
use num_traits::Zero;
use serde_json::Value as Json;

use super::construct::{
    PiecesReport, barycentric_points, child_patch, construction_net, rational_pieces,
};
use super::{CliError, Outcome};
use crate::cli::OutputArgs;
use crate::report::Render;
use tribez::hazmat::io::patch_file::read_any_patch;
use tribez::hazmat::subdivide::{Piece, midpoint_split, replaced, split_at, split_at_pieces};

/// Arguments of `tribez subdivide`.
#[derive(Debug, clap::Args)]
#[command(group(clap::ArgGroup::new("mode").required(true).args(["at", "midpoints"])))]
pub struct Args {
    /// The patch file (.toml or .json).
    pub patch: PathBuf,
    /// Split at this barycentric point (m+1 coordinates, may be negative): piece k replaces corner k by the point.
    #[arg(long = "at", value_name = "POINT", allow_hyphen_values = true)]
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
    // (piece, its number among the m+1 of a split at a point)
    let (pieces, numbers, total, note): (Vec<Piece<BigRational>>, Vec<usize>, usize, _) =
        match &args.at {
            Some(text) => {
                let t = barycentric_points(std::slice::from_ref(text), "at", m)?.remove(0);
                let (pieces, numbers, note) = split_at_point(&parent.net, &t, text)?;
                (pieces, numbers, m + 1, note)
            }
            None => {
                let pieces = midpoint_split(&parent.net).map_err(|e| CliError::core(&file, e))?;
                let n = pieces.len();
                (pieces, (1..=n).collect(), n, None)
            }
        };
    let label = |k: usize| format!("piece {} of {total}", numbers[k]);
    if let Some(r) = rational {
        let report = rational_pieces(&file, &r, pieces, label)?;
        return Outcome::rendered(
            &Noted {
                note,
                inner: report,
            },
            args.out.format,
            true,
        );
    }
    let pieces = pieces
        .into_iter()
        .enumerate()
        .map(|(k, p)| {
            let patch = child_patch(&parent, p.net, Some(&p.domain_in_parent), &label(k))?;
            Ok((p.domain_in_parent, patch))
        })
        .collect::<Result<_, CliError>>()?;
    Outcome::rendered(
        &Noted {
            note,
            inner: PiecesReport { pieces },
        },
        args.out.format,
        true,
    )
}

/// Pieces, their numbers among the m+1 of the full split, and the note on degenerate pieces.
type Split = (Vec<Piece<BigRational>>, Vec<usize>, Option<String>);

/// The pieces of a split at `t` with their numbers (1-based: piece k replaces corner k), and a
/// note naming the degenerate pieces omitted when `t` lies on a facet. A corner is an error.
fn split_at_point(
    net: &tribez::hazmat::patch::ControlNet<BigRational>,
    t: &[BigRational],
    text: &str,
) -> Result<Split, CliError> {
    let what = || format!("--at {text}");
    let zero: Vec<usize> = (0..t.len()).filter(|&k| t[k].is_zero()).collect();
    if zero.is_empty() {
        let pieces = split_at_pieces(net, t).map_err(|e| CliError::core(what(), e))?;
        let n = pieces.len();
        return Ok((pieces, (1..=n).collect(), None));
    }
    if zero.len() + 1 >= t.len() {
        let corner = (0..t.len()).find(|k| !zero.contains(k)).unwrap_or(0) + 1;
        return Err(CliError::check(
            what(),
            format!(
                "the point is corner {corner} of the domain: every piece but one would be degenerate and that one is the patch itself"
            ),
        ));
    }
    let m = net.m();
    let (pieces, numbers): (Vec<_>, Vec<_>) = split_at(net, t)
        .into_iter()
        .enumerate()
        .filter(|(s, _)| !t[*s].is_zero())
        .map(|(s, n)| {
            (
                Piece {
                    domain_in_parent: replaced(m, s, t),
                    net: n,
                },
                s + 1,
            )
        })
        .unzip();
    let names: Vec<String> = zero.iter().map(|k| (k + 1).to_string()).collect();
    let (piece_word, verb) = if zero.len() == 1 {
        ("piece", "is")
    } else {
        ("pieces", "are")
    };
    let note = format!(
        "--at {text} lies on the boundary (coordinate {} is 0): {piece_word} {} {verb} degenerate and omitted; piece k replaces corner k by the point",
        names.join(", "),
        names.join(", "),
    );
    Ok((pieces, numbers, Some(note)))
}

/// A report with an optional note: a `#` comment first in text (the TOML document stays valid),
/// a `"note"` key in JSON.
struct Noted<R> {
    note: Option<String>,
    inner: R,
}

impl<R: Render> Render for Noted<R> {
    fn text(&self) -> String {
        match &self.note {
            Some(n) => format!("# {n}\n{}", self.inner.text()),
            None => self.inner.text(),
        }
    }
    fn json(&self) -> Json {
        let mut j = self.inner.json();
        if let (Some(n), Some(obj)) = (&self.note, j.as_object_mut()) {
            obj.insert("note".into(), Json::String(n.clone()));
        }
        j
    }
}
