//! Reading results files: rows of numbers (CSV, JSON lines, or one JSON array of rows), in chunks.
//!
//! The format: a `.json`, `.jsonl` or `.ndjson` file whose first non-space character is `[` and
//! whose next non-space character after it is `[` (or `]`) is ONE JSON array of rows (as
//! `json.dump(rows, f, indent=2)` writes it); any other such file is JSON lines. This is
//! unambiguous: a JSON-lines row is an array of numbers, strings or null, so its first entry is
//! never `[`, and the empty row `[]` is never a valid row. Any other extension is CSV.
//!
//! Every row is checked as what it claims to be: a JSON-lines row and a row of a JSON array are
//! parsed as JSON (numbers keep their exact text), so a `,` or `]` inside a string never splits
//! it. A UTF-8 byte-order mark at the start is ignored; invalid UTF-8 is an error naming the
//! line. A CSV file may start with one header line of column names (`u,v,w,x,y,z`, see
//! [`crate::io::points::csv_header`]); it must have one name per column. The file is streamed:
//! only one line (CSV, JSON lines) or one row (JSON array) is held whole, at most
//! [`MAX_ROW_BYTES`].

use std::io::BufRead;

use num_rational::BigRational;

use super::CHUNK;
use crate::io::points::csv_header;
use crate::io::text::{BOM, not_utf8, plain_io_error};

/// The longest line (CSV, JSON lines) or row (JSON array) of a results file: 16 MiB.
pub const MAX_ROW_BYTES: usize = 16 << 20;
use crate::certify::measures::as_float;
use crate::float::Precision;
use crate::io::{InputError, Problem, RowsProblem};
use crate::number::parse_rational;

/// One field of a row: its text and its 1-based column.
pub(super) struct Field<'a> {
    pub(super) text: &'a str,
    pub(super) column: usize,
}

/// A parsed number: the exact value of its text, and (with a precision) the float it denotes.
#[derive(Clone, Debug)]
pub(super) enum Num {
    /// `nan`, `inf`, empty, or a number that overflows the precision: the row is a failed
    /// claim. The text says what it was; the float is the one it denotes (NaN for `nan` and an
    /// empty field, ±∞ for `inf` and, as round to nearest gives, for an overflowing number).
    NotFinite(String, f64),
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
    let t = unquoted(f.text);
    let body = t.trim_start_matches(['+', '-']);
    let named = |name: &str| body.eq_ignore_ascii_case(name);
    // ±∞ for an infinity or an overflow, by the text's sign
    let infinite = if t.starts_with('-') {
        f64::NEG_INFINITY
    } else {
        f64::INFINITY
    };
    if t.is_empty() || named("nan") {
        return Ok(Num::NotFinite(
            if t.is_empty() {
                "empty field".into()
            } else {
                format!("`{t}`")
            },
            f64::NAN,
        ));
    }
    if named("inf") || named("infinity") {
        return Ok(Num::NotFinite(format!("`{t}`"), infinite));
    }
    let bad = |e| {
        InputError::at(
            file,
            Some(line),
            Some(f.column),
            RowsProblem::MalformedNumber(e),
        )
    };
    match precision {
        Some(p) => {
            if let Some(x) = std_float(t, p) {
                if x.is_finite() {
                    return Ok(Num::Value {
                        float: x,
                        text_exact: None,
                    });
                }
                // a number too large for the precision, however many digits its exponent has
                // (`1e400` and `1e999999` alike): a failed row, never an aborted run
                return Ok(Num::NotFinite(
                    format!("`{t}` overflows {}", p.name()),
                    infinite,
                ));
            }
            let q = parse_rational(t).map_err(bad)?;
            match as_float(&q, p) {
                Some(x) => Ok(Num::Value {
                    float: crate::number::round_f64(&x),
                    text_exact: Some(q),
                }),
                None => Ok(Num::NotFinite(
                    format!("`{t}` overflows {}", p.name()),
                    infinite,
                )),
            }
        }
        None => {
            let q = parse_rational(t).map_err(bad)?;
            Ok(Num::Value {
                float: crate::number::round_f64(&q),
                text_exact: Some(q),
            })
        }
    }
}

/// A field's text without the white space and double quotes around it.
fn unquoted(text: &str) -> &str {
    // a field that starts and ends with a printable ASCII character other than `"` (most of
    // them) is its own text: neither trim removes anything
    let bare = |b: Option<&u8>| b.is_some_and(|&b| b.is_ascii_graphic() && b != b'"');
    let bytes = text.as_bytes();
    if bare(bytes.first()) && bare(bytes.last()) {
        text
    } else {
        text.trim().trim_matches('"')
    }
}

/// The standard library's correctly rounded parse of a number's text to the float of `p`
/// nearest it (the fast path of [`parse_num`]; `None` for text it does not take, such as
/// fractions and hex floats).
fn std_float(t: &str, p: Precision) -> Option<f64> {
    match p {
        Precision::F64 => t.parse::<f64>().ok(),
        Precision::F32 => t.parse::<f32>().ok().map(f64::from),
    }
}

/// The numbers of a CSV row as floats of `p`, straight from its text: its `inputs.len() =
/// width` input numbers and `claimed.len() = dim` claimed ones (the buffers are cleared
/// first), when the row has `width + dim` fields and [`std_float`] reads every one of them
/// as a finite float: then [`parse_row`] would give these floats (each a `Num::Value` without
/// `text_exact`). `false` for any other row (blank and comment lines, other numbers, errors),
/// which [`parse_row`] then reads. No allocation once the buffers have grown.
pub(super) fn csv_floats(
    row: &str,
    width: usize,
    dim: usize,
    p: Precision,
    inputs: &mut Vec<f64>,
    claimed: &mut Vec<f64>,
) -> bool {
    inputs.clear();
    claimed.clear();
    // the line ending is white space the last field's trim would drop; the commas are found
    // in one pass over the row (`str::split` calls `memchr` once per field, slow on short ones)
    let row = row.trim_ascii_end();
    let mut start = 0;
    let fields = memchr::memchr_iter(b',', row.as_bytes())
        .chain([row.len()])
        .map(|end| {
            let field = &row[start..end];
            start = end + 1;
            field
        });
    for (i, field) in fields.enumerate() {
        let x = match std_float(unquoted(field), p) {
            Some(x) if x.is_finite() => x,
            _ => return false,
        };
        if i < width {
            inputs.push(x);
        } else if i < width + dim {
            claimed.push(x);
        } else {
            return false;
        }
    }
    inputs.len() == width && claimed.len() == dim
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
            Num::NotFinite(..) => None,
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

/// A results file to read: its name as errors and reports give it, its [`Format`], and the file
/// opened (its errors name the file).
pub(crate) fn open_results(
    path: &std::path::Path,
) -> Result<(String, Format, std::fs::File), InputError> {
    let file = path.display().to_string();
    // a results file is streamed, so a FIFO (`/dev/stdin`, a shell's `<(…)`) is welcome; a
    // directory opens on some systems and fails at its first read: refuse it by name
    if std::fs::metadata(path).is_ok_and(|m| m.is_dir()) {
        let problem = Problem::NotRegularFile {
            kind: Some("a directory"),
        };
        return Err(InputError::file(&file, problem));
    }
    let format = Format::of(path, &file)?;
    let reader = std::fs::File::open(path).map_err(|e| InputError::file(&file, cannot_read(&e)))?;
    Ok((file, format, reader))
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
        let f = std::fs::File::open(path).map_err(|e| InputError::file(file, cannot_read(&e)))?;
        let mut reader = std::io::BufReader::new(f);
        let mut first = None;
        let mut offset = 0usize;
        loop {
            let buf = reader
                .fill_buf()
                .map_err(|e| InputError::file(file, cannot_read(&e)))?;
            if buf.is_empty() {
                return Ok(Format::JsonLines);
            }
            let n = buf.len();
            for &b in buf {
                offset += 1;
                if is_json_space(b) || (offset <= BOM.len() && BOM.as_bytes()[offset - 1] == b) {
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
    /// Line formats: the bytes of the line being read.
    bytes: Vec<u8>,
    /// The number of columns, if known (to check a CSV header line).
    columns: Option<usize>,
    /// CSV: a line that is neither blank nor a comment has been read.
    data_seen: bool,
    /// JSON array: how many bytes of a byte-order mark have been skipped.
    bom: usize,
    /// Line formats: read lines in bulk after the first ([`Self::read_lines`]); false: every
    /// line one by one (the reference the tests hold the bulk reading to).
    bulk: bool,
}

/// Read `reader` chunk by chunk (a chunk judged before the next is read), hand each chunk's rows
/// `(line, column, text)` to `judge`, which folds them into its report and answers the report's
/// `(checked, failed)`, and call `progress` with those after each chunk. No row at all is an error
/// naming `file`. (What the sequential results checkers share: inverse and routed batches.)
pub(super) fn each_chunk<R: BufRead>(
    reader: &mut RowReader<R>,
    file: &str,
    progress: &mut dyn FnMut(u64, u64),
    mut judge: impl FnMut(&[(usize, usize, &str)]) -> Result<(u64, u64), super::BatchError>,
) -> Result<(), super::BatchError> {
    let mut chunk = Chunk::default();
    loop {
        let eof = reader.read(&mut chunk)?;
        let rows: Vec<(usize, usize, &str)> = chunk.rows().collect();
        let (checked, failed) = judge(&rows)?;
        progress(checked, failed);
        if eof {
            if checked == 0 {
                return Err(InputError::file(file, crate::io::RowsProblem::NoResultRows).into());
            }
            return Ok(());
        }
    }
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
            bytes: Vec::new(),
            columns: None,
            data_seen: false,
            bom: 0,
            bulk: true,
        }
    }

    /// Expect `n` columns: a CSV header line must then have `n` names.
    pub(super) fn expect_columns(mut self, n: usize) -> Self {
        self.columns = Some(n);
        self
    }

    /// The next line (with its line ending) appended to `out`, at most [`MAX_ROW_BYTES`], UTF-8
    /// (the byte-order mark of the first line dropped); 0 at the end of the file.
    fn read_line(&mut self, out: &mut String) -> Result<usize, InputError> {
        self.bytes.clear();
        loop {
            let buf = self.reader.fill_buf().map_err(|e| {
                InputError::file(
                    &self.file,
                    RowsProblem::CannotReadLine {
                        line: self.line,
                        reason: plain_io_error(&e),
                    },
                )
            })?;
            if buf.is_empty() {
                break;
            }
            let (take, done) = match buf.iter().position(|&b| b == b'\n') {
                Some(i) => (i + 1, true),
                None => (buf.len(), false),
            };
            if self.bytes.len() + take > MAX_ROW_BYTES {
                return Err(InputError::at(
                    &self.file,
                    Some(self.line),
                    None,
                    RowsProblem::LineTooLong {
                        limit_mib: MAX_ROW_BYTES >> 20,
                    },
                ));
            }
            self.bytes.extend_from_slice(&buf[..take]);
            self.reader.consume(take);
            if done {
                break;
            }
        }
        let n = self.bytes.len();
        let start = if self.line == 1 && self.bytes.starts_with(BOM.as_bytes()) {
            BOM.len()
        } else {
            0
        };
        match std::str::from_utf8(&self.bytes[start..]) {
            Ok(t) => out.push_str(t),
            Err(e) => {
                let mut err = not_utf8(&self.file, &self.bytes[start..], e.valid_up_to());
                err.line = Some(self.line);
                return Err(err);
            }
        }
        Ok(n)
    }

    /// Read the next rows into `chunk` (at most [`CHUNK`]); true at the end of the file.
    pub(super) fn read(&mut self, chunk: &mut Chunk) -> Result<bool, InputError> {
        chunk.clear();
        chunk.first_line = self.line;
        if self.format != Format::JsonArray {
            return self.read_lines(chunk);
        }
        self.read_array(chunk)
    }

    /// Line formats: the next lines into `chunk` (at most [`CHUNK`]); true at the end of the
    /// file. The first line (which may start with a byte-order mark) and, in CSV, the lines up
    /// to the first data line (which may be a header) are read one by one, the rest in bulk.
    fn read_lines(&mut self, chunk: &mut Chunk) -> Result<bool, InputError> {
        while chunk.starts.len() < CHUNK
            && (!self.bulk || self.line == 1 || (self.format == Format::Csv && !self.data_seen))
        {
            let start = chunk.text.len();
            let mut text = std::mem::take(&mut chunk.text);
            let n = self.read_line(&mut text);
            chunk.text = text;
            if n? == 0 {
                return Ok(true);
            }
            chunk.starts.push(start);
            if self.format == Format::Csv && !self.data_seen {
                let t = chunk.text[start..].trim();
                if !t.is_empty() && !t.starts_with('#') {
                    self.data_seen = true;
                    if let Some(names) = csv_header(t) {
                        if let Some(n) = self.columns.filter(|&n| n != names) {
                            return Err(InputError {
                                file: self.file.clone(),
                                line: Some(self.line),
                                column: None,
                                key: None,
                                problem: Box::new(Problem::HeaderWidth { names, expected: n }),
                                named_at: None,
                            });
                        }
                        // the header is kept as a blank row, so that row i stays line
                        // first_line + i
                        chunk.text.truncate(start);
                    }
                }
            }
            self.line += 1;
        }
        self.read_bulk(chunk)
    }

    /// Whole lines appended to `chunk` until it holds [`CHUNK`] rows or the file ends (true
    /// then): the bytes copied straight from the reader's buffer, each line found by `memchr`,
    /// and checked UTF-8 in one pass at the end. The errors are [`Self::read_line`]'s, for the
    /// first line that has one: a line not UTF-8 (before any later line's), longer than
    /// [`MAX_ROW_BYTES`], or that cannot be read.
    fn read_bulk(&mut self, chunk: &mut Chunk) -> Result<bool, InputError> {
        let mut bytes = std::mem::take(&mut chunk.text).into_bytes();
        // where the line being read starts in `bytes`
        let mut line_start = bytes.len();
        let result = loop {
            if chunk.starts.len() == CHUNK {
                break Ok(false);
            }
            let buf = match self.reader.fill_buf() {
                Ok(buf) => buf,
                Err(e) => {
                    break Err(InputError::file(
                        &self.file,
                        RowsProblem::CannotReadLine {
                            line: self.line,
                            reason: plain_io_error(&e),
                        },
                    ));
                }
            };
            if buf.is_empty() {
                if bytes.len() > line_start {
                    // a last line without a line ending
                    chunk.starts.push(line_start);
                    line_start = bytes.len();
                    self.line += 1;
                }
                break Ok(true);
            }
            let mut used = 0;
            let mut too_long = false;
            while chunk.starts.len() < CHUNK && used < buf.len() {
                let rest = &buf[used..];
                let (take, done) = match memchr::memchr(b'\n', rest) {
                    Some(i) => (i + 1, true),
                    None => (rest.len(), false),
                };
                if bytes.len() - line_start + take > MAX_ROW_BYTES {
                    too_long = true;
                    break;
                }
                bytes.extend_from_slice(&rest[..take]);
                used += take;
                if done {
                    chunk.starts.push(line_start);
                    line_start = bytes.len();
                    self.line += 1;
                }
            }
            self.reader.consume(used);
            if too_long {
                break Err(InputError::at(
                    &self.file,
                    Some(self.line),
                    None,
                    RowsProblem::LineTooLong {
                        limit_mib: MAX_ROW_BYTES >> 20,
                    },
                ));
            }
        };
        // the complete lines (a partial one is left only by an error, which comes after them)
        bytes.truncate(line_start);
        match String::from_utf8(bytes) {
            Ok(text) => chunk.text = text,
            Err(e) => {
                let at = e.utf8_error().valid_up_to();
                let bytes = e.into_bytes();
                let i = chunk.starts.partition_point(|&s| s <= at) - 1;
                let start = chunk.starts[i];
                let end = chunk.starts.get(i + 1).copied().unwrap_or(bytes.len());
                let mut err = not_utf8(&self.file, &bytes[start..end], at - start);
                err.line = Some(chunk.first_line + i);
                return Err(err);
            }
        }
        result
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
                .map_err(|e| InputError::file(&self.file, cannot_read(&e)))?;
            if buf.is_empty() {
                return match (depth, self.between) {
                    (0, Between::Done) => Ok(true),
                    (0, _) => Err(located(
                        &self.file,
                        self.line,
                        self.col,
                        RowsProblem::ArrayNotClosed {
                            line: self.open.0,
                            column: self.open.1,
                        },
                    )),
                    _ => Err(located(
                        &self.file,
                        self.line,
                        self.col,
                        RowsProblem::RowNotClosed {
                            line: row_at.0,
                            column: row_at.1,
                        },
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
                    if self.row.len() >= MAX_ROW_BYTES {
                        return Err(located(
                            &self.file,
                            row_at.0,
                            row_at.1,
                            RowsProblem::RowTooLong {
                                limit_mib: MAX_ROW_BYTES >> 20,
                            },
                        ));
                    }
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
                            return Err(located(&self.file, line, col, RowsProblem::RowEntries));
                        }
                        b']' => {
                            depth = 0;
                            let text = std::str::from_utf8(&self.row).map_err(|_| {
                                located(&self.file, row_at.0, row_at.1, RowsProblem::RowNotUtf8)
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
                if self.between == Between::Start
                    && (line, col) == (1, self.bom + 1)
                    && BOM.as_bytes().get(self.bom) == Some(&b)
                {
                    self.bom += 1;
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
                            RowsProblem::ExpectedRow {
                                found: char::from(b),
                            },
                        ));
                    }
                    (Between::CommaOrEnd, _) => {
                        return Err(located(
                            &self.file,
                            line,
                            col,
                            RowsProblem::ExpectedCommaOrEnd {
                                found: char::from(b),
                            },
                        ));
                    }
                    (Between::Done, _) => {
                        return Err(located(&self.file, line, col, RowsProblem::TextAfterRows));
                    }
                    (Between::Start, _) => {
                        return Err(located(&self.file, line, col, RowsProblem::ExpectedArray));
                    }
                }
            }
            self.reader.consume(used);
        }
    }
}

fn located(file: &str, line: usize, col: usize, problem: RowsProblem) -> InputError {
    InputError::at(file, Some(line), Some(col), problem)
}

/// The operating system's reason a file cannot be read.
pub(super) fn cannot_read(e: &std::io::Error) -> Problem {
    Problem::CannotRead {
        reason: crate::io::text::plain_io_error(e),
    }
}

/// The fields of a JSON row (a JSON-lines row, or a row of a JSON array of rows), each with its
/// own 1-based line (a row may span many lines) and column. `text` is the row, which starts at
/// (`line`, `col`); it must be ONE JSON array of numbers, strings or null (checked by a JSON
/// parser, so that text that is not JSON is never read as a row). Linear in the row's length.
pub(super) fn split_json_row<'a>(
    text: &'a str,
    line: usize,
    col: usize,
    file: &str,
) -> Result<Vec<(usize, Field<'a>)>, InputError> {
    let bad = |l: usize, c: usize, problem: RowsProblem| located(file, l, c, problem);
    if let Err(e) = serde_json::from_str::<serde::de::IgnoredAny>(text.trim_end()) {
        // serde's position is within the row: 1-based line, column (of the row text)
        let (l, c) = if e.line() <= 1 {
            (line, col + e.column().saturating_sub(1))
        } else {
            (line + e.line() - 1, e.column().max(1))
        };
        let msg = e.to_string();
        let msg = msg.split(" at line ").next().unwrap_or(&msg);
        return Err(bad(
            l,
            c,
            RowsProblem::RowJson {
                message: msg.to_string(),
            },
        ));
    }
    let bytes = text.as_bytes();
    let (mut l, mut c) = (line, col);
    let mut out = Vec::new();
    let mut i = 0;
    // the opening bracket
    while i < bytes.len() && bytes[i] != b'[' {
        if bytes[i] == b'\n' {
            (l, c) = (l + 1, 1);
        } else {
            c += 1;
        }
        if !is_json_space(bytes[i]) {
            return Err(bad(l, c - 1, RowsProblem::ExpectedArray));
        }
        i += 1;
    }
    if i == bytes.len() {
        return Err(bad(line, col, RowsProblem::ExpectedArray));
    }
    i += 1;
    c += 1;
    // (start byte, line, column) of the field being read, once its first character is seen
    let mut field: Option<(usize, usize, usize)> = None;
    let (mut in_string, mut escaped) = (false, false);
    while i < bytes.len() {
        let b = bytes[i];
        if in_string {
            if escaped {
                escaped = false;
            } else if b == b'\\' {
                escaped = true;
            } else if b == b'"' {
                in_string = false;
            }
        } else if b == b',' || b == b']' {
            if let Some((start, fl, fc)) = field.take() {
                let t = text[start..i].trim_end();
                out.push((
                    fl,
                    Field {
                        text: if t == "null" { "" } else { t },
                        column: fc,
                    },
                ));
            }
            if b == b']' {
                return Ok(out);
            }
        } else if !is_json_space(b) && field.is_none() {
            if matches!(b, b'[' | b'{' | b't' | b'f') {
                return Err(bad(l, c, RowsProblem::RowEntries));
            }
            field = Some((i, l, c));
            in_string = b == b'"';
        } else if b == b'"' {
            in_string = true;
        }
        if b == b'\n' {
            (l, c) = (l + 1, 1);
        } else {
            c += 1;
        }
        i += 1;
    }
    Err(bad(l, c, RowsProblem::ExpectedArray))
}

/// One line of claimed coordinates, as a results row's claimed columns are read (CSV, or one
/// JSON array when the line starts with `[`): `dim` numbers in any syntax `check --results`
/// reads, each the float of `precision` nearest its text (hex floats exact; `nan` and an empty
/// field give NaN, `inf` and a number beyond the precision's range ±∞: a failed row when
/// judged). What `tribez hunt` reads of its target.
///
/// Errors: one line saying what is wrong (an empty or comment line, the wrong number of
/// numbers, a field that is not a number, with its 1-based column).
pub fn parse_claimed_line(
    text: &str,
    dim: usize,
    precision: Precision,
) -> Result<Vec<f64>, String> {
    let t = text.trim();
    if t.is_empty() {
        return Err("an empty line".into());
    }
    let format = if t.starts_with('[') {
        Format::JsonLines
    } else {
        Format::Csv
    };
    match parse_row(format, text, 1, 1, 0, dim, Some(precision), "") {
        Ok(Some((_, claimed))) => Ok(claimed
            .iter()
            .map(|x| match x {
                Num::Value { float, .. } => *float,
                Num::NotFinite(_, x) => *x,
            })
            .collect()),
        Ok(None) => Err("a comment line".into()),
        Err(e) => Err(match (&*e.problem, e.column) {
            (Problem::Rows(RowsProblem::ColumnCount { found, .. }), _) => {
                let numbers = if *found == 1 { "number" } else { "numbers" };
                format!("{found} {numbers}, expected {dim}")
            }
            (p, Some(c)) => format!("column {c}: {p}"),
            (p, None) => p.to_string(),
        }),
    }
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
        Format::JsonLines => split_json_row(row, line, 1, file)?,
        Format::Csv => split_csv(row).into_iter().map(|f| (line, f)).collect(),
    };
    if fields.len() != width + dim {
        return Err(InputError::at(
            file,
            Some(line),
            (format == Format::JsonArray).then_some(col),
            RowsProblem::ColumnCount {
                found: fields.len(),
                width,
                dim,
            },
        ));
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
        Format::JsonLines => split_json_row(row, line, 1, file)
            .unwrap_or_default()
            .into_iter()
            .map(|(_, f)| f)
            .collect(),
        Format::Csv => split_csv(row),
    };
    fields
        .iter()
        .map(|f| unquoted(f.text).to_string())
        .collect()
}

/// Fuzzing entry (see [`crate::fuzz`]): every row of `data` read as a results file in
/// `format` and parsed; the first byte chooses the input width (1 to 4), the claimed dimension
/// (1 to 3) and the precision (none, f64, f32). Errors are fine; a panic or a hang is the bug.
#[cfg(any(fuzzing, feature = "unstable-internals"))]
pub(crate) fn fuzz_rows(format: Format, data: &[u8]) {
    let Some((&first, rest)) = data.split_first() else {
        return;
    };
    let width = usize::from(first) % 4 + 1;
    let dim = usize::from(first / 4) % 3 + 1;
    let precision = [None, Some(Precision::F64), Some(Precision::F32)][usize::from(first / 12) % 3];
    // a small buffer, so that rows straddle refills
    let reader = std::io::BufReader::with_capacity(7, rest);
    let mut rows = RowReader::new(reader, format, "fuzz").expect_columns(width + dim);
    let mut chunk = Chunk::default();
    loop {
        let Ok(eof) = rows.read(&mut chunk) else {
            return;
        };
        for (line, col, text) in chunk.rows() {
            let _ = parse_row(format, text, line, col, width, dim, precision, "fuzz");
            let _ = texts_of(format, text, line, col, "fuzz");
        }
        if eof {
            return;
        }
    }
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

    /// [`csv_floats`] reads a row exactly when [`parse_row`] gives finite floats without exact
    /// values, and then reads the same floats.
    #[test]
    fn csv_floats_agree_with_parse_row() {
        let rows = [
            "0.5,0.25,0.25,1,2,3\n",
            "0.5,0.25,0.25,1,2,3",
            "0.5,0.25,0.25,1,2,3\r\n",
            " 0.5 ,\t0.25,\"0.25\",+1e0,-2.5E-3,3.\n",
            "\u{a0}0.5,.25,0.25,1,2,3\n",
            "0.5,0.25,0.25,1,2\n",
            "0.5,0.25,0.25,1,2,3,4\n",
            "0.5,0.25,0.25,1,2,\n",
            "0.5,0.25,0.25,1,nan,3\n",
            "0.5,0.25,0.25,1,-inf,3\n",
            "0.5,0.25,0.25,1,1e400,3\n",
            "0.5,0.25,0.25,1,1e39,3\n",
            "0x1.8p-1,0.25,0.25,1,2,3\n",
            "1/2,0.25,0.25,1,2,3\n",
            "0.5,0.25,0.25,1,2,3 # note\n",
            "# 0.5,0.25,0.25,1,2,3\n",
            "\n",
            "1e-400,0.25,0.25,1,2,3\n",
            "0.1000000000000000055511151231257827,0.25,0.25,1,2,3\n",
        ];
        for row in rows {
            for p in [Precision::F64, Precision::F32] {
                let (mut inputs, mut claimed) = (Vec::new(), Vec::new());
                let fast = csv_floats(row, 3, 3, p, &mut inputs, &mut claimed);
                let full = parse_row(Format::Csv, row, 1, 1, 3, 3, Some(p), "f");
                let floats = |xs: &[Num]| {
                    xs.iter()
                        .map(|x| match x {
                            Num::Value {
                                float,
                                text_exact: None,
                            } => Some(*float),
                            _ => None,
                        })
                        .collect::<Option<Vec<f64>>>()
                };
                let plain = match &full {
                    Ok(Some((i, c))) => floats(i).zip(floats(c)),
                    _ => None,
                };
                assert_eq!(fast, plain.is_some(), "{row:?} {p:?}");
                if let Some((i, c)) = plain {
                    assert_eq!((inputs, claimed), (i, c), "{row:?} {p:?}");
                }
            }
        }
    }

    /// What a reader read: every chunk (first line, row starts, text), then its error if any.
    type Read = (Vec<(usize, Vec<usize>, String)>, Option<String>);

    /// Every chunk and error of `text` read by `reader` (buffer of `capacity` bytes, in bulk or
    /// line by line).
    fn chunks(text: &[u8], format: Format, capacity: usize, bulk: bool) -> Read {
        let reader = std::io::BufReader::with_capacity(capacity, text);
        let mut rows = RowReader::new(reader, format, "f").expect_columns(2);
        rows.bulk = bulk;
        let mut out = Vec::new();
        let mut chunk = Chunk::default();
        loop {
            match rows.read(&mut chunk) {
                Ok(eof) => {
                    out.push((chunk.first_line, chunk.starts.clone(), chunk.text.clone()));
                    if eof {
                        return (out, None);
                    }
                }
                Err(e) => return (out, Some(e.to_string())),
            }
        }
    }

    proptest::proptest! {
        /// Lines read in bulk are the lines read one by one: the same rows, line numbers and
        /// errors (a byte-order mark, a header, comments, blank lines, CRLF, no final line
        /// ending, bytes that are not UTF-8), whatever the buffer size.
        #[test]
        fn lines_read_in_bulk_are_lines_read_one_by_one(
            lines in proptest::collection::vec(0usize..9, 0..40),
            bom in proptest::bool::ANY,
            end in proptest::bool::ANY,
            capacity in 1usize..64,
            json in proptest::bool::ANY,
        ) {
            let pool: [&[u8]; 9] = [
                b"1,2", b"0.5,-3e4", b"", b"# c", b"x,y", b"1,\xff", b"\xe2\x82", b"\"\xc3\xa9\",1", b" 1 , 2 ",
            ];
            let mut text = Vec::new();
            if bom {
                text.extend_from_slice(BOM.as_bytes());
            }
            for (i, &k) in lines.iter().enumerate() {
                text.extend_from_slice(pool[k]);
                if i + 1 < lines.len() || end {
                    text.extend_from_slice(if i % 3 == 0 { b"\r\n" } else { b"\n" });
                }
            }
            let format = if json { Format::JsonLines } else { Format::Csv };
            proptest::prop_assert_eq!(
                chunks(&text, format, capacity, true),
                chunks(&text, format, capacity, false)
            );
        }
    }

    /// A line longer than [`MAX_ROW_BYTES`] after the first is the same error in bulk, and a
    /// line not UTF-8 before it comes first.
    #[test]
    fn a_long_line_read_in_bulk_is_the_error_of_a_line_read_alone() {
        let long = vec![b'1'; MAX_ROW_BYTES];
        for before in [&b"1,2\n3,4\n"[..], b"1,2\n3,\xff\n"] {
            let mut text = before.to_vec();
            text.extend_from_slice(&long);
            text.extend_from_slice(b"\n5,6\n");
            let bulk = chunks(&text, Format::Csv, 1 << 20, true);
            assert_eq!(bulk, chunks(&text, Format::Csv, 1 << 20, false));
            assert!(bulk.1.is_some());
        }
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
