//! `tribez subpatch`: the same patch over any sub-simplex (docs/theory.md §4, §11):
//! `c′_α = b[f_1^{α_1}, …, f_{m+1}^{α_{m+1}}]` (for a rational patch, of its homogeneous net).

use std::path::PathBuf;

use super::construct::{PatchReport, barycentric_points, constructions, relabel};
use super::{CliError, Outcome};
use crate::cli::OutputArgs;
use tribez::CoreError;

// Arguments of `tribez subpatch` (a plain comment: see `Command`).
#[derive(Debug, clap::Args)]
pub struct Args {
    /// The patch file (.toml or .json).
    pub patch: PathBuf,
    /// A vertex of the sub-triangle (sub-simplex) in the parent's barycentric coordinates; may lie outside. Give m+1 (3 for a triangle), in order.
    #[arg(long = "vertex", value_name = "POINT", allow_hyphen_values = true)]
    pub vertices: Vec<String>,
    #[command(flatten)]
    pub out: OutputArgs,
}

/// Run `tribez subpatch`.
pub fn run(args: &Args) -> Result<Outcome, CliError> {
    let file = args.patch.display().to_string();
    let patch = tribez::Patch::from_file(&args.patch)?;
    let c = constructions(&file, "subpatch", &patch)?;
    let m = patch.simplex_dim();
    if args.vertices.len() != m + 1 {
        return Err(CliError::core(
            "--vertex",
            CoreError::WrongLength {
                what: format!("the sub-simplex of a patch over the {m}-simplex (vertices given)"),
                expected: m + 1,
                found: args.vertices.len(),
            },
        ));
    }
    let f = barycentric_points(&args.vertices, "vertex", m)?;
    let context = args
        .vertices
        .iter()
        .map(|v| format!("--vertex {v}"))
        .collect::<Vec<_>>()
        .join(" ");
    let mut sub = tribez::Patch::from(c.subpatch(&f).map_err(|e| CliError::core(context, e))?);
    relabel(&mut sub, "subpatch");
    Outcome::rendered(
        &PatchReport {
            patch: sub,
            domain_in_parent: Some(f),
        },
        args.out.format,
        true,
    )
}
