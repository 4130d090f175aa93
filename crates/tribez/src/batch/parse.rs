//! Reading results files: rows of numbers (CSV, JSON lines, or one JSON array of rows), in chunks.
//!
//! The format: a `.json`, `.jsonl` or `.ndjson` file whose first non-space character is `[` and
//! whose next non-space character after it is `[` (or `]`) is ONE JSON array of rows (as
//! `json.dump(rows, f, indent=2)` writes it); any other such file is JSON lines. This is
//! unambiguous: a JSON-lines row is an array of numbers, strings or null, so its first entry is
//! never `[`, and the empty row `[]` is never a valid row. Any other extension is CSV.

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

/// The layout of a results file (see the module documentation for how it is recognised).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// Comma-separated values, `#` comment lines.
    Csv,
    /// One JSON array per line.
    JsonLines,
    /// One JSON array of row arrays, rows possibly spread over many lines.
    JsonArray,
}

impl Format {
    /// The format of `path`: by extension, then (for JSON) by its first two non-space characters.
    pub fn of(path: &std::path::Path, file: &str) -> Result<Format, InputError> {
        let ext = path
            .extension()
            .and_then(|e| e.to_str())
            .unwrap_or("")
            .to_ascii_lowercase();
        if !matches!(ext.as_str(), "jsonl" | "ndjson" | "json") {
            return Ok(Format::Csv);
        }
        let f = std::fs::File::open(path)
            .map_err(|e| InputError::file(file, format!("cannot read: {e}")))?;
        let mut reader = std::io::BufReader::new(f);
        let mut first = None;
        loop {
            let buf = reader
                .fill_buf()
                .map_err(|e| InputError::file(file, format!("cannot read: {e}")))?;
            if buf.is_empty() {
                return Ok(Format::JsonLines);
            }
            let n = buf.len();
            for &b in buf {
                if is_json_space(b) {
                    continue;
                }
                match first {
                    None if b == b'[' => first = Some(b),
                    None => return Ok(Format::JsonLines),
                    Some(_) if b == b'[' || b == b']' => return Ok(Format::JsonArray),
                    Some(_) => return Ok(Format::JsonLines),
                }
            }
            reader.consume(n);
        }
    }
}

fn is_json_space(b: u8) -> bool {
    matches!(b, b' ' | b'\t' | b'\n' | b'\r')
}

/// Up to [`CHUNK`] rows of a results file, read into one buffer (no allocation per row).
#[derive(Default)]
pub(super) struct Chunk {
    /// The rows' text, one after another (each line with its line ending, as read).
    pub(super) text: String,
    /// Byte offset of each row's start in `text`.
    pub(super) starts: Vec<usize>,
    /// 1-based number of the first line (line formats: row `i` is line `first_line + i`).
    pub(super) first_line: usize,
    /// A JSON array of rows: the 1-based (line, column) where each row starts.
    pub(super) at: Vec<(usize, usize)>,
}

impl Chunk {
    fn clear(&mut self) {
        self.text.clear();
        self.starts.clear();
        self.at.clear();
    }

    pub(super) fn len(&self) -> usize {
        self.starts.len()
    }

    /// The text of row `i` of this chunk.
    pub(super) fn row(&self, i: usize) -> &str {
        let end = self.starts.get(i + 1).copied().unwrap_or(self.text.len());
        &self.text[self.starts[i]..end]
    }

    /// Where row `i` starts: 1-based (line, column).
    pub(super) fn position(&self, i: usize) -> (usize, usize) {
        self.at.get(i).copied().unwrap_or((self.first_line + i, 1))
    }

    /// `(line, column, text)` for every row, in order.
    pub(super) fn rows(&self) -> impl Iterator<Item = (usize, usize, &str)> + '_ {
        (0..self.len()).map(|i| {
            let (line, col) = self.position(i);
            (line, col, self.row(i))
        })
    }
}

/// Where the scan of a JSON array of rows is, between rows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Between {
    /// Before the top-level `[`.
    Start,
    /// After the top-level `[`: a row or `]`.
    First,
    /// After a `,`: a row.
    Row,
    /// After a row: `,` or `]`.
    CommaOrEnd,
    /// After the top-level `]`: only white space.
    Done,
}

/// The rows of a results file, read chunk by chunk.
pub(super) struct RowReader<R> {
    reader: R,
    format: Format,
    file: String,
    /// 1-based line and byte column of the next byte.
    line: usize,
    col: usize,
    /// JSON array: the state between rows, and where the top-level array opened.
    between: Between,
    open: (usize, usize),
    /// JSON array: the bytes of the row being read.
    row: Vec<u8>,
}

impl<R: BufRead> RowReader<R> {
    pub(super) fn new(reader: R, format: Format, file: &str) -> Self {
        RowReader {
            reader,
            format,
            file: file.into(),
            line: 1,
            col: 1,
            between: Between::Start,
            open: (1, 1),
            row: Vec::new(),
        }
    }

    /// Read the next rows into `chunk` (at most [`CHUNK`]); true at the end of the file.
    pub(super) fn read(&mut self, chunk: &mut Chunk) -> Result<bool, InputError> {
        chunk.clear();
        chunk.first_line = self.line;
        if self.format != Format::JsonArray {
            while chunk.starts.len() < CHUNK {
                let start = chunk.text.len();
                let n = self.reader.read_line(&mut chunk.text).map_err(|e| {
                    InputError::file(&self.file, format!("cannot read line {}: {e}", self.line))
                })?;
                if n == 0 {
                    return Ok(true);
                }
                chunk.starts.push(start);
                self.line += 1;
            }
            return Ok(false);
        }
        self.read_array(chunk)
    }

    /// A JSON array of rows: scan it (brackets, strings and escapes), cutting out each row's
    /// text; the rows themselves are split and parsed later, in parallel.
    fn read_array(&mut self, chunk: &mut Chunk) -> Result<bool, InputError> {
        // Inside a row: its start, bracket depth, and whether in a string / after a backslash.
        let mut row_at = (0, 0);
        let mut depth = 0usize;
        let (mut in_string, mut escaped) = (false, false);
        loop {
            let buf = self
                .reader
                .fill_buf()
                .map_err(|e| InputError::file(&self.file, format!("cannot read: {e}")))?;
            if buf.is_empty() {
                return match (depth, self.between) {
                    (0, Between::Done) => Ok(true),
                    (0, _) => Err(located(
                        &self.file,
                        self.line,
                        self.col,
                        format!(
                            "invalid JSON: unexpected end of file: the array opened at line {}, column {} is never closed",
                            self.open.0, self.open.1
                        ),
                    )),
                    _ => Err(located(
                        &self.file,
                        self.line,
                        self.col,
                        format!(
                            "invalid JSON: unexpected end of file: the row opened at line {}, column {} is never closed",
                            row_at.0, row_at.1
                        ),
                    )),
                };
            }
            let mut used = 0;
            for &b in buf {
                used += 1;
                let (line, col) = (self.line, self.col);
                if b == b'\n' {
                    self.line += 1;
                    self.col = 1;
                } else {
                    self.col += 1;
                }
                if depth > 0 {
                    self.row.push(b);
                    if in_string {
                        if escaped {
                            escaped = false;
                        } else if b == b'\\' {
                            escaped = true;
                        } else if b == b'"' {
                            in_string = false;
                        }
                        continue;
                    }
                    match b {
                        b'"' => in_string = true,
                        b'[' | b'{' => {
                            return Err(located(
                                &self.file,
                                line,
                                col,
                                "a row's entries must be numbers, strings or null".into(),
                            ));
                        }
                        b']' => {
                            depth = 0;
                            let text = std::str::from_utf8(&self.row).map_err(|_| {
                                located(
                                    &self.file,
                                    row_at.0,
                                    row_at.1,
                                    "the row is not UTF-8 text".into(),
                                )
                            })?;
                            chunk.starts.push(chunk.text.len());
                            chunk.text.push_str(text);
                            chunk.at.push(row_at);
                            self.row.clear();
                            self.between = Between::CommaOrEnd;
                            if chunk.starts.len() == CHUNK {
                                self.reader.consume(used);
                                return Ok(false);
                            }
                        }
                        _ => {}
                    }
                    continue;
                }
                if is_json_space(b) {
                    continue;
                }
                match (self.between, b) {
                    (Between::Start, b'[') => {
                        self.open = (line, col);
                        self.between = Between::First;
                    }
                    (Between::First | Between::Row, b'[') => {
                        depth = 1;
                        row_at = (line, col);
                        self.row.push(b);
                    }
                    (Between::First, b']') | (Between::CommaOrEnd, b']') => {
                        self.between = Between::Done;
                    }
                    (Between::CommaOrEnd, b',') => self.between = Between::Row,
                    (Between::First | Between::Row, _) => {
                        return Err(located(
                            &self.file,
                            line,
                            col,
                            format!(
                                "invalid JSON: expected a row (an array `[…]`), found `{}`",
                                char::from(b).escape_default()
                            ),
                        ));
                    }
                    (Between::CommaOrEnd, _) => {
                        return Err(located(
                            &self.file,
                            line,
                            col,
                            format!(
                                "invalid JSON: expected ',' or ']' after a row, found `{}`",
                                char::from(b).escape_default()
                            ),
                        ));
                    }
                    (Between::Done, _) => {
                        return Err(located(
                            &self.file,
                            line,
                            col,
                            "invalid JSON: unexpected text after the array of rows".into(),
                        ));
                    }
                    (Between::Start, _) => {
                        return Err(located(
                            &self.file,
                            line,
                            col,
                            "expected a JSON array `[…]`".into(),
                        ));
                    }
                }
            }
            self.reader.consume(used);
        }
    }
}

fn located(file: &str, line: usize, col: usize, message: String) -> InputError {
    InputError {
        file: file.into(),
        line: Some(line),
        column: Some(col),
        key: None,
        message,
    }
}

/// The fields of a row of a JSON array of rows: each with its own 1-based line (a row may span
/// many lines). `text` is the row from its `[` to its `]`, which starts at (`line`, `col`).
pub(super) fn split_json_row<'a>(
    text: &'a str,
    line: usize,
    col: usize,
    file: &str,
) -> Result<Vec<(usize, Field<'a>)>, InputError> {
    // 1-based (line, column) of byte offset `k` of the row text
    let at = |k: usize| {
        let before = &text.as_bytes()[..k];
        match before.iter().rposition(|&b| b == b'\n') {
            None => (line, col + k),
            Some(nl) => (
                line + before.iter().filter(|&&b| b == b'\n').count(),
                k - nl,
            ),
        }
    };
    let inner = &text[1..text.len() - 1];
    if inner.bytes().all(is_json_space) {
        return Ok(Vec::new());
    }
    let mut out = Vec::new();
    let (mut start, mut in_string, mut escaped) = (0, false, false);
    for (i, b) in inner
        .bytes()
        .enumerate()
        .chain(std::iter::once((inner.len(), b',')))
    {
        if in_string {
            if escaped {
                escaped = false;
            } else if b == b'\\' {
                escaped = true;
            } else if b == b'"' {
                in_string = false;
            }
            continue;
        }
        if b == b'"' {
            in_string = true;
        } else if b == b',' {
            let raw = &inner[start..i];
            let lead = raw.len() - raw.trim_start().len();
            let field = raw.trim();
            let (l, c) = at(1 + start + lead);
            if field.is_empty() {
                return Err(InputError {
                    file: file.into(),
                    line: Some(l),
                    column: Some(c),
                    key: None,
                    message: "invalid JSON: expected a number, a string or null".into(),
                });
            }
            out.push((
                l,
                Field {
                    text: if field == "null" { "" } else { field },
                    column: c,
                },
            ));
            start = i + 1;
        }
    }
    Ok(out)
}

/// Read one row into numbers; `None` for blank and comment lines. `line` and `col` locate the
/// row's start.
#[allow(clippy::too_many_arguments)]
pub(super) fn parse_row(
    format: Format,
    row: &str,
    line: usize,
    col: usize,
    width: usize,
    dim: usize,
    precision: Option<Precision>,
    file: &str,
) -> Result<Option<Row>, InputError> {
    let t = row.trim();
    if t.is_empty() || (format != Format::JsonArray && t.starts_with('#')) {
        return Ok(None);
    }
    let fields = match format {
        Format::JsonArray => split_json_row(row, line, col, file)?,
        Format::JsonLines => split_json(row, file, line)?
            .into_iter()
            .map(|f| (line, f))
            .collect(),
        Format::Csv => split_csv(row).into_iter().map(|f| (line, f)).collect(),
    };
    if fields.len() != width + dim {
        return Err(InputError {
            file: file.into(),
            line: Some(line),
            column: (format == Format::JsonArray).then_some(col),
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
        .map(|(l, f)| parse_num(f, precision, file, *l))
        .collect::<Result<Vec<_>, _>>()?;
    let mut inputs = nums;
    let claimed = inputs.split_off(width);
    Ok(Some((inputs, claimed)))
}

/// The field texts of a row (unquoted), for reports.
pub(super) fn texts_of(
    format: Format,
    row: &str,
    line: usize,
    col: usize,
    file: &str,
) -> Vec<String> {
    let fields: Vec<Field<'_>> = match format {
        Format::JsonArray => split_json_row(row, line, col, file)
            .unwrap_or_default()
            .into_iter()
            .map(|(_, f)| f)
            .collect(),
        Format::JsonLines => split_json(row, file, line).unwrap_or_default(),
        Format::Csv => split_csv(row),
    };
    fields
        .iter()
        .map(|f| f.text.trim().trim_matches('"').to_string())
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Rows cut out of a JSON array read through a 3-byte buffer (so rows, strings and escapes
    /// straddle refills): each row's text and start, a `]` and an escaped quote inside strings.
    #[test]
    fn array_rows_across_buffer_refills() {
        let text = "\n [ [1, \"a]\\\"b\", 2],\n  [\n   3,\n   4\n  ],[5]\n]\n";
        let reader = std::io::BufReader::with_capacity(3, text.as_bytes());
        let mut rows = RowReader::new(reader, Format::JsonArray, "f.json");
        let mut chunk = Chunk::default();
        assert!(rows.read(&mut chunk).unwrap());
        let got: Vec<(usize, usize, &str)> = chunk.rows().collect();
        assert_eq!(
            got,
            vec![
                (2, 4, "[1, \"a]\\\"b\", 2]"),
                (3, 3, "[\n   3,\n   4\n  ]"),
                (6, 5, "[5]"),
            ]
        );
        // fields keep their own lines and columns
        let fields = split_json_row(got[1].2, 3, 3, "f.json").unwrap();
        let at: Vec<(usize, usize, &str)> =
            fields.iter().map(|(l, f)| (*l, f.column, f.text)).collect();
        assert_eq!(at, vec![(4, 4, "3"), (5, 4, "4")]);
        let fields = split_json_row(got[0].2, 2, 4, "f.json").unwrap();
        let at: Vec<(usize, usize, &str)> =
            fields.iter().map(|(l, f)| (*l, f.column, f.text)).collect();
        assert_eq!(at, vec![(2, 5, "1"), (2, 8, "\"a]\\\"b\""), (2, 17, "2")]);
    }

    #[test]
    fn the_format_is_told_by_the_first_two_non_space_characters() {
        let dir = std::env::temp_dir().join(format!("tribez-format-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let cases = [
            ("a.json", " \n[\n  [1, 2]]", Format::JsonArray),
            ("a.jsonl", "[[1, 2]]", Format::JsonArray),
            ("b.json", "[]", Format::JsonArray),
            ("c.json", "[1, 2]\n[3, 4]\n", Format::JsonLines),
            ("d.json", "# comment\n[1, 2]\n", Format::JsonLines),
            ("e.ndjson", "[\"1\", 2]\n", Format::JsonLines),
            ("f.json", "", Format::JsonLines),
            ("g.csv", "[[1, 2]]", Format::Csv),
        ];
        for (name, text, format) in cases {
            let path = dir.join(name);
            std::fs::write(&path, text).unwrap();
            assert_eq!(Format::of(&path, name).unwrap(), format, "{name}");
        }
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
