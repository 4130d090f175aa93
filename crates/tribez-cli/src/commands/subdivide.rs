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

use super::construct::{PiecesReport, barycentric_points, constructions};
use super::{CliError, Outcome};
use crate::cli::OutputArgs;
use crate::report::Render;
use tribez::Split;

// Arguments of `tribez subdivide` (a plain comment: see `Command`).
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
    let patch = tribez::Patch::from_file(&args.patch)?;
    let c = constructions(&file, "subdivide", &patch)?;
    let m = patch.simplex_dim();
    let (pieces, total, note) = match &args.at {
        Some(text) => {
            let t = barycentric_points(std::slice::from_ref(text), "at", m)?.remove(0);
            let note = boundary_note(&t, text)?;
            let pieces = c
                .pieces(&Split::At(&t))
                .map_err(|e| CliError::core(format!("--at {text}"), e))?;
            (pieces, m + 1, note)
        }
        None => {
            let pieces = c
                .pieces(&Split::Midpoints)
                .map_err(|e| CliError::core(&file, e))?;
            let n = pieces.len();
            (pieces, n, None)
        }
    };
    let pieces = PiecesReport::relabelled(pieces, |i| format!("piece {} of {total}", i + 1));
    Outcome::rendered(
        &Noted {
            note,
            inner: pieces,
        },
        args.out.format,
        true,
    )
}

/// The note naming the degenerate pieces left out when `t` lies on a facet (piece `k` replaces
/// corner `k` by the point, so `t_k = 0` makes it degenerate); a corner is an error.
fn boundary_note(t: &[BigRational], text: &str) -> Result<Option<String>, CliError> {
    let zero: Vec<usize> = (0..t.len()).filter(|&k| t[k].is_zero()).collect();
    if zero.is_empty() {
        return Ok(None);
    }
    if zero.len() + 1 >= t.len() {
        let corner = (0..t.len()).find(|k| !zero.contains(k)).unwrap_or(0) + 1;
        return Err(CliError::check(
            format!("--at {text}"),
            format!(
                "the point is corner {corner} of the domain: every piece but one would be degenerate and that one is the patch itself"
            ),
        ));
    }
    let names: Vec<String> = zero.iter().map(|k| (k + 1).to_string()).collect();
    let (piece_word, verb) = if zero.len() == 1 {
        ("piece", "is")
    } else {
        ("pieces", "are")
    };
    Ok(Some(format!(
        "--at {text} lies on the boundary (coordinate {} is 0): {piece_word} {} {verb} degenerate and omitted; piece k replaces corner k by the point",
        names.join(", "),
        names.join(", "),
    )))
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
