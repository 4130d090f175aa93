//! `tribez subpatch`: the same polynomial over any sub-simplex (docs/theory.md §4, §11):
//! `c′_α = b[f_1^{α_1}, …, f_{m+1}^{α_{m+1}}]`.

use std::path::PathBuf;

use num_rational::BigRational;
use serde_json::Value as Json;

use super::construct::AnyPatchReport;
use super::construct::{PatchReport, barycentric_points, child_patch};
use super::{CliError, Outcome};
use crate::cli::OutputArgs;
use crate::report::Render;
use tribez::hazmat::any_patch::AnyPatch;
use tribez::hazmat::error::CoreError;
use tribez::hazmat::io::patch_file::read_any_patch;

/// Arguments of `tribez subpatch`.
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

/// A rational subpatch: the patch file (with `[weights]`) and, as for a polynomial subpatch,
/// `domain_in_parent` (its simplex in the parent's barycentric coordinates).
pub struct RationalSubpatchReport {
    /// The rational patch.
    pub patch: AnyPatch,
    /// Its vertices in the parent's barycentric coordinates.
    pub domain_in_parent: Vec<Vec<BigRational>>,
}

impl Render for RationalSubpatchReport {
    fn text(&self) -> String {
        let text = AnyPatchReport(self.patch.clone()).text();
        let rows: Vec<String> = self
            .domain_in_parent
            .iter()
            .map(|p| {
                let xs: Vec<String> = p.iter().map(|x| format!("\"{x}\"")).collect();
                format!("[{}]", xs.join(", "))
            })
            .collect();
        let line = format!("domain_in_parent = [{}]\n", rows.join(", "));
        // top-level keys come before the first table
        match text.find("\n[") {
            Some(k) => format!("{}{line}{}", &text[..k], &text[k..]),
            None => text + &line,
        }
    }
    fn json(&self) -> Json {
        super::construct::json_with_any(&self.patch, Some(&self.domain_in_parent))
    }
}

/// Run `tribez subpatch`.
pub fn run(args: &Args) -> Result<Outcome, CliError> {
    let file = args.patch.display().to_string();
    let (parent, rational) = super::points_patch(&file, "subpatch", read_any_patch(&args.patch)?)?;
    let m = parent.net.m();
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
    if let Some(r) = rational {
        // a rational patch: the subpatch of the homogeneous net (w c, w)
        let mut sub = r.subpatch(&f).map_err(|e| CliError::core(context, e))?;
        sub.patch = child_patch(&parent, sub.patch.net, Some(&f), "subpatch")?;
        return Outcome::rendered(
            &RationalSubpatchReport {
                patch: AnyPatch::Rational(sub),
                domain_in_parent: f,
            },
            args.out.format,
            true,
        );
    }
    let net = tribez::hazmat::blossom::subpatch(&parent.net, &f)
        .map_err(|e| CliError::core(context, e))?;
    let patch = child_patch(&parent, net, Some(&f), "subpatch")?;
    Outcome::rendered(
        &PatchReport {
            patch,
            domain_in_parent: Some(f),
        },
        args.out.format,
        true,
    )
}
