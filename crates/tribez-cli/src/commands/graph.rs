//! `tribez graph`: the graph `(x, y, f(x, y))` of a functional patch as a parametric patch file
//! (docs/theory.md §13: control points `(ξ_α, b_α)` at the Bézier abscissae).

use std::path::PathBuf;

use serde_json::Value as Json;

use super::construct::{PieceJson, PiecesJson, point_strings};
use super::{CliError, Outcome};
use crate::cli::OutputArgs;
use crate::report::Render;
use tribez::Patch;
use tribez::hazmat::any_patch::AnyPatch;
use tribez::hazmat::io::patch_file::{any_patch_to_json, any_patch_to_toml, read_any_patch};

/// Arguments of `tribez graph`.
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
    let patch = Patch::from(read_any_patch(&args.patch)?);
    let graph = patch.constructions().and_then(|c| c.graph()).ok_or_else(|| {
        CliError::Usage(format!(
            "{file}: `tribez graph` takes a functional patch (kind = \"functional\"), this is a {} patch",
            patch.kind().name()
        ))
    })?;
    let g = graph.map_err(|e| CliError::core(&file, e))?;
    Outcome::rendered(&AnyPatchReport(g), args.out.format, true)
}

/// A patch of any kind, written as a patch file (TOML text, or JSON): the output of commands that
/// construct rational patches (`elevate`, `subpatch`).
pub struct AnyPatchReport(pub AnyPatch);

impl Render for AnyPatchReport {
    fn text(&self) -> String {
        any_patch_to_toml(&self.0)
    }

    fn json(&self) -> Json {
        any_patch_to_json(&self.0)
    }
}

/// Pieces of a rational patch (`subdivide`), in the layout of the polynomial pieces report:
/// `[[pieces]]` with `domain_in_parent` and a `[pieces.patch]` table (now with `weights`).
pub struct AnyPiecesReport(pub Vec<(Vec<Vec<num_rational::BigRational>>, AnyPatch)>);

fn toml_rows(f: &[Vec<num_rational::BigRational>]) -> String {
    let rows: Vec<String> = f
        .iter()
        .map(|p| {
            let xs: Vec<String> = p.iter().map(|x| format!("\"{x}\"")).collect();
            format!("[{}]", xs.join(", "))
        })
        .collect();
    format!("[{}]", rows.join(", "))
}

impl Render for AnyPiecesReport {
    fn text(&self) -> String {
        let mut out = String::new();
        for (i, (f, p)) in self.0.iter().enumerate() {
            if i > 0 {
                out.push('\n');
            }
            out += &format!(
                "[[pieces]]\ndomain_in_parent = {}\n\n[pieces.patch]\n",
                toml_rows(f)
            );
            out += &any_patch_to_toml(p)
                .replace("\n[control_points]\n", "\n[pieces.patch.control_points]\n")
                .replace("\n[weights]\n", "\n[pieces.patch.weights]\n");
        }
        out
    }

    fn json(&self) -> Json {
        crate::report::to_json(&PiecesJson {
            pieces: self
                .0
                .iter()
                .map(|(f, p)| PieceJson {
                    domain_in_parent: point_strings(f),
                    patch: any_patch_to_json(p),
                })
                .collect(),
        })
    }
}
