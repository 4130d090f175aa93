//! `tribez graph`: the graph `(x, y, f(x, y))` of a functional patch as a parametric patch file
//! (docs/theory.md §13: control points `(ξ_α, b_α)` at the Bézier abscissae).

use std::path::PathBuf;

use super::construct::PatchReport;
use super::{CliError, Outcome};
use crate::cli::OutputArgs;
use tribez::Patch;

// Arguments of `tribez graph` (a plain comment: see `Command`).
#[derive(Debug, clap::Args)]
pub struct Args {
    /// A functional patch file (`kind = "functional"`).
    pub patch: PathBuf,
    #[command(flatten)]
    pub out: OutputArgs,
}

/// Run `tribez graph`.
pub fn run(args: &Args) -> Result<Outcome, CliError> {
    let file = args.patch.display().to_string();
    let patch = Patch::from_file(&args.patch)?;
    let graph = patch.constructions().and_then(|c| c.graph()).ok_or_else(|| {
        CliError::Usage(format!(
            "{file}: `tribez graph` takes a functional patch (kind = \"functional\"), this is a {} patch",
            patch.kind().name()
        ))
    })?;
    let g = graph.map_err(|e| CliError::core(&file, e))?;
    Outcome::rendered(&PatchReport::of(g), args.out.format, true)
}
