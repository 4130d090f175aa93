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
    /// A check of the command line's own (a result above the patch-file limits, a matrix
    /// too large, an edge that is not two numbers), with what it concerns.
    #[error("{context}: {message}")]
    Check {
        /// The file or argument concerned.
        context: String,
        /// What is wrong.
        message: String,
    },
    /// Wrong use of the command line.
    #[error("{0}")]
    Usage(String),
}

impl From<tribez::Error> for CliError {
    /// Bad input stays located; every other error of the library is one line of its own.
    fn from(e: tribez::Error) -> Self {
        match e {
            tribez::Error::Input(e) => CliError::Input(e),
            e => CliError::Usage(e.to_string()),
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

    /// A core error about `context`.
    pub fn core(context: impl Into<String>, source: CoreError) -> Self {
        CliError::Core {
            context: context.into(),
            source,
        }
    }
}
