//! `tribez reproduce`: `tribez check` on the built-in fixtures, listing the known errata apart.

use std::path::PathBuf;

use super::check::{CheckReport, judge_paths};
use super::{CliError, Outcome};
use crate::cli::OutputArgs;

/// Arguments of `tribez reproduce`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// Directory of claim files (`*.claims.toml`, `*.claims.json`); default: the built-in `fixtures/`.
    pub dir: Option<PathBuf>,
    #[command(flatten)]
    pub out: OutputArgs,
}

/// The built-in fixtures directory: `./fixtures` if present, else the one in the source tree.
pub fn default_fixtures() -> PathBuf {
    let local = PathBuf::from("fixtures");
    if local.is_dir() {
        local
    } else {
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../fixtures")
    }
}

/// Run `tribez reproduce`.
pub fn run(args: &Args) -> Result<Outcome, CliError> {
    let dir = args.dir.clone().unwrap_or_else(default_fixtures);
    if !dir.is_dir() {
        return Err(CliError::Usage(format!(
            "{}: not a directory",
            dir.display()
        )));
    }
    let files = judge_paths(&[dir])?;
    let report = CheckReport {
        files,
        ok_word: "reproduced",
        regressions: Vec::new(),
    };
    let success = report.success();
    Outcome::rendered(&report, args.out.format, success)
}
