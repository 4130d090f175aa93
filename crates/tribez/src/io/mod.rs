//! Files in: the document tree shared by TOML and JSON, patch files, and the input error.
//!
//! This layer depends on the core and never the reverse.

pub mod claim_problem;
pub mod inverse_problem;
pub mod patch_file;
pub mod points;
#[cfg(test)]
mod problem_tests;
pub mod rows_problem;
pub mod text;
pub mod tree;
pub mod walk;

use std::fmt;

pub use claim_problem::{ClaimProblem, NeededKind};
pub use inverse_problem::InverseProblem;
pub use rows_problem::RowsProblem;

use crate::certify::measures::{ParseToleranceError, ToleranceNeeds};
use crate::error::CoreError;
use crate::exact::ParseAlgorithmError;
use crate::float::{ParsePrecisionError, Precision};
use crate::number::NumberError;

/// Bad input: which file, where in it, and what is wrong ([`Problem`]). The CLI prints it on
/// one line and exits with status 2.
#[derive(Debug, Clone, PartialEq)]
pub struct InputError {
    /// The file (or `<command line>`).
    pub file: String,
    /// Line number (1-based), when known.
    pub line: Option<usize>,
    /// Column number (1-based), when known.
    pub column: Option<usize>,
    /// The key or field, e.g. `control_points."1,1,0"`.
    pub key: Option<String>,
    /// What is wrong (boxed: errors stay small on the happy path's stack).
    pub problem: Box<Problem>,
    /// For an error in a file named by another one (a patch file named by a claim file): where
    /// it was named.
    pub named_at: Option<Box<NamedAt>>,
}

/// Where a file was named by another file ([`InputError::named_at`]).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct NamedAt {
    /// The naming file.
    pub file: String,
    /// Its line.
    pub line: usize,
    /// The key that names the file.
    pub key: String,
}

/// What is wrong with an input. `Display` is the message after the location.
///
/// Every variant carries data (the key, the limit, the figures found and expected); the
/// message is written once, in `Display`. A new check of a file format or a claim operation
/// adds a variant (here, or to [`ClaimProblem`], [`RowsProblem`] or
/// `patch_file::PatchFileProblem`), never a message at the call site.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum Problem {
    /// The file cannot be read (the operating system's reason, without its error number: the
    /// one message tribez does not write itself).
    #[error("cannot read: {reason}")]
    CannotRead {
        /// The operating system's reason.
        reason: String,
    },
    /// A directory cannot be listed.
    #[error("cannot read directory: {reason}")]
    CannotReadDirectory {
        /// The operating system's reason.
        reason: String,
    },
    /// An output cannot be written.
    #[error("cannot write: {reason}")]
    CannotWrite {
        /// The operating system's reason.
        reason: String,
    },
    /// The path is not a regular file (`kind`: `"a directory"`, `"a FIFO (named pipe)"`, …;
    /// `None`: something else).
    #[error("{}not a regular file", kind.map_or(String::new(), |k| format!("{k}, ")))]
    NotRegularFile {
        /// What it is instead.
        kind: Option<&'static str>,
    },
    /// A file above the size read whole.
    #[error("the file is larger than the limit of {limit_mib} MiB for a file read whole")]
    FileTooLarge {
        /// The limit, in MiB.
        limit_mib: u64,
    },
    /// A TOML document with more values than `tree::MAX_TOML_VALUES`, refused before it is
    /// parsed (by a count that takes every `,`, `=`, `[` and `.` for a value), so that the memory
    /// its tree takes is bounded. The line is where the limit is passed.
    #[error(
        "more than {limit} values (the limit of a TOML file, counting every ',', '=', '[' and '.' \
         as one; write a larger input as JSON)"
    )]
    TooManyTomlValues {
        /// The limit.
        limit: usize,
    },
    /// A JSON document with more values than `tree::MAX_JSON_VALUES`, refused as its tree
    /// grows. The line is where the limit is passed.
    #[error("more than {limit} values (the limit of a JSON file)")]
    TooManyJsonValues {
        /// The limit.
        limit: usize,
    },
    /// A byte that is not UTF-8 (the location is the error's line and column).
    #[error("the file is not UTF-8 text (invalid byte 0x{byte:02x})")]
    NotUtf8 {
        /// The first invalid byte.
        byte: u8,
    },
    /// An extension other than `.toml` or `.json`.
    #[error("unknown file type (expected a .toml or .json extension)")]
    UnknownFileType,
    /// A file with nothing in it.
    #[error("the file is empty")]
    EmptyFile,
    /// TOML syntax. The message is the `toml` parser's own: tribez does not re-word a
    /// third-party parser's diagnosis.
    #[error("invalid TOML: {message}")]
    Toml {
        /// The parser's message.
        message: String,
    },
    /// JSON syntax (tribez's own parser).
    #[error("invalid JSON: {0}")]
    Json(JsonSyntax),
    /// A value of the wrong type.
    #[error("expected {expected}, found {found}")]
    WrongType {
        /// What the key takes (`"a table"`, `"a number"`, …).
        expected: &'static str,
        /// What it has (`"a string"`, …).
        found: &'static str,
    },
    /// A required key is absent.
    #[error("missing key `{key}`")]
    MissingKey {
        /// The key.
        key: &'static str,
    },
    /// A key that the table does not take.
    #[error("unknown key (expected one of: {})", known.join(", "))]
    UnknownKey {
        /// The keys it takes.
        known: Vec<String>,
    },
    /// Text that is not a non-negative integer.
    #[error("`{text}` is not a non-negative integer")]
    NotAnInteger {
        /// The text.
        text: String,
    },
    /// Text that is not an exact number.
    #[error(transparent)]
    Number(#[from] NumberError),
    /// Not a tolerance.
    #[error(transparent)]
    Tolerance(#[from] ParseToleranceError),
    /// A tolerance that cannot judge this value.
    #[error(transparent)]
    ToleranceNeeds(#[from] ToleranceNeeds),
    /// Not a precision.
    #[error(transparent)]
    Precision(#[from] ParsePrecisionError),
    /// Not an algorithm.
    #[error(transparent)]
    Algorithm(#[from] ParseAlgorithmError),
    /// A mathematical precondition the input violates.
    #[error(transparent)]
    Core(#[from] CoreError),
    /// A number of the input that overflows the precision it denotes a float of.
    #[error("{what} overflows {precision}")]
    Overflows {
        /// What overflows (`"an input"`, `"a control point"`, …).
        what: &'static str,
        /// The precision.
        precision: Precision,
    },
    /// A CSV header with the wrong number of names.
    #[error("a header line of {names} names, expected {expected} (one per column)")]
    HeaderWidth {
        /// Names in the header.
        names: usize,
        /// Columns expected.
        expected: usize,
    },
    /// A CSV row with the wrong number of fields.
    #[error("{found} fields, expected {expected}")]
    FieldCount {
        /// Fields in the row.
        found: usize,
        /// Fields expected.
        expected: usize,
    },
    /// A points file without a point.
    #[error("no points")]
    NoPoints,
    /// Random points of an S-patch are made in f64 as convex combinations of the polygon's
    /// vertices (rounded to f64); for this polygon such a sum overflows.
    #[error(
        "its coordinates are too large for random points, which are made in f64 as combinations \
         of the vertices (a sum overflows f64); give the points instead"
    )]
    RandomPointsOverflow,
    /// More rows (or array entries) than a file of this kind may hold (checked before the row
    /// is stored).
    #[error("more than {limit} {unit} (the limit of {what})")]
    TooManyRows {
        /// The limit.
        limit: usize,
        /// What is counted: `"rows"` of a CSV file, `"points"` of a JSON array.
        unit: &'static str,
        /// What has the limit (`"a fit's data"`).
        what: &'static str,
    },
    /// A check of the patch file format.
    #[error(transparent)]
    Patch(#[from] patch_file::PatchFileProblem),
    /// A check of a file format that a layer above this one reads (a mesh file: `tribez::mesh`
    /// defines its problems), typed behind a trait object (`FormatProblem::downcast_ref`).
    #[error(transparent)]
    Format(FormatProblem),
    /// A claim file's or a claim operation's check.
    #[error(transparent)]
    Claim(#[from] ClaimProblem),
    /// A check of a file of result rows or points.
    #[error(transparent)]
    Rows(#[from] RowsProblem),
    /// An inverse claim's or batch's inputs (`InverseProblem`).
    #[error(transparent)]
    Inverse(#[from] InverseProblem),
    /// A path that names nothing.
    #[error("no such file or directory")]
    NoSuchFile,
    /// The `index`-th (1-based) item of a list (`"direction"`, `"vector"`, `"point"`) violates
    /// a precondition.
    #[error("{what} {index}: {error}")]
    Item {
        /// What the list holds.
        what: &'static str,
        /// Its 1-based index.
        index: usize,
        /// What is wrong with it.
        error: CoreError,
    },
}

/// The problem of a file format defined above the file layer ([`Problem::Format`]): this layer
/// carries it without naming its type, so that the layers keep pointing down; the layer that
/// defines it gets it back with [`FormatProblem::downcast_ref`].
///
/// Two are equal when they are of one type and say the same.
#[derive(Clone)]
pub struct FormatProblem {
    problem: std::sync::Arc<dyn std::error::Error + Send + Sync + 'static>,
    type_id: std::any::TypeId,
}

impl FormatProblem {
    /// Wrap a typed problem.
    pub fn new<E: std::error::Error + Send + Sync + 'static>(problem: E) -> Self {
        FormatProblem {
            problem: std::sync::Arc::new(problem),
            type_id: std::any::TypeId::of::<E>(),
        }
    }

    /// The typed problem, if it is an `E`.
    pub fn downcast_ref<E: std::error::Error + 'static>(&self) -> Option<&E> {
        self.problem.downcast_ref::<E>()
    }
}

impl fmt::Debug for FormatProblem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Debug::fmt(&self.problem, f)
    }
}

impl fmt::Display for FormatProblem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(&self.problem, f)
    }
}

impl std::error::Error for FormatProblem {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        self.problem.source()
    }
}

impl PartialEq for FormatProblem {
    fn eq(&self, other: &Self) -> bool {
        self.type_id == other.type_id && self.problem.to_string() == other.problem.to_string()
    }
}

/// What is wrong in JSON text ([`Problem::Json`]).
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum JsonSyntax {
    /// Arrays and objects nested deeper than the limit.
    #[error("nested too deeply")]
    TooDeep,
    /// The text ends inside a value.
    #[error("unexpected end of file")]
    UnexpectedEnd,
    /// A key twice in one object.
    #[error("duplicate key \"{key}\"")]
    DuplicateKey {
        /// The key.
        key: String,
    },
    /// Something other than the expected token (`"':' after a key"`, `"',' or '}'"`, `"a
    /// value"`, `"a string"`, …).
    #[error("expected {0}")]
    Expected(&'static str),
    /// A string without its closing quote.
    #[error("unterminated string")]
    UnterminatedString,
    /// A `\u` escape that is not four hex digits or a valid code point.
    #[error("bad \\u escape")]
    BadUnicodeEscape,
    /// Another bad escape.
    #[error("bad escape in string")]
    BadEscape,
    /// A string whose bytes are not UTF-8.
    #[error("string is not UTF-8")]
    StringNotUtf8,
    /// Text after the value.
    #[error("unexpected text after the JSON value")]
    TrailingText,
}

impl InputError {
    /// An error about a whole file.
    pub fn file(file: impl Into<String>, problem: impl Into<Problem>) -> Self {
        InputError {
            file: file.into(),
            line: None,
            column: None,
            key: None,
            problem: Box::new(problem.into()),
            named_at: None,
        }
    }

    /// An error at a line and column of a file.
    pub fn at(
        file: impl Into<String>,
        line: Option<usize>,
        column: Option<usize>,
        problem: impl Into<Problem>,
    ) -> Self {
        InputError {
            line,
            column,
            ..InputError::file(file, problem)
        }
    }

    /// Attach a key, keeping an existing one as a prefix.
    pub fn with_key(mut self, key: impl Into<String>) -> Self {
        self.key = Some(key.into());
        self
    }
}

impl fmt::Display for InputError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.file)?;
        if let Some(line) = self.line {
            write!(f, ":{line}")?;
            if let Some(col) = self.column {
                write!(f, ":{col}")?;
            }
        }
        if let Some(key) = &self.key {
            write!(f, ": {key}")?;
        }
        write!(f, ": {}", self.problem)?;
        if let Some(n) = &self.named_at {
            write!(f, " (named at {}:{}: {})", n.file, n.line, n.key)?;
        }
        Ok(())
    }
}

impl std::error::Error for InputError {}
