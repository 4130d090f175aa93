//! `tribez elevate`: degree elevation by R steps (docs/theory.md §6): the same surface, degree n + R.

use std::path::PathBuf;

use super::construct::{PatchReport, check_size, constructions, relabel};
use super::{CliError, Outcome};
use crate::cli::OutputArgs;

// Arguments of `tribez elevate` (a plain comment: see `Command`).
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
    let patch = tribez::Patch::from_file(&args.patch)?;
    let c = constructions(&file, "elevate", &patch)?;
    let (m, n) = (patch.simplex_dim(), patch.degree());
    check_size(m, n.saturating_add(args.by), &format!("--by {}", args.by))?;
    let mut up = tribez::Patch::from(c.elevate(args.by).map_err(|e| CliError::core(&file, e))?);
    relabel(&mut up, &format!("elevated to degree {}", n + args.by));
    Outcome::rendered(&PatchReport::of(up), args.out.format, true)
}
