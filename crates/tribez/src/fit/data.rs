//! Data files of a fit: CSV rows `x, y, value` in the exact number syntax of patch files.
//!
//! Blank lines and lines starting with `#` are skipped; the first other line may be a header of
//! three names (`x,y,value`); a UTF-8 byte-order mark is ignored. At most [`MAX_DATA_ROWS`] rows
//! (counted before each row is stored), and the file at most
//! [`MAX_FILE_BYTES`](crate::io::text::MAX_FILE_BYTES). Every error names the file and line
//! (and field).

use std::path::Path;

use num_rational::BigRational;

use crate::io::points::{csv_header, parse_csv_row};
use crate::io::text::{read_text, strip_bom};
use crate::io::{InputError, Problem};

/// The most data rows a fit reads.
pub const MAX_DATA_ROWS: usize = 1_000_000;

/// One row of data: the exact point and value, and the line it came from (1-based).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct DataPoint {
    /// The line of the file (1-based).
    pub line: usize,
    /// `x`.
    pub x: BigRational,
    /// `y`.
    pub y: BigRational,
    /// The value at `(x, y)`.
    pub value: BigRational,
}

/// Read a data file (see the module documentation).
pub fn read_data(path: &Path) -> Result<Vec<DataPoint>, InputError> {
    let text = read_text(path)?;
    parse_data(&text, &path.display().to_string())
}

/// Parse data text; `file` names it in errors.
///
/// ```
/// use tribez::fit::parse_data;
/// let rows = parse_data("x,y,value\n# a comment\n1/2, 0.25, -3\n", "data.csv").unwrap();
/// assert_eq!((rows[0].line, rows[0].value.to_string()), (3, "-3".to_string()));
/// let e = parse_data("1,2\n", "data.csv").unwrap_err();
/// assert_eq!(e.to_string(), "data.csv:1: 2 fields, expected 3");
/// ```
pub fn parse_data(text: &str, file: &str) -> Result<Vec<DataPoint>, InputError> {
    parse_limited(text, file, MAX_DATA_ROWS)
}

/// [`parse_data`] with at most `limit` rows.
pub(crate) fn parse_limited(
    text: &str,
    file: &str,
    limit: usize,
) -> Result<Vec<DataPoint>, InputError> {
    let text = strip_bom(text);
    let mut out = Vec::new();
    let mut first = true;
    for (i, line) in text.lines().enumerate() {
        let t = line.trim();
        if t.is_empty() || t.starts_with('#') {
            continue;
        }
        if std::mem::take(&mut first)
            && let Some(names) = csv_header(t)
        {
            if names != 3 {
                return Err(InputError::at(
                    file,
                    Some(i + 1),
                    None,
                    Problem::HeaderWidth { names, expected: 3 },
                ));
            }
            continue;
        }
        if out.len() == limit {
            return Err(InputError::at(
                file,
                Some(i + 1),
                None,
                Problem::TooManyRows {
                    limit,
                    what: "a fit's data",
                },
            ));
        }
        let mut row = parse_csv_row(t, 3, file, i + 1)?;
        let value = row.pop().unwrap_or_default();
        let y = row.pop().unwrap_or_default();
        let x = row.pop().unwrap_or_default();
        out.push(DataPoint {
            line: i + 1,
            x,
            y,
            value,
        });
    }
    if out.is_empty() {
        return Err(InputError::file(file, Problem::NoPoints));
    }
    Ok(out)
}
