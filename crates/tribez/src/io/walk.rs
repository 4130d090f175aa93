//! Walking a directory tree for input files, safely.
//!
//! * Subdirectories are entered, but **symbolic links to directories are not followed** (so a
//!   link to `.` or to `/` can neither loop nor walk the whole file system); a directory reached
//!   twice (a bind mount) is entered once.
//! * A symbolic link to a regular file is read like the file; **each file is counted once**,
//!   however many names lead to it (a name that is not a link is kept first, then the first
//!   in sorted order).
//! * Anything else with a matching name (a FIFO, a device, a socket, a dangling or looping
//!   link, a link to a directory) is **skipped with a note**: opening a FIFO would block.
//!
//! The notes are returned for the caller to show (the command line prints them on standard
//! error); an unreadable directory is an error.

use std::collections::HashSet;
use std::path::{Path, PathBuf};

use super::text::{not_regular, plain_io_error};
use super::{InputError, Problem};

/// The outcome of a walk: the files found (sorted) and one note per path skipped.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Walk {
    /// Regular files whose name matched, sorted by path, each file once.
    pub files: Vec<PathBuf>,
    /// `"PATH: skipped: REASON"` for every matching name that is not read, and every
    /// symbolic link to a directory that is not followed.
    pub notes: Vec<String>,
}

/// The claim files under `dir`: names ending in `.claims.toml` or `.claims.json`.
pub fn claim_files(dir: &Path) -> Result<Walk, InputError> {
    walk(dir, &|name| {
        name.ends_with(".claims.toml") || name.ends_with(".claims.json")
    })
}

/// A file's identity: (device, inode) on Unix, the canonical path elsewhere.
#[cfg(unix)]
fn identity(_path: &Path, meta: &std::fs::Metadata) -> Option<(u64, u64, PathBuf)> {
    use std::os::unix::fs::MetadataExt;
    Some((meta.dev(), meta.ino(), PathBuf::new()))
}

#[cfg(not(unix))]
fn identity(path: &Path, _meta: &std::fs::Metadata) -> Option<(u64, u64, PathBuf)> {
    std::fs::canonicalize(path).ok().map(|p| (0, 0, p))
}

/// A file's identity: (device, inode, canonical path).
type Identity = (u64, u64, PathBuf);

/// The regular files under `dir` whose file name satisfies `matches` (see the module
/// documentation). `dir` itself may be a symbolic link: it was named explicitly.
pub fn walk(dir: &Path, matches: &dyn Fn(&str) -> bool) -> Result<Walk, InputError> {
    // (is a link, path, identity)
    let mut found: Vec<(bool, PathBuf, Option<Identity>)> = Vec::new();
    let mut notes = Vec::new();
    let mut entered = HashSet::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        let dir_error = |e: std::io::Error| {
            InputError::file(
                d.display().to_string(),
                Problem::CannotReadDirectory {
                    reason: plain_io_error(&e),
                },
            )
        };
        let meta = std::fs::metadata(&d).map_err(dir_error)?;
        if let Some(id) = identity(&d, &meta)
            && !entered.insert(id)
        {
            continue;
        }
        let mut entries = std::fs::read_dir(&d)
            .map_err(dir_error)?
            .collect::<Result<Vec<_>, _>>()
            .map_err(dir_error)?;
        entries.sort_by_key(std::fs::DirEntry::path);
        for entry in entries {
            let path = entry.path();
            let name_matches = path
                .file_name()
                .and_then(|n| n.to_str())
                .is_some_and(matches);
            let Ok(kind) = entry.file_type() else {
                if name_matches {
                    notes.push(format!("{}: skipped: cannot tell its type", path.display()));
                }
                continue;
            };
            if kind.is_dir() {
                stack.push(path);
                continue;
            }
            if kind.is_symlink() {
                match std::fs::metadata(&path) {
                    Ok(target) if target.is_dir() => notes.push(format!(
                        "{}: skipped: a symbolic link to a directory is not followed",
                        path.display()
                    )),
                    Ok(target) if name_matches && target.is_file() => {
                        found.push((true, path.clone(), identity(&path, &target)));
                    }
                    Ok(target) if name_matches => notes.push(format!(
                        "{}: skipped: a symbolic link to {}",
                        path.display(),
                        not_regular(&target)
                    )),
                    Err(e) if name_matches => notes.push(format!(
                        "{}: skipped: a symbolic link that cannot be followed: {}",
                        path.display(),
                        plain_io_error(&e)
                    )),
                    _ => {}
                }
                continue;
            }
            if !name_matches {
                continue;
            }
            match entry.metadata() {
                Ok(meta) if meta.is_file() => {
                    found.push((false, path.clone(), identity(&path, &meta)));
                }
                Ok(meta) => notes.push(format!(
                    "{}: skipped: {}",
                    path.display(),
                    not_regular(&meta)
                )),
                Err(e) => notes.push(format!(
                    "{}: skipped: {}",
                    path.display(),
                    plain_io_error(&e)
                )),
            }
        }
    }
    found.sort();
    let mut kept: std::collections::HashMap<_, PathBuf> = std::collections::HashMap::new();
    let mut files = Vec::new();
    for (_, path, id) in found {
        if let Some(id) = id {
            if let Some(first) = kept.get(&id) {
                notes.push(format!(
                    "{}: skipped: the same file as {} (counted once)",
                    path.display(),
                    first.display()
                ));
                continue;
            }
            kept.insert(id, path.clone());
        }
        files.push(path);
    }
    files.sort();
    notes.sort();
    Ok(Walk { files, notes })
}

#[cfg(all(test, unix))]
mod tests {
    use super::*;
    use std::os::unix::fs::symlink;

    #[test]
    fn links_are_not_followed_into_directories_and_files_count_once() {
        let tmp = tempfile::tempdir().unwrap();
        let d = tmp.path();
        std::fs::create_dir(d.join("sub")).unwrap();
        std::fs::write(d.join("a.claims.toml"), "").unwrap();
        std::fs::write(d.join("sub/b.claims.json"), "").unwrap();
        std::fs::write(d.join("sub/other.toml"), "").unwrap();
        symlink(".", d.join("sub/dot")).unwrap();
        symlink("..", d.join("sub/up")).unwrap();
        symlink("/", d.join("root")).unwrap();
        symlink("a.claims.toml", d.join("z.claims.toml")).unwrap();
        symlink("self.claims.toml", d.join("self.claims.toml")).unwrap();
        symlink("nowhere", d.join("gone.claims.toml")).unwrap();
        let w = claim_files(d).unwrap();
        assert_eq!(
            w.files,
            vec![d.join("a.claims.toml"), d.join("sub/b.claims.json")]
        );
        let notes = w.notes.join("\n");
        for skipped in [
            "gone.claims.toml: skipped",
            "root: skipped: a symbolic link to a directory",
            "self.claims.toml: skipped",
            "sub/dot: skipped",
            "sub/up: skipped",
            "z.claims.toml: skipped: the same file as",
        ] {
            assert!(notes.contains(skipped), "{skipped} in\n{notes}");
        }
        assert_eq!(w.notes.len(), 6, "{notes}");
    }

    #[test]
    fn a_fifo_is_skipped_with_a_note() {
        let tmp = tempfile::tempdir().unwrap();
        let fifo = tmp.path().join("x.claims.toml");
        let made = std::process::Command::new("mkfifo").arg(&fifo).status();
        assert!(made.is_ok_and(|s| s.success()), "mkfifo");
        let w = claim_files(tmp.path()).unwrap();
        assert!(w.files.is_empty());
        assert_eq!(
            w.notes,
            vec![format!(
                "{}: skipped: a FIFO (named pipe), not a regular file",
                fifo.display()
            )]
        );
    }

    #[test]
    fn an_unreadable_directory_is_an_error() {
        let e = claim_files(Path::new("/no/such/dir")).unwrap_err();
        assert!(
            e.to_string()
                .starts_with("/no/such/dir: cannot read directory"),
            "{e}"
        );
    }
}
