//! What is wrong in a file of result rows (a batch: CSV, JSON lines or a JSON array of rows) or
//! a list of points ([`super::Problem::Rows`]): one variant per check, with the figures of the
//! message as data. `Display` is the message after the location (file, line, column).

use crate::number::NumberError;

/// What is wrong in a file of rows or points.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum RowsProblem {
    /// A file without a single result row.
    #[error("no result rows")]
    NoResultRows,
    /// A read that failed partway (`reason`: the operating system's, without its error number).
    #[error("cannot read line {line}: {reason}")]
    CannotReadLine {
        /// The line being read.
        line: usize,
        /// The operating system's reason.
        reason: String,
    },
    /// A line above the limit of a row's length.
    #[error("the line is longer than the limit of {limit_mib} MiB")]
    LineTooLong {
        /// The limit, in MiB.
        limit_mib: usize,
    },
    /// A row of a JSON array above the limit of a row's length.
    #[error("the row is longer than the limit of {limit_mib} MiB")]
    RowTooLong {
        /// The limit, in MiB.
        limit_mib: usize,
    },
    /// A row with the wrong number of columns.
    #[error(
        "{found} columns, expected {} ({width} input coordinates, then the {dim} claimed coordinates of the point)",
        width + dim
    )]
    ColumnCount {
        /// Columns in the row.
        found: usize,
        /// Input coordinates per row.
        width: usize,
        /// Claimed coordinates per row.
        dim: usize,
    },
    /// A field that is not a number.
    #[error("malformed number: {0}")]
    MalformedNumber(NumberError),
    /// A row entry that is an array, an object or a boolean.
    #[error("a row's entries must be numbers, strings or null")]
    RowEntries,
    /// A row whose bytes are not UTF-8.
    #[error("the row is not UTF-8 text")]
    RowNotUtf8,
    /// A JSON row or file that is not a JSON array.
    #[error("expected a JSON array `[…]`")]
    ExpectedArray,
    /// A row that is not JSON (`message`: the JSON parser's own, without its position).
    #[error("invalid JSON: {message}")]
    RowJson {
        /// The parser's message.
        message: String,
    },
    /// The end of the file inside the array of rows.
    #[error(
        "invalid JSON: unexpected end of file: the array opened at line {line}, column {column} is never closed"
    )]
    ArrayNotClosed {
        /// Where the array opens.
        line: usize,
        /// Its column.
        column: usize,
    },
    /// The end of the file inside a row.
    #[error(
        "invalid JSON: unexpected end of file: the row opened at line {line}, column {column} is never closed"
    )]
    RowNotClosed {
        /// Where the row opens.
        line: usize,
        /// Its column.
        column: usize,
    },
    /// Something other than a row where one is expected.
    #[error("invalid JSON: expected a row (an array `[…]`), found `{}`", found.escape_default())]
    ExpectedRow {
        /// The character found.
        found: char,
    },
    /// Something other than `,` or `]` after a row.
    #[error("invalid JSON: expected ',' or ']' after a row, found `{}`", found.escape_default())]
    ExpectedCommaOrEnd {
        /// The character found.
        found: char,
    },
    /// Text after the closing bracket of the array of rows.
    #[error("invalid JSON: unexpected text after the array of rows")]
    TextAfterRows,
    /// A point with the wrong number of coordinates (`index` is 1-based).
    #[error("point {index}: has {found} coordinates, expected {expected}")]
    PointLength {
        /// The point (1-based).
        index: usize,
        /// Its coordinates.
        found: usize,
        /// Coordinates expected.
        expected: usize,
    },
}
