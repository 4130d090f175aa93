//! `tribez reproduce`: `tribez check` on the built-in fixtures, listing the known errata apart.
//!
//! The fixtures are embedded in the binary at build time (`build.rs`), so the command works from
//! any directory and from an installed binary. They are unpacked into a fresh temporary
//! directory (removed afterwards) so that each claim file finds the patch files beside it, and
//! reported under their names in the repository (`fixtures/…`).

use std::path::{Path, PathBuf};

use super::check::judge_paths;
use super::{CliError, Outcome};
use crate::cli::OutputArgs;
use tribez::claims::ClaimsOptions;

mod embedded {
    include!(concat!(env!("OUT_DIR"), "/fixtures.rs"));
}

// Arguments of `tribez reproduce` (a plain comment: see `Command`).
#[derive(Debug, clap::Args)]
pub struct Args {
    /// Directory of claim files (`*.claims.toml`, `*.claims.json`); default: the fixtures built into tribez (the repository's `fixtures/`).
    pub dir: Option<PathBuf>,
    #[command(flatten)]
    pub out: OutputArgs,
}

/// The built-in fixtures: (path under `fixtures/`, content).
pub fn builtin_fixtures() -> &'static [(&'static str, &'static [u8])] {
    embedded::FIXTURES
}

/// Unpack the built-in fixtures into `dir/fixtures`; returns that directory.
fn unpack(dir: &Path) -> Result<PathBuf, CliError> {
    let root = dir.join("fixtures");
    for (rel, bytes) in builtin_fixtures() {
        let path = root.join(rel);
        let written = path
            .parent()
            .map_or(Ok(()), std::fs::create_dir_all)
            .and_then(|()| std::fs::write(&path, bytes));
        written.map_err(|e| {
            CliError::check(
                path.display().to_string(),
                format!("cannot unpack the built-in fixtures: {e}"),
            )
        })?;
    }
    Ok(root)
}

/// Run `tribez reproduce`.
pub fn run(args: &Args) -> Result<Outcome, CliError> {
    let options = ClaimsOptions { reproduce: true };
    let report = match &args.dir {
        Some(dir) => {
            if !dir.is_dir() {
                return Err(CliError::Usage(format!(
                    "{}: not a directory",
                    dir.display()
                )));
            }
            judge_paths(std::slice::from_ref(dir), &options)?
        }
        None => {
            if builtin_fixtures().is_empty() {
                return Err(CliError::Usage(
                    "this tribez was built without fixtures: give a directory of claim files"
                        .into(),
                ));
            }
            let tmp = tempfile::tempdir().map_err(|e| {
                CliError::check(
                    std::env::temp_dir().display().to_string(),
                    format!("cannot unpack the built-in fixtures: {e}"),
                )
            })?;
            let root = unpack(tmp.path())?;
            let mut report = judge_paths(&[root], &options)?;
            // report the files under their names in the repository, not the temporary copy's
            let rename = |name: &mut String| {
                if let Ok(rel) = Path::new(name.as_str()).strip_prefix(tmp.path()) {
                    *name = rel
                        .components()
                        .map(|c| c.as_os_str().to_string_lossy().into_owned())
                        .collect::<Vec<_>>()
                        .join("/");
                }
            };
            for f in &mut report.files {
                rename(&mut f.file);
                f.claims.iter_mut().for_each(|j| rename(&mut j.file));
            }
            report
        }
    };
    let success = report.success();
    Outcome::rendered(&report, args.out.format, success)
}
