//! `tribez elevate`: degree elevation by R steps (docs/theory.md §6): the same surface, degree n + R.

use std::path::PathBuf;

use super::construct::AnyPatchReport;
use super::construct::{PatchReport, check_size, child_patch};
use super::{CliError, Outcome};
use crate::cli::OutputArgs;
use tribez::hazmat::any_patch::AnyPatch;
use tribez::hazmat::io::patch_file::read_any_patch;

/// Arguments of `tribez elevate`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// The patch file (.toml or .json).
    pub patch: PathBuf,
    /// Raise the degree by R (at least 1).
    #[arg(long = "by", value_name = "R", default_value_t = 1, value_parser = crate::cli::whole_number::<usize>(1, u64::MAX), allow_negative_numbers = true)]
    pub by: usize,
    #[command(flatten)]
    pub out: OutputArgs,
}

/// Run `tribez elevate`.
pub fn run(args: &Args) -> Result<Outcome, CliError> {
    let file = args.patch.display().to_string();
    let (parent, rational) = super::points_patch(&file, "elevate", read_any_patch(&args.patch)?)?;
    if let Some(r) = rational {
        // a rational patch: elevate the homogeneous net (w c, w)
        let (m, n) = (r.patch.net.m(), r.patch.net.degree());
        check_size(m, n.saturating_add(args.by), &format!("--by {}", args.by))?;
        let mut up = r.elevate(args.by).map_err(|e| CliError::core(&file, e))?;
        let label = format!("elevated to degree {}", n + args.by);
        up.patch = child_patch(&r.patch, up.patch.net, None, &label)?;
        return Outcome::rendered(
            &AnyPatchReport(AnyPatch::Rational(up)),
            args.out.format,
            true,
        );
    }
    let (m, n) = (parent.net.m(), parent.net.degree());
    check_size(m, n.saturating_add(args.by), &format!("--by {}", args.by))?;
    let net = tribez::hazmat::elevate::elevate(&parent.net, args.by);
    let patch = child_patch(
        &parent,
        net,
        None,
        &format!("elevated to degree {}", n + args.by),
    )?;
    Outcome::rendered(
        &PatchReport {
            patch,
            domain_in_parent: None,
        },
        args.out.format,
        true,
    )
}
