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
                    unit: "rows",
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

/// The most rows the fuzz target [`fuzz_fit_data`] fits (every file is parsed, up to
/// [`MAX_DATA_ROWS`]).
#[cfg(any(fuzzing, feature = "unstable-internals"))]
const FUZZ_FIT_ROWS: usize = 32;
/// The largest numerator or denominator (in bits) of a number the fuzz target fits with.
#[cfg(any(fuzzing, feature = "unstable-internals"))]
const FUZZ_FIT_BITS: u64 = 512;

/// The fuzz target `fit_data` (`tribez::hazmat::io::fuzz::fit_data`): the first byte chooses
/// the degree (1 to 3); the rest is parsed as a data file (every size capped: at most
/// [`MAX_DATA_ROWS`] rows, each row stored only after the count is checked). A small file of
/// moderate numbers is then fitted (minimum norm) on the unit square cut along its diagonal,
/// and the fit's residuals are checked against the fitted mesh's own lookups:
/// `Σ (f(x_i, y_i) − v_i)²` is the residual sum of squares reported, and the largest
/// absolute residual squared is at most that sum.
#[cfg(any(fuzzing, feature = "unstable-internals"))]
pub fn fuzz_fit_data(data: &[u8]) {
    use num_traits::{Signed, Zero};
    let Some((&first, rest)) = data.split_first() else {
        return;
    };
    let Ok(text) = std::str::from_utf8(rest) else {
        return;
    };
    let Ok(rows) = parse_data(text, "fuzz.csv") else {
        return;
    };
    assert!(!rows.is_empty() && rows.len() <= MAX_DATA_ROWS);
    assert!(rows.windows(2).all(|w| w[0].line < w[1].line));
    let small =
        |q: &BigRational| q.numer().bits() <= FUZZ_FIT_BITS && q.denom().bits() <= FUZZ_FIT_BITS;
    if rows.len() > FUZZ_FIT_ROWS
        || !rows
            .iter()
            .all(|r| small(&r.x) && small(&r.y) && small(&r.value))
    {
        return;
    }
    let q = |n: i64| BigRational::from_integer(n.into());
    let mesh = crate::mesh::Mesh::new(
        vec![[q(0), q(0)], [q(1), q(0)], [q(1), q(1)], [q(0), q(1)]],
        vec![[0, 1, 2], [0, 2, 3]],
        1 + usize::from(first % 3),
    )
    .expect("a valid mesh");
    let options = super::FitOptions {
        regularize: true,
        ..super::FitOptions::default()
    };
    let Ok(f) = super::fit(&mesh, &rows, "fuzz.csv", &options) else {
        return;
    };
    let mut rss = BigRational::zero();
    for r in &rows {
        let hits = f
            .mesh
            .lookup(&[r.x.clone(), r.y.clone()])
            .expect("every ordinate");
        let (_, value) = hits.first().expect("the point was located by the fit");
        let d = value - &r.value;
        rss += &d * &d;
    }
    assert_eq!(rss, f.rss, "residual sum of squares");
    let (m, _) = f.max_residual.expect("at least one row");
    assert!(!m.is_negative() && &m * &m <= f.rss);
}
