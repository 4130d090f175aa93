//! Lists of points: CSV (one point per line, numbers separated by commas; `#` starts a comment
//! line) or JSON (an array of arrays), numbers read exactly from their text.
//!
//! A CSV file may start with one header line of column names (`u,v,w`, as other tools write
//! it): the first line that is neither blank nor a comment is a header when every field is a
//! name (see [`csv_header`]); it must then have one name per column. A UTF-8 byte-order mark is
//! ignored. Both kinds are read whole (at most [`super::text::MAX_FILE_BYTES`]) and hold at most
//! [`MAX_POINTS`] points, counted before any point's numbers are read.

use std::path::Path;

use num_rational::BigRational;
use rayon::prelude::*;

use super::text::read_text;
use super::tree::Document;
use super::{InputError, Problem};
use crate::number::parse_rational;

/// The most points a points file may hold (each point's exact numbers take about a hundred
/// bytes and more; a file of short rows at the size limit would otherwise take gigabytes).
pub const MAX_POINTS: usize = 1_000_000;

/// The error for a points file with more than [`MAX_POINTS`] points, counted as `unit` (CSV
/// rows, or the points of a JSON array).
fn too_many(unit: &'static str) -> Problem {
    Problem::TooManyRows {
        limit: MAX_POINTS,
        unit,
        what: "a points file",
    }
}

/// Read the points of a `.csv` or `.json` file; every point must have `width` coordinates.
pub fn read_points(path: &Path, width: usize) -> Result<Vec<Vec<BigRational>>, InputError> {
    let file = path.display().to_string();
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .unwrap_or("")
        .to_ascii_lowercase();
    if ext == "json" {
        let doc = Document::read(path)?;
        return points_from_document(&doc, width);
    }
    let text = read_text(path)?;
    parse_csv_points(&text, width, &file)
}

/// The points of a JSON document: an array of arrays of `width` numbers each.
pub fn points_from_document(
    doc: &Document,
    width: usize,
) -> Result<Vec<Vec<BigRational>>, InputError> {
    let rows = doc.array(&doc.root, "")?;
    if let Some(row) = rows.get(MAX_POINTS) {
        return Err(doc.error(row, &format!("[{MAX_POINTS}]"), too_many("points")));
    }
    let mut out = Vec::with_capacity(rows.len());
    for (i, row) in rows.iter().enumerate() {
        let key = format!("[{i}]");
        let p = doc.rationals(row, &key)?;
        if p.len() != width {
            return Err(doc.error(
                row,
                &key,
                crate::error::CoreError::WrongLength {
                    what: "point".into(),
                    expected: width,
                    found: p.len(),
                },
            ));
        }
        out.push(p);
    }
    if out.is_empty() {
        return Err(InputError::file(&doc.file, Problem::NoPoints));
    }
    Ok(out)
}

/// The points of CSV text (see the module documentation); every point has `width` coordinates.
///
/// From [`PARALLEL_ROWS`] rows on, the rows are parsed on all cores, block by block; the error
/// reported is still that of the first bad line in the file (a block stops at its first bad
/// line, so there is at most one error per block).
pub fn parse_csv_points(
    text: &str,
    width: usize,
    file: &str,
) -> Result<Vec<Vec<BigRational>>, InputError> {
    let text = super::text::strip_bom(text);
    // (line number, trimmed text) of every data row
    let mut rows: Vec<(usize, &str)> = Vec::new();
    let mut first = true;
    for (i, line) in text.lines().enumerate() {
        let t = line.trim();
        if t.is_empty() || t.starts_with('#') {
            continue;
        }
        if std::mem::take(&mut first)
            && let Some(names) = csv_header(t)
        {
            if names != width {
                return Err(InputError::at(
                    file,
                    Some(i + 1),
                    None,
                    Problem::HeaderWidth {
                        names,
                        expected: width,
                    },
                ));
            }
            continue;
        }
        if rows.len() == MAX_POINTS {
            return Err(InputError::at(file, Some(i + 1), None, too_many("rows")));
        }
        rows.push((i + 1, t));
    }
    if rows.is_empty() {
        return Err(InputError::file(file, Problem::NoPoints));
    }
    let block = |rows: &[(usize, &str)]| {
        rows.iter()
            .map(|&(line, t)| parse_csv_row(t, width, file, line))
            .collect::<Result<Vec<_>, _>>()
    };
    if rows.len() < PARALLEL_ROWS {
        return block(&rows);
    }
    let size = (rows.len() / (8 * rayon::current_num_threads())).max(PARALLEL_ROWS / 4);
    let blocks: Vec<_> = rows.par_chunks(size).map(block).collect();
    let mut out = Vec::with_capacity(rows.len());
    for b in blocks {
        out.extend(b?);
    }
    Ok(out)
}

/// The number of CSV rows from which [`parse_csv_points`] parses on all cores (below it, the
/// threads' start would cost more than they save).
pub const PARALLEL_ROWS: usize = 256;

/// One CSV row of exactly `width` numbers; errors name the line and column (field).
pub fn parse_csv_row(
    line: &str,
    width: usize,
    file: &str,
    line_no: usize,
) -> Result<Vec<BigRational>, InputError> {
    let fields: Vec<&str> = line.split(',').collect();
    if fields.len() != width {
        return Err(InputError::at(
            file,
            Some(line_no),
            None,
            Problem::FieldCount {
                found: fields.len(),
                expected: width,
            },
        ));
    }
    let mut column = 1; // character column where the field starts
    let mut out = Vec::with_capacity(fields.len());
    for (c, f) in fields.iter().enumerate() {
        out.push(parse_rational(f).map_err(|e| {
            InputError::at(file, Some(line_no), Some(column), e)
                .with_key(format!("field {}", c + 1))
        })?);
        column += f.chars().count() + 1;
    }
    Ok(out)
}

/// If `line` is a CSV header line, its number of names. A header is a line whose every field
/// (trimmed, without surrounding double quotes) is a name: a letter or `_`, then letters,
/// digits, `_`, `.`, `-`, `[`, `]`, `(` or `)`; and not a line of `nan`/`inf` fields only
/// (those are failed values in a results file, never names).
pub fn csv_header(line: &str) -> Option<usize> {
    let fields: Vec<&str> = line
        .split(',')
        .map(|f| {
            let f = f.trim();
            f.strip_prefix('"')
                .and_then(|g| g.strip_suffix('"'))
                .unwrap_or(f)
                .trim()
        })
        .collect();
    let is_name = |f: &str| {
        let mut chars = f.chars();
        chars
            .next()
            .is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
            && chars.all(|c| c.is_ascii_alphanumeric() || "_.-[]()".contains(c))
    };
    let not_finite =
        |f: &str| matches!(f.to_ascii_lowercase().as_str(), "nan" | "inf" | "infinity");
    (fields.iter().all(|f| is_name(f)) && !fields.iter().all(|f| not_finite(f)))
        .then_some(fields.len())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_header_line_of_names_is_skipped() {
        let pts = parse_csv_points("\u{feff}u,v,w\n1/2,1/4,1/4\n", 3, "p.csv").unwrap();
        assert_eq!(pts.len(), 1);
        assert_eq!(pts[0][0].to_string(), "1/2");
        let pts = parse_csv_points("# comment\n\"u\", \"v\", \"w\"\n0,0,1\n", 3, "p.csv").unwrap();
        assert_eq!(pts.len(), 1);
        // a second line of names is a bad row
        let e = parse_csv_points("u,v,w\nu,v,w\n", 3, "p.csv").unwrap_err();
        assert_eq!(e.line, Some(2));
        // a header with the wrong number of names
        let e = parse_csv_points("u,v\n0,0,1\n", 3, "p.csv").unwrap_err();
        assert!(
            e.to_string()
                .starts_with("p.csv:1: a header line of 2 names, expected 3"),
            "{e}"
        );
        // names after data are bad rows
        let e = parse_csv_points("0,0,1\nu,v,w\n", 3, "p.csv").unwrap_err();
        assert_eq!(e.line, Some(2));
    }

    /// A file long enough to be parsed on all cores, with comments and blank lines between the
    /// rows: the same points, in order, as row by row; and of several bad lines, the first.
    #[test]
    fn long_files_parse_as_row_by_row_and_report_the_first_bad_line() {
        let rows = 4 * PARALLEL_ROWS + 13;
        let mut text = String::from("u,v,w\n");
        let mut lines = Vec::new(); // (line number, row)
        for r in 0..rows {
            if r % 7 == 0 {
                text.push_str("# a comment\n\n");
            }
            let (p, q) = (r % 97 + 1, r % 89 + 3);
            let row = format!("{p}/{q},-{q}/{},0.25", p * 7 + 1);
            lines.push((text.lines().count() + 1, row.clone()));
            text.push_str(&row);
            text.push('\n');
        }
        let all = parse_csv_points(&text, 3, "p.csv").unwrap();
        let one_by_one: Vec<_> = lines
            .iter()
            .map(|(line, row)| parse_csv_row(row, 3, "p.csv", *line).unwrap())
            .collect();
        assert_eq!(all, one_by_one);
        // three bad lines far apart (in different blocks): the error names the first
        let bad: Vec<usize> = [rows - 5, rows / 2, rows / 3]
            .iter()
            .map(|&r| lines[r].0)
            .collect();
        let broken: String = text
            .lines()
            .enumerate()
            .map(|(i, l)| {
                if bad.contains(&(i + 1)) {
                    "1,x,2\n".to_string()
                } else {
                    format!("{l}\n")
                }
            })
            .collect();
        let e = parse_csv_points(&broken, 3, "p.csv").unwrap_err();
        assert_eq!(e.line, Some(lines[rows / 3].0), "{e}");
        assert!(e.to_string().contains("field 2"), "{e}");
    }

    /// A file of one point more than [`MAX_POINTS`] is refused before any number is read,
    /// naming the line (CSV, after a header and a comment) or the array element (JSON) of the
    /// point too many; a file of exactly `MAX_POINTS` points is read.
    #[test]
    fn more_than_max_points_are_refused() {
        let mut csv = String::from("u,v,w\n# comment\n");
        csv.push_str(&"0,0,1\n".repeat(MAX_POINTS));
        assert_eq!(
            parse_csv_points(&csv, 3, "p.csv").unwrap().len(),
            MAX_POINTS
        );
        csv.push_str("1,x,0\n"); // never parsed: the count stops first
        let e = parse_csv_points(&csv, 3, "p.csv").unwrap_err();
        assert_eq!(e.line, Some(MAX_POINTS + 3));
        assert_eq!(
            e.to_string(),
            format!(
                "p.csv:{}: more than 1000000 rows (the limit of a points file)",
                MAX_POINTS + 3
            )
        );
        let mut json = String::from("[");
        json.push_str(&"[0,0,1],\n".repeat(MAX_POINTS));
        json.push_str("[1,\"x\",0]]");
        let doc = Document::parse_json("p.json", &json).unwrap();
        let e = points_from_document(&doc, 3).unwrap_err();
        assert_eq!(e.line, Some(MAX_POINTS + 1));
        assert_eq!(
            e.to_string(),
            format!(
                "p.json:{}: [1000000]: more than 1000000 points (the limit of a points file)",
                MAX_POINTS + 1
            )
        );
    }

    #[test]
    fn what_is_a_header() {
        assert_eq!(csv_header("u,v,w,x,y,z"), Some(6));
        assert_eq!(csv_header("x_0, y.1 ,\"z[2]\""), Some(3));
        assert_eq!(csv_header("u,v,1"), None);
        assert_eq!(csv_header("nan,inf,Infinity"), None);
        assert_eq!(csv_header("u,,w"), None);
        assert_eq!(csv_header("1e5,2"), None);
    }
}
