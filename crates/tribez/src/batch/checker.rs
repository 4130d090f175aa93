//! [`ResultsChecker`]: what every results checker shares (the patch batch [`super::BatchChecker`],
//! the mesh lookups [`super::MeshBatchChecker`], the inverse answers
//! [`super::InverseBatchChecker`]): rows read from any reader, or from a file opened by name.

use std::io::Read;
use std::path::Path;

use super::parse::open_results;
use super::{BatchError, Format};

/// A checker of another implementation's results, streamed from a reader in chunks (bounded
/// memory) and judged in parallel; one required method, [`ResultsChecker::check_reader`].
///
/// [`ResultsChecker::check_file`] opens a file by name, tells its [`Format`] by [`Format::of`]
/// (extension, then for `.json` its first two non-space characters) and refuses a directory by
/// name; every error names the file as `path.display()` does, and the report names it so too.
///
/// ```
/// use std::path::Path;
/// use tribez::ResultsChecker;
/// use tribez::batch::{BatchError, BatchReport};
///
/// /// The failed rows of a results file, whichever checker judges it (a patch's or a mesh's).
/// fn failed_rows<C>(checker: &C, path: &Path, name: &str) -> Result<u64, BatchError>
/// where
///     C: ResultsChecker<Report = BatchReport>,
/// {
///     Ok(checker.check_file(path, name, &mut |_, _| {})?.failed)
/// }
/// ```
pub trait ResultsChecker {
    /// What a check returns: [`super::BatchReport`] for values and lookups,
    /// [`super::InverseBatchReport`] for inverse answers.
    type Report;

    /// Check the rows read from `reader` in `format`; `file` names them in errors and in the
    /// report, `subject` names the patch (or the mesh) in the report. `progress(rows, failed)`
    /// is called after each chunk of rows.
    ///
    /// Errors: a malformed row (naming `file` and its line), no rows, a row the exact
    /// computation refuses.
    fn check_reader<R: Read + Send>(
        &self,
        reader: R,
        format: Format,
        file: &str,
        subject: &str,
        progress: &mut dyn FnMut(u64, u64),
    ) -> Result<Self::Report, BatchError>;

    /// [`ResultsChecker::check_reader`] on the file at `path` (its format told by
    /// [`Format::of`]; `path.display()` names it in errors and the report). A FIFO is read as
    /// a stream; a directory, an unknown extension or an unreadable file is an error naming it.
    fn check_file(
        &self,
        path: &Path,
        subject: &str,
        progress: &mut dyn FnMut(u64, u64),
    ) -> Result<Self::Report, BatchError> {
        let (file, format, reader) = open_results(path)?;
        self.check_reader(reader, format, &file, subject, progress)
    }
}
