//! Files in: the document tree shared by TOML and JSON, patch files, and the input error.
//!
//! This layer depends on the core and never the reverse.

pub mod fuzz;
pub mod patch_file;
pub mod points;
pub mod text;
pub mod tree;
pub mod walk;

use std::fmt;

/// Bad input: which file, where in it, and what is wrong. The CLI prints it on one line and
/// exits with status 2.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct InputError {
    /// The file (or `<command line>`).
    pub file: String,
    /// Line number (1-based), when known.
    pub line: Option<usize>,
    /// Column number (1-based), when known.
    pub column: Option<usize>,
    /// The key or field, e.g. `control_points."1,1,0"`.
    pub key: Option<String>,
    /// What is wrong.
    pub message: String,
}

impl InputError {
    /// An error about a whole file.
    pub fn file(file: impl Into<String>, message: impl Into<String>) -> Self {
        InputError {
            file: file.into(),
            line: None,
            column: None,
            key: None,
            message: message.into(),
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
        write!(f, ": {}", self.message)
    }
}

impl std::error::Error for InputError {}
