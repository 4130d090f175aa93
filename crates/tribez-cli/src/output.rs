//! Every file and byte the command line writes goes through here.
//!
//! * Output files (`-o FILE`, `--junit FILE`, `--record-baseline FILE`, ...) are **staged** with
//!   [`stage`]: the target is checked at once (it must be a regular file or not exist; a
//!   symbolic link, a directory, a device node, a FIFO or a socket is refused), and the bytes are
//!   written to a temporary file created exclusively (`O_EXCL`, an unpredictable name) in the
//!   target's directory, with the permissions of the file it replaces (a new file gets the
//!   usual `0666` less the umask).
//! * [`crate::commands::main`] commits every staged file (one rename each) only after the command
//!   succeeded with exit status 0 or 1 and its report reached standard output; a run that exits 2
//!   drops them all, so it leaves no output file behind, whole or partial.
//! * Standard output is written with [`write_stdout`]: a failed write (a full disk, `> /dev/full`)
//!   is an error (exit status 2, one line); a closed pipe (`| head -1`) is not worth a message.
//! * A report written while it is produced goes through [`stream`], to standard output or a
//!   staged file, with the same rules.
//!
//! A file staged twice in one run (`-o r.xml --junit r.xml`) is refused: one of the two would be
//! lost.

use std::io::{ErrorKind, Write};
use std::path::{Path, PathBuf};
use std::sync::{Mutex, MutexGuard};

use tempfile::NamedTempFile;
use tribez::{InputError, Problem};

use crate::error::CliError;

/// The files staged in this run, committed together by [`commit_all`].
static STAGED: Mutex<Staging> = Mutex::new(Staging { files: Vec::new() });

/// Stage `bytes` as the new content of `path`; the file appears (whole) only when the run ends
/// with exit status 0 or 1. Errors (a target that is not a regular file, a directory that
/// cannot be written, a full disk) are reported now, before anything is committed.
pub fn stage(path: &Path, bytes: &[u8]) -> Result<(), CliError> {
    staging().stage(path, &[bytes])
}

/// [`stage`] the parts `parts` written one after another.
pub fn stage_parts<T: AsRef<[u8]>>(path: &Path, parts: &[T]) -> Result<(), CliError> {
    staging().stage(path, parts)
}

/// Commit every staged file (called once, at the end of a successful run).
pub(crate) fn commit_all() -> Result<(), CliError> {
    let staged = std::mem::take(&mut staging().files);
    Staging { files: staged }.commit()
}

/// Drop every staged file (their temporary files are removed): the run failed.
pub(crate) fn discard_all() {
    staging().files.clear();
}

fn staging() -> MutexGuard<'static, Staging> {
    STAGED
        .lock()
        .unwrap_or_else(|poisoned| poisoned.into_inner())
}

/// Write `bytes` to standard output. A closed pipe is quiet (`Ok`); any other failure is an
/// error naming standard output.
pub fn write_stdout(bytes: &[u8]) -> Result<(), CliError> {
    write_stdout_parts(&[bytes])
}

/// [`write_stdout`] the parts `parts`, one after another.
pub fn write_stdout_parts<T: AsRef<[u8]>>(parts: &[T]) -> Result<(), CliError> {
    let mut out = std::io::stdout().lock();
    let written = parts
        .iter()
        .try_for_each(|part| out.write_all(part.as_ref()))
        .and_then(|()| out.flush());
    stdout_written(written)
}

/// How a write to standard output ended, as the command line reports it.
fn stdout_written(written: std::io::Result<()>) -> Result<(), CliError> {
    match written {
        Ok(()) => Ok(()),
        Err(e) if e.kind() == ErrorKind::BrokenPipe => Ok(()),
        Err(e) => Err(InputError::file("<standard output>", cannot_write(&e)).into()),
    }
}

/// Where a report written while it is produced goes ([`stream`]): standard output or a staged
/// file. It can be shared by threads (behind a lock). A failed write is kept and reported when
/// the report ends; the writes after it are skipped.
pub struct Sink<'a> {
    out: &'a mut (dyn Write + Send),
    failure: Option<std::io::Error>,
}

impl<'a> Sink<'a> {
    /// A sink writing to `out`.
    pub fn new(out: &'a mut (dyn Write + Send)) -> Self {
        Sink { out, failure: None }
    }

    /// Write `bytes` (nothing once a write has failed).
    pub fn write(&mut self, bytes: &[u8]) {
        if self.failure.is_none()
            && let Err(e) = self.out.write_all(bytes)
        {
            self.failure = Some(e);
        }
    }

    /// Flush, and the first failure of all the writes.
    fn finish(mut self) -> std::io::Result<()> {
        match self.failure.take() {
            Some(e) => Err(e),
            None => self.out.flush(),
        }
    }
}

/// Write the report that `produce` writes into a [`Sink`] to standard output (`target` `None`),
/// or stage it as `target` (see [`stage`]). An error of `produce` is the run's error: a staged
/// file is then dropped; what `produce` wrote to standard output before it stays written, so
/// `produce` writes only when nothing can fail any more.
pub fn stream(
    target: Option<&Path>,
    produce: impl FnOnce(&mut Sink<'_>) -> Result<(), CliError>,
) -> Result<(), CliError> {
    match target {
        None => {
            let mut out = std::io::stdout();
            let mut sink = Sink::new(&mut out);
            produce(&mut sink)?;
            stdout_written(sink.finish())
        }
        Some(path) => {
            let staged = staging().create(path)?;
            let mut out = staged.tmp.as_file();
            let mut sink = Sink::new(&mut out);
            produce(&mut sink)?;
            let written = sink.finish();
            staging().files.push(staged.synced(written)?);
            Ok(())
        }
    }
}

/// The operating system's reason an output cannot be written.
fn cannot_write(e: &std::io::Error) -> Problem {
    Problem::CannotWrite {
        reason: e.to_string(),
    }
}

/// A set of staged output files.
#[derive(Default)]
pub(crate) struct Staging {
    files: Vec<Staged>,
}

/// One staged file: its target and the temporary file beside it holding the new content.
struct Staged {
    /// The target as given (for messages) and as an absolute path (to detect duplicates).
    target: PathBuf,
    key: PathBuf,
    tmp: NamedTempFile,
}

impl Staged {
    /// The staged file once its content is on disk: `written` is how writing it ended; a failed
    /// write or sync is an error naming the target (the temporary file is then dropped).
    fn synced(self, written: std::io::Result<()>) -> Result<Self, CliError> {
        written
            .and_then(|()| self.tmp.as_file().sync_all())
            .map_err(|e| {
                CliError::check(
                    self.target.display().to_string(),
                    format!("cannot write: {e}"),
                )
            })?;
        Ok(self)
    }
}

impl Staging {
    /// See [`stage`].
    pub(crate) fn stage<T: AsRef<[u8]>>(
        &mut self,
        path: &Path,
        parts: &[T],
    ) -> Result<(), CliError> {
        let mut staged = self.create(path)?;
        let written = parts
            .iter()
            .try_for_each(|part| staged.tmp.write_all(part.as_ref()));
        self.files.push(staged.synced(written)?);
        Ok(())
    }

    /// The checked target `path` and an empty temporary file beside it (not yet in the set).
    fn create(&self, path: &Path) -> Result<Staged, CliError> {
        let file = path.display().to_string();
        let fail = |message: String| CliError::check(&file, message);
        let name = path
            .file_name()
            .ok_or_else(|| fail("not a file name".into()))?;
        let dir = match path.parent() {
            Some(d) if !d.as_os_str().is_empty() => d,
            _ => Path::new("."),
        };
        let existing = match std::fs::symlink_metadata(path) {
            Ok(md) => {
                let kind = md.file_type();
                if kind.is_symlink() {
                    return Err(fail(
                        "is a symbolic link; tribez writes only regular files (give the path it points to, or remove the link)".into(),
                    ));
                }
                if kind.is_dir() {
                    return Err(fail(
                        "is a directory; tribez writes only regular files".into(),
                    ));
                }
                if !kind.is_file() {
                    return Err(fail(
                        "is not a regular file (a device, FIFO or socket); tribez writes only regular files".into(),
                    ));
                }
                Some(md.permissions())
            }
            Err(e) if e.kind() == ErrorKind::NotFound => None,
            Err(e) => return Err(fail(format!("cannot write: {e}"))),
        };
        let key = std::fs::canonicalize(dir)
            .map_err(|e| fail(format!("cannot write into {}: {e}", dir.display())))?
            .join(name);
        if self.files.iter().any(|s| s.key == key) {
            return Err(fail(
                "given as two outputs of one run; give each output its own file".into(),
            ));
        }
        let prefix = format!(".{}.", name.to_string_lossy());
        let mut builder = tempfile::Builder::new();
        builder.prefix(&prefix).suffix(".tribez-tmp");
        #[cfg(unix)]
        {
            use std::os::unix::fs::PermissionsExt;
            // a new file: 0666 less the umask, as any program creating a file gets
            builder.permissions(std::fs::Permissions::from_mode(0o666));
        }
        let tmp = builder
            .tempfile_in(dir)
            .map_err(|e| fail(format!("cannot write: {e}")))?;
        if let Some(permissions) = existing {
            // keep the permissions of the file being replaced (exactly, not less the umask)
            tmp.as_file()
                .set_permissions(permissions)
                .map_err(|e| fail(format!("cannot write: {e}")))?;
        }
        Ok(Staged {
            target: path.to_path_buf(),
            key,
            tmp,
        })
    }

    /// Rename every staged file onto its target, in the order staged.
    pub(crate) fn commit(self) -> Result<(), CliError> {
        for s in self.files {
            s.tmp.persist(&s.target).map_err(|e| {
                InputError::file(s.target.display().to_string(), cannot_write(&e.error))
            })?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn listing(dir: &Path) -> Vec<String> {
        let mut names: Vec<String> = std::fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        names.sort();
        names
    }

    #[test]
    fn nothing_appears_before_commit_and_nothing_stays_when_dropped() {
        let dir = tempfile::tempdir().unwrap();
        let target = dir.path().join("out.txt");
        let mut s = Staging::default();
        s.stage(&target, &[b"hello\n"]).unwrap();
        assert!(!target.exists());
        drop(s);
        assert_eq!(listing(dir.path()), Vec::<String>::new());
    }

    #[test]
    fn commit_writes_every_file_and_leaves_no_temporary() {
        let dir = tempfile::tempdir().unwrap();
        let (a, b) = (dir.path().join("a"), dir.path().join("b"));
        let mut s = Staging::default();
        s.stage(&a, &[b"1"]).unwrap();
        s.stage(&b, &[b"2"]).unwrap();
        s.commit().unwrap();
        assert_eq!(std::fs::read(&a).unwrap(), b"1");
        assert_eq!(std::fs::read(&b).unwrap(), b"2");
        assert_eq!(listing(dir.path()), ["a", "b"]);
    }

    #[test]
    fn a_stream_that_fails_leaves_no_file() {
        let dir = tempfile::tempdir().unwrap();
        let target = dir.path().join("report.json");
        let e = stream(Some(&target), |sink| {
            sink.write(b"the first half");
            Err(CliError::Usage("the second half failed".into()))
        })
        .unwrap_err();
        assert!(e.to_string().contains("second half"), "{e}");
        assert_eq!(listing(dir.path()), Vec::<String>::new());
    }

    #[test]
    fn the_same_target_twice_is_refused() {
        let dir = tempfile::tempdir().unwrap();
        let mut s = Staging::default();
        s.stage(&dir.path().join("r.xml"), &[b"1"]).unwrap();
        let twice = dir.path().join(".").join("r.xml");
        let e = s.stage(&twice, &[b"2"]).unwrap_err().to_string();
        assert!(e.contains("two outputs"), "{e}");
    }

    #[cfg(unix)]
    #[test]
    fn permissions_of_a_replaced_file_are_kept() {
        use std::os::unix::fs::PermissionsExt;
        let dir = tempfile::tempdir().unwrap();
        let target = dir.path().join("secret");
        std::fs::write(&target, "old").unwrap();
        std::fs::set_permissions(&target, std::fs::Permissions::from_mode(0o600)).unwrap();
        let mut s = Staging::default();
        s.stage(&target, &[b"new"]).unwrap();
        s.commit().unwrap();
        let md = std::fs::metadata(&target).unwrap();
        assert_eq!(md.permissions().mode() & 0o7777, 0o600);
        assert_eq!(std::fs::read(&target).unwrap(), b"new");
    }

    #[cfg(unix)]
    #[test]
    fn links_directories_and_devices_are_refused() {
        let dir = tempfile::tempdir().unwrap();
        let aim = dir.path().join("aim");
        std::fs::write(&aim, "keep").unwrap();
        let link = dir.path().join("link");
        std::os::unix::fs::symlink(&aim, &link).unwrap();
        let mut s = Staging::default();
        for (path, word) in [
            (link.as_path(), "symbolic link"),
            (dir.path(), "directory"),
            (Path::new("/dev/null"), "not a regular file"),
        ] {
            let e = s.stage(path, &[b"x"]).unwrap_err().to_string();
            assert!(e.contains(word), "{}: {e}", path.display());
        }
        assert_eq!(std::fs::read(&aim).unwrap(), b"keep");
        assert!(
            std::fs::symlink_metadata(&link)
                .unwrap()
                .file_type()
                .is_symlink()
        );
    }
}
