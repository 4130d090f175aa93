//! Why a command could not run (exit status 2): located bad input, a violated mathematical
//! precondition, or wrong use of the command line. The one error type of the CLI; every layer
//! of the binary (commands, pictures, output files) returns it.

use tribez::CoreError;
use tribez::InputError;

/// Why a command could not run: bad input or usage (exit status 2).
#[derive(Debug, thiserror::Error)]
pub enum CliError {
    /// A file or argument with a located problem.
    #[error(transparent)]
    Input(#[from] InputError),
    /// A mathematical precondition that the input violates, with what it concerns.
    #[error("{context}: {source}")]
    Core {
        /// The file or argument concerned.
        context: String,
        /// What is wrong.
        #[source]
        source: CoreError,
    },
    /// An error of the library that names what it concerns itself (a located mesh problem, a
    /// fit's data point outside the mesh): its data kept, its message the line printed.
    #[error(transparent)]
    Library(tribez::Error),
    /// An error of the library about `context` (a file, two files, a flag), its data kept
    /// (any of the library's error types: [`tribez::Error`], a flag value's parse error, a
    /// hunt's error).
    #[error("{context}: {source}")]
    About {
        /// The file or argument concerned.
        context: String,
        /// What is wrong.
        #[source]
        source: Box<dyn std::error::Error + Send + Sync>,
    },
    /// A batch that cannot be judged (rows of the wrong shape, a tolerance that needs a
    /// precision), its data kept.
    #[error(transparent)]
    Batch(tribez::batch::BatchError),
    /// A check of the command line's own (a result above the patch-file limits, a matrix
    /// too large, an edge that is not two numbers), with what it concerns.
    #[error("{context}: {message}")]
    Check {
        /// The file or argument concerned.
        context: String,
        /// What is wrong.
        message: String,
    },
    /// Wrong use of the command line (a flag missing, two flags that exclude each other, a
    /// value of the wrong shape).
    #[error("{0}")]
    Usage(String),
}

impl From<tribez::Error> for CliError {
    /// Bad input stays located ([`CliError::Input`]); every other error of the library is
    /// kept whole ([`CliError::Library`]), its message one line of its own.
    fn from(e: tribez::Error) -> Self {
        match e {
            tribez::Error::Input(e) => CliError::Input(e),
            e => CliError::Library(e),
        }
    }
}

impl CliError {
    /// A check of the command line's own about `context`.
    pub fn check(context: impl Into<String>, message: impl Into<String>) -> Self {
        CliError::Check {
            context: context.into(),
            message: message.into(),
        }
    }

    /// An error of the library about `context` (a file or a flag).
    pub fn about(
        context: impl Into<String>,
        source: impl Into<Box<dyn std::error::Error + Send + Sync>>,
    ) -> Self {
        CliError::About {
            context: context.into(),
            source: source.into(),
        }
    }

    /// A core error about `context`.
    pub fn core(context: impl Into<String>, source: CoreError) -> Self {
        CliError::Core {
            context: context.into(),
            source,
        }
    }
}
