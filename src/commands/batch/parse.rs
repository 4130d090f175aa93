//! Reading results files: rows of numbers (CSV or JSON lines), in chunks.

use std::io::BufRead;

use num_rational::BigRational;

use super::CHUNK;
use crate::certify::measures::as_float;
use crate::float::Precision;
use crate::io::InputError;
use crate::number::parse_rational;

/// One field of a row: its text and its 1-based column.
pub(super) struct Field<'a> {
    pub(super) text: &'a str,
    pub(super) column: usize,
}

/// A parsed number: the exact value of its text, and (with a precision) the float it denotes.
#[derive(Clone, Debug)]
pub(super) enum Num {
    /// `nan`, `inf` or empty: the row is a failed claim.
    NotFinite(String),
    /// A number.
    Value {
        float: f64,
        text_exact: Option<BigRational>,
    },
}

pub(super) fn parse_num(
    f: &Field<'_>,
    precision: Option<Precision>,
    file: &str,
    line: usize,
) -> Result<Num, InputError> {
    let t = f.text.trim().trim_matches('"');
    let lower = t.to_ascii_lowercase();
    let body = lower.trim_start_matches(['+', '-']);
    if t.is_empty() || body == "nan" || body == "inf" || body == "infinity" {
        return Ok(Num::NotFinite(if t.is_empty() {
            "empty field".into()
        } else {
            format!("`{t}`")
        }));
    }
    let bad = |msg: String| InputError {
        file: file.into(),
        line: Some(line),
        column: Some(f.column),
        key: None,
        message: msg,
    };
    match precision {
        Some(p) => {
            // Fast path: the standard library's correctly rounded decimal parsing.
            let fast = match p {
                Precision::F64 => t.parse::<f64>().ok(),
                Precision::F32 => t.parse::<f32>().ok().map(f64::from),
            };
            if let Some(x) = fast.filter(|x| x.is_finite()) {
                return Ok(Num::Value {
                    float: x,
                    text_exact: None,
                });
            }
            let q = parse_rational(t).map_err(|e| bad(format!("malformed number: {e}")))?;
            match as_float(&q, p) {
                Some(x) => Ok(Num::Value {
                    float: crate::number::round_f64(&x),
                    text_exact: Some(q),
                }),
                None => Ok(Num::NotFinite(format!("`{t}` overflows {}", p.name()))),
            }
        }
        None => {
            let q = parse_rational(t).map_err(|e| bad(format!("malformed number: {e}")))?;
            Ok(Num::Value {
                float: crate::number::round_f64(&q),
                text_exact: Some(q),
            })
        }
    }
}

impl Num {
    /// The exact value of the text (intended).
    pub(super) fn text_value(&self, text: &str) -> Option<BigRational> {
        match self {
            Num::Value {
                text_exact: Some(q),
                ..
            } => Some(q.clone()),
            Num::Value { .. } => parse_rational(text).ok(),
            Num::NotFinite(_) => None,
        }
    }
}

pub(super) fn split_csv(line: &str) -> Vec<Field<'_>> {
    let mut out = Vec::new();
    let mut start = 0;
    for (i, ch) in line.char_indices() {
        if ch == ',' {
            out.push(Field {
                text: &line[start..i],
                column: start + 1,
            });
            start = i + 1;
        }
    }
    out.push(Field {
        text: &line[start..],
        column: start + 1,
    });
    out
}

/// The fields of a JSON-lines row (an array of numbers, strings or nulls).
pub(super) fn split_json<'a>(
    line: &'a str,
    file: &str,
    line_no: usize,
) -> Result<Vec<Field<'a>>, InputError> {
    let bad = |col: usize, msg: &str| InputError {
        file: file.into(),
        line: Some(line_no),
        column: Some(col),
        key: None,
        message: msg.into(),
    };
    let t = line.trim_end();
    let open = t
        .find('[')
        .ok_or_else(|| bad(1, "expected a JSON array `[…]`"))?;
    if !t[..open].trim().is_empty() || !t.ends_with(']') {
        return Err(bad(1, "expected a JSON array `[…]`"));
    }
    let inner = &t[open + 1..t.len() - 1];
    if inner.trim().is_empty() {
        return Ok(Vec::new());
    }
    let mut out = Vec::new();
    let mut start = 0;
    for (i, ch) in inner
        .char_indices()
        .chain(std::iter::once((inner.len(), ',')))
    {
        if ch == ',' {
            let raw = &inner[start..i];
            let lead = raw.len() - raw.trim_start().len();
            let text = raw.trim();
            let text = if text == "null" { "" } else { text };
            if text.contains(['[', '{', ']', '}']) {
                return Err(bad(
                    open + 2 + start + lead,
                    "expected numbers, strings or null",
                ));
            }
            out.push(Field {
                text,
                column: open + 2 + start + lead,
            });
            start = i + 1;
        }
    }
    Ok(out)
}

/// A parsed row: its input numbers and its claimed numbers.
pub(super) type Row = (Vec<Num>, Vec<Num>);

/// Up to [`CHUNK`] lines of a results file, read into one buffer (no allocation per line).
#[derive(Default)]
pub(super) struct Chunk {
    /// The lines' text, one after another (each with its line ending, as read).
    pub(super) text: String,
    /// Byte offset of each line's start in `text`.
    pub(super) starts: Vec<usize>,
    /// 1-based number of the first line.
    pub(super) first_line: usize,
}

impl Chunk {
    /// Read the next lines, numbering them from `first_line`; true at the end of the file.
    pub(super) fn read(
        &mut self,
        reader: &mut impl BufRead,
        first_line: usize,
        file: &str,
    ) -> Result<bool, InputError> {
        self.text.clear();
        self.starts.clear();
        self.first_line = first_line;
        while self.starts.len() < CHUNK {
            let start = self.text.len();
            let n = reader.read_line(&mut self.text).map_err(|e| {
                InputError::file(
                    file,
                    format!("cannot read line {}: {e}", first_line + self.starts.len()),
                )
            })?;
            if n == 0 {
                return Ok(true);
            }
            self.starts.push(start);
        }
        Ok(false)
    }

    pub(super) fn len(&self) -> usize {
        self.starts.len()
    }

    /// The text of line number `no` (which must be in this chunk).
    pub(super) fn line(&self, no: usize) -> &str {
        let i = no - self.first_line;
        let end = self.starts.get(i + 1).copied().unwrap_or(self.text.len());
        &self.text[self.starts[i]..end]
    }

    /// `(line number, text)` for every line.
    pub(super) fn lines(&self) -> impl Iterator<Item = (usize, &str)> + '_ {
        (0..self.len()).map(|i| (self.first_line + i, self.line(self.first_line + i)))
    }
}

/// Read one data line into numbers; `None` for blank and comment lines.
pub(super) fn parse_line(
    line: &str,
    json_lines: bool,
    width: usize,
    dim: usize,
    precision: Option<Precision>,
    file: &str,
    line_no: usize,
) -> Result<Option<Row>, InputError> {
    let t = line.trim();
    if t.is_empty() || t.starts_with('#') {
        return Ok(None);
    }
    let fields = if json_lines {
        split_json(line, file, line_no)?
    } else {
        split_csv(line)
    };
    if fields.len() != width + dim {
        return Err(InputError {
            file: file.into(),
            line: Some(line_no),
            column: None,
            key: None,
            message: format!(
                "{} columns, expected {} ({width} input coordinates, then the {dim} claimed coordinates of the point)",
                fields.len(),
                width + dim
            ),
        });
    }
    let nums = fields
        .iter()
        .map(|f| parse_num(f, precision, file, line_no))
        .collect::<Result<Vec<_>, _>>()?;
    let mut inputs = nums;
    let claimed = inputs.split_off(width);
    Ok(Some((inputs, claimed)))
}

pub(super) fn texts_of(line: &str, json_lines: bool, file: &str, line_no: usize) -> Vec<String> {
    let fields = if json_lines {
        split_json(line, file, line_no).unwrap_or_default()
    } else {
        split_csv(line)
    };
    fields
        .iter()
        .map(|f| f.text.trim().trim_matches('"').to_string())
        .collect()
}
