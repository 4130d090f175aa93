//! Lists of points: CSV (one point per line, numbers separated by commas; `#` starts a comment
//! line) or JSON (an array of arrays), numbers read exactly from their text.

use std::path::Path;

use num_rational::BigRational;

use super::InputError;
use super::tree::Document;
use crate::number::parse_rational;

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
        let rows = doc.array(&doc.root, "")?;
        let mut out = Vec::with_capacity(rows.len());
        for (i, row) in rows.iter().enumerate() {
            let key = format!("[{i}]");
            let p = doc.rationals(row, &key)?;
            if p.len() != width {
                return Err(doc.error(
                    row,
                    &key,
                    format!("point has {} coordinates, expected {width}", p.len()),
                ));
            }
            out.push(p);
        }
        if out.is_empty() {
            return Err(InputError::file(file, "no points"));
        }
        return Ok(out);
    }
    let text = std::fs::read_to_string(path)
        .map_err(|e| InputError::file(&file, format!("cannot read: {e}")))?;
    let mut out = Vec::new();
    for (i, line) in text.lines().enumerate() {
        let t = line.trim();
        if t.is_empty() || t.starts_with('#') {
            continue;
        }
        out.push(parse_csv_row(t, width, &file, i + 1)?);
    }
    if out.is_empty() {
        return Err(InputError::file(file, "no points"));
    }
    Ok(out)
}

/// One CSV row of exactly `width` numbers; errors name the line and column (field).
pub fn parse_csv_row(
    line: &str,
    width: usize,
    file: &str,
    line_no: usize,
) -> Result<Vec<BigRational>, InputError> {
    let fields: Vec<&str> = line.split(',').collect();
    if fields.len() != width {
        return Err(InputError {
            file: file.into(),
            line: Some(line_no),
            column: None,
            key: None,
            message: format!("{} fields, expected {width}", fields.len()),
        });
    }
    let mut column = 1; // character column where the field starts
    let mut out = Vec::with_capacity(fields.len());
    for (c, f) in fields.iter().enumerate() {
        out.push(parse_rational(f).map_err(|e| InputError {
            file: file.into(),
            line: Some(line_no),
            column: Some(column),
            key: Some(format!("field {}", c + 1)),
            message: e.to_string(),
        })?);
        column += f.chars().count() + 1;
    }
    Ok(out)
}
