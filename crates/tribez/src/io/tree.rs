//! A small document tree read from TOML or JSON, keeping for every value its line and, for
//! numbers, their exact TEXT (so `0.1` means 1/10, never the f64 nearest it).
//!
//! JSON is read by a small parser of our own, because the usual readers turn numbers into
//! f64 and silently keep the last of two duplicated keys; both would be wrong here. TOML is read
//! with the `toml` crate's borrowed document (`DeTable`), whose spans give the exact number text
//! and the line.

use std::path::Path;

use num_rational::BigRational;

use super::text::{LineIndex, MAX_FILE_BYTES, read_text, strip_bom};
use super::{InputError, JsonSyntax, Problem};
use crate::number::parse_rational;

/// A value with the line it starts on.
#[derive(Clone, Debug, PartialEq)]
pub struct Node {
    /// The value.
    pub value: Value,
    /// 1-based line in the source.
    pub line: usize,
}

/// The value kinds of TOML and JSON that tribez reads.
#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    /// JSON `null`.
    Null,
    /// A boolean.
    Bool(bool),
    /// A number, as its source text.
    Number(String),
    /// A string.
    String(String),
    /// An array.
    Array(Vec<Node>),
    /// A table / object, in source order (duplicates are rejected by the parsers).
    Table(Vec<(String, Node)>),
}

impl Value {
    /// A word for messages: "a string", "an array", …
    pub fn kind(&self) -> &'static str {
        match self {
            Value::Null => "null",
            Value::Bool(_) => "a boolean",
            Value::Number(_) => "a number",
            Value::String(_) => "a string",
            Value::Array(_) => "an array",
            Value::Table(_) => "a table",
        }
    }
}

/// A parsed document and the file it came from, for error messages.
#[derive(Clone, Debug)]
pub struct Document {
    /// The file name as given.
    pub file: String,
    /// The root table.
    pub root: Node,
}

impl Document {
    /// An error located at `node`, under `key`.
    pub fn error(&self, node: &Node, key: &str, problem: impl Into<Problem>) -> InputError {
        InputError {
            key: (!key.is_empty()).then(|| key.to_string()),
            ..InputError::at(self.file.clone(), Some(node.line), None, problem)
        }
    }

    /// Read and parse a `.toml` or `.json` file (by extension): a regular file of at most
    /// [`super::text::MAX_FILE_BYTES`], UTF-8, with or without a byte-order mark.
    pub fn read(path: &Path) -> Result<Self, InputError> {
        let file = path.display().to_string();
        let ext = path
            .extension()
            .and_then(|e| e.to_str())
            .unwrap_or("")
            .to_ascii_lowercase();
        if !matches!(ext.as_str(), "toml" | "json") {
            return Err(InputError::file(&file, Problem::UnknownFileType));
        }
        let text = read_text(path)?;
        if ext == "toml" {
            Document::parse_toml(&file, &text)
        } else {
            Document::parse_json(&file, &text)
        }
    }

    /// Parse TOML text (a leading byte-order mark is ignored). Linear in the text's length.
    pub fn parse_toml(file: &str, text: &str) -> Result<Self, InputError> {
        Document::parse_toml_capped(file, text, MAX_TOML_VALUES)
    }

    /// [`Document::parse_toml`] with at most `max_values` values (as bounded by
    /// [`toml_values_exceed`]).
    fn parse_toml_capped(file: &str, text: &str, max_values: usize) -> Result<Self, InputError> {
        let text = strip_bom(text);
        if text.trim().is_empty() {
            return Err(InputError::file(file, Problem::EmptyFile));
        }
        if text.len() as u64 > MAX_FILE_BYTES {
            return Err(too_large(file));
        }
        if let Some(at) = toml_values_exceed(text.as_bytes(), max_values) {
            let problem = Problem::TooManyTomlValues { limit: max_values };
            // the line of one offset: counted, not indexed (the index is for a text that parses)
            let line = 1 + memchr::memchr_iter(b'\n', &text.as_bytes()[..at]).count();
            return Err(InputError::at(file, Some(line), None, problem));
        }
        let lines = LineIndex::new(text.as_bytes());
        let doc = toml::de::DeTable::parse(text).map_err(|e| {
            let (line, column) = e.span().map(|s| lines.line_col(s.start)).unzip();
            let msg = e.message().trim().to_string();
            InputError::at(file, line, column, Problem::Toml { message: msg })
        })?;
        let root = Toml { text, lines }.table(doc.get_ref(), 1);
        Ok(Document {
            file: file.into(),
            root,
        })
    }

    /// Parse JSON text (a leading byte-order mark is ignored). Linear in the text's length.
    pub fn parse_json(file: &str, text: &str) -> Result<Self, InputError> {
        Document::parse_json_capped(file, text, MAX_JSON_VALUES)
    }

    /// [`Document::parse_json`] with at most `max_values` values.
    fn parse_json_capped(file: &str, text: &str, max_values: usize) -> Result<Self, InputError> {
        let text = strip_bom(text);
        if text.trim().is_empty() {
            return Err(InputError::file(file, Problem::EmptyFile));
        }
        if text.len() as u64 > MAX_FILE_BYTES {
            return Err(too_large(file));
        }
        let mut p = JsonParser {
            text: text.as_bytes(),
            pos: 0,
            file,
            line: 1,
            line_start: 0,
            values: 0,
            max_values,
        };
        p.skip_ws();
        let root = p.value(0)?;
        p.skip_ws();
        if p.pos != p.text.len() {
            return Err(p.err(JsonSyntax::TrailingText));
        }
        Ok(Document {
            file: file.into(),
            root,
        })
    }
}

/// The most values (numbers, strings, booleans, arrays, tables) a JSON document may hold, counted
/// as they are read: room for the largest points file (1,000,000 points of up to 17 coordinates,
/// 18,000,001 values) and mesh, and a bound of about 2 GB on the tree whatever the file holds
/// (without it, a 256 MiB file of `[1,1,…]` took 9.5 GB before any file kind's own cap could
/// refuse it).
pub const MAX_JSON_VALUES: usize = 20_000_000;

/// The most values a TOML document may hold, bounded before the text is parsed by counting the
/// bytes that can introduce one (every value or table but the root follows a `,`, `=`, `[` or
/// `.` of its own; strings and comments only over-count): twice the count of the largest patch
/// file allowed, and a bound of about 0.8 GB on the memory parsing takes (some 190 bytes a value
/// for the parser's tree and tribez's, so a 256 MiB file of `a = [1,1,…]` would take 25 GB).
/// Larger inputs belong in JSON.
pub const MAX_TOML_VALUES: usize = 4_000_000;

/// The offset of the byte at which `text` holds more than `limit` bytes that can introduce a
/// TOML value (`,` `=` `[` `.`, counting the root as one), if it does.
fn toml_values_exceed(text: &[u8], limit: usize) -> Option<usize> {
    let mut count = 1usize;
    text.iter().position(|&b| {
        count += usize::from(matches!(b, b',' | b'=' | b'[' | b'.'));
        count > limit
    })
}

/// The error of a text longer than a file read whole may be (texts handed to the parsers
/// directly are held to the same limit as files).
fn too_large(file: &str) -> InputError {
    InputError::file(
        file,
        Problem::FileTooLarge {
            limit_mib: MAX_FILE_BYTES >> 20,
        },
    )
}

/// 1-based (line, column) of a byte offset (the column counts bytes). Linear in `offset`: to
/// locate many offsets of one text, build a [`LineIndex`] once.
pub fn line_col(text: &str, offset: usize) -> (usize, usize) {
    LineIndex::new(&text.as_bytes()[..offset.min(text.len())]).line_col(offset.min(text.len()))
}

/// A TOML document's text and its line index, to locate every value in `O(log lines)`.
struct Toml<'a> {
    text: &'a str,
    lines: LineIndex,
}

impl Toml<'_> {
    fn table(&self, table: &toml::de::DeTable<'_>, line: usize) -> Node {
        let entries = table
            .iter()
            .map(|(k, v)| (k.get_ref().to_string(), self.value(v, line)))
            .collect();
        Node {
            value: Value::Table(entries),
            line,
        }
    }

    /// A value's node; `line` stands for a span the parser did not record (none does today).
    fn value(&self, v: &toml::Spanned<toml::de::DeValue<'_>>, line: usize) -> Node {
        use toml::de::DeValue as V;
        let span = v.span();
        let line = if span.is_empty() && span.start == 0 {
            line
        } else {
            self.lines.line(span.start)
        };
        let raw = || self.text.get(span).unwrap_or_default().trim();
        let value = match v.get_ref() {
            V::String(s) => Value::String(s.to_string()),
            V::Integer(_) | V::Float(_) => Value::Number(raw().replace('_', "")),
            V::Boolean(b) => Value::Bool(*b),
            V::Datetime(_) => Value::String(raw().to_string()),
            V::Array(a) => Value::Array(a.iter().map(|x| self.value(x, line)).collect()),
            V::Table(t) => return self.table(t, line),
        };
        Node { value, line }
    }
}

/// The position of the first key that repeats an earlier one (the second occurrence).
fn first_duplicate(entries: &[(String, Node)]) -> Option<usize> {
    let mut seen = std::collections::HashSet::with_capacity(entries.len());
    entries.iter().position(|(k, _)| !seen.insert(k.as_str()))
}

struct JsonParser<'a> {
    text: &'a [u8],
    pos: usize,
    file: &'a str,
    /// The 1-based line of `pos`, and the offset where that line starts (kept as the text is
    /// read: no index of every line is built).
    line: usize,
    line_start: usize,
    /// Values read so far, and their cap ([`MAX_JSON_VALUES`]; smaller under test).
    values: usize,
    max_values: usize,
}

const MAX_DEPTH: usize = 128;

impl JsonParser<'_> {
    fn err(&self, syntax: JsonSyntax) -> InputError {
        let column = self.pos - self.line_start + 1;
        InputError::at(
            self.file,
            Some(self.line),
            Some(column),
            Problem::Json(syntax),
        )
    }

    /// Step over the byte at `pos`, counting a line feed.
    fn advance(&mut self, b: u8) {
        self.pos += 1;
        if b == b'\n' {
            self.line += 1;
            self.line_start = self.pos;
        }
    }

    fn skip_ws(&mut self) {
        while let Some(&b) = self.text.get(self.pos) {
            if !matches!(b, b' ' | b'\t' | b'\n' | b'\r') {
                break;
            }
            self.advance(b);
        }
    }

    fn eat(&mut self, b: u8) -> bool {
        self.skip_ws();
        if self.text.get(self.pos) == Some(&b) {
            self.pos += 1;
            true
        } else {
            false
        }
    }

    fn value(&mut self, depth: usize) -> Result<Node, InputError> {
        if depth > MAX_DEPTH {
            return Err(self.err(JsonSyntax::TooDeep));
        }
        self.skip_ws();
        self.values += 1;
        if self.values > self.max_values {
            let problem = Problem::TooManyJsonValues {
                limit: self.max_values,
            };
            return Err(InputError::at(self.file, Some(self.line), None, problem));
        }
        let line = self.line;
        let value = match self.text.get(self.pos) {
            None => return Err(self.err(JsonSyntax::UnexpectedEnd)),
            Some(b'{') => {
                self.pos += 1;
                let mut entries: Vec<(String, Node)> = Vec::new();
                // Where each key starts (offset, line, line start), to point at a duplicate;
                // duplicates are looked for once the object is read, by hashing borrowed keys
                // (no copy of every key).
                let mut key_starts: Vec<(usize, usize, usize)> = Vec::new();
                if !self.eat(b'}') {
                    loop {
                        self.skip_ws();
                        key_starts.push((self.pos, self.line, self.line_start));
                        let key = self.string()?;
                        if !self.eat(b':') {
                            return Err(self.err(JsonSyntax::Expected("':' after a key")));
                        }
                        let v = self.value(depth + 1)?;
                        entries.push((key, v));
                        if self.eat(b',') {
                            continue;
                        }
                        if self.eat(b'}') {
                            break;
                        }
                        return Err(self.err(JsonSyntax::Expected("',' or '}'")));
                    }
                }
                if let Some(dup) = first_duplicate(&entries) {
                    (self.pos, self.line, self.line_start) = key_starts[dup];
                    let key = entries.swap_remove(dup).0;
                    return Err(self.err(JsonSyntax::DuplicateKey { key }));
                }
                Value::Table(entries)
            }
            Some(b'[') => {
                self.pos += 1;
                let mut items = Vec::new();
                if !self.eat(b']') {
                    loop {
                        items.push(self.value(depth + 1)?);
                        if self.eat(b',') {
                            continue;
                        }
                        if self.eat(b']') {
                            break;
                        }
                        return Err(self.err(JsonSyntax::Expected("',' or ']'")));
                    }
                }
                Value::Array(items)
            }
            Some(b'"') => Value::String(self.string()?),
            Some(b't') if self.text[self.pos..].starts_with(b"true") => {
                self.pos += 4;
                Value::Bool(true)
            }
            Some(b'f') if self.text[self.pos..].starts_with(b"false") => {
                self.pos += 5;
                Value::Bool(false)
            }
            Some(b'n') if self.text[self.pos..].starts_with(b"null") => {
                self.pos += 4;
                Value::Null
            }
            Some(b'-' | b'0'..=b'9') => {
                let start = self.pos;
                while self.pos < self.text.len()
                    && matches!(
                        self.text[self.pos],
                        b'-' | b'+' | b'.' | b'e' | b'E' | b'0'..=b'9'
                    )
                {
                    self.pos += 1;
                }
                let s = std::str::from_utf8(&self.text[start..self.pos])
                    .unwrap_or("")
                    .to_string();
                Value::Number(s)
            }
            Some(_) => return Err(self.err(JsonSyntax::Expected("a value"))),
        };
        Ok(Node { value, line })
    }

    fn string(&mut self) -> Result<String, InputError> {
        if self.text.get(self.pos) != Some(&b'"') {
            return Err(self.err(JsonSyntax::Expected("a string")));
        }
        self.pos += 1;
        let mut out = Vec::new();
        loop {
            match self.text.get(self.pos) {
                None => return Err(self.err(JsonSyntax::UnterminatedString)),
                Some(b'"') => {
                    self.pos += 1;
                    break;
                }
                Some(b'\\') => {
                    let esc = self.text.get(self.pos + 1).copied();
                    self.pos += 2;
                    match esc {
                        Some(b'"') => out.push(b'"'),
                        Some(b'\\') => out.push(b'\\'),
                        Some(b'/') => out.push(b'/'),
                        Some(b'b') => out.push(8),
                        Some(b'f') => out.push(12),
                        Some(b'n') => out.push(b'\n'),
                        Some(b'r') => out.push(b'\r'),
                        Some(b't') => out.push(b'\t'),
                        Some(b'u') => {
                            let hex = self
                                .text
                                .get(self.pos..self.pos + 4)
                                .and_then(|h| std::str::from_utf8(h).ok());
                            let code = hex
                                .and_then(|h| u32::from_str_radix(h, 16).ok())
                                .ok_or_else(|| self.err(JsonSyntax::BadUnicodeEscape))?;
                            self.pos += 4;
                            let c = char::from_u32(code).unwrap_or('\u{fffd}');
                            let mut buf = [0u8; 4];
                            out.extend_from_slice(c.encode_utf8(&mut buf).as_bytes());
                        }
                        _ => return Err(self.err(JsonSyntax::BadEscape)),
                    }
                }
                Some(&b) => {
                    out.push(b);
                    self.advance(b);
                }
            }
        }
        String::from_utf8(out).map_err(|_| self.err(JsonSyntax::StringNotUtf8))
    }
}

/// Typed access to a document's nodes, with errors that name the file, line and key.
impl Document {
    /// The root as a table.
    pub fn root_table(&self) -> Result<&[(String, Node)], InputError> {
        self.table(&self.root, "")
    }

    /// `node` as a table.
    pub fn table<'a>(&self, node: &'a Node, key: &str) -> Result<&'a [(String, Node)], InputError> {
        match &node.value {
            Value::Table(t) => Ok(t),
            other => Err(self.error(
                node,
                key,
                Problem::WrongType {
                    expected: "a table",
                    found: other.kind(),
                },
            )),
        }
    }

    /// `node` as an array.
    pub fn array<'a>(&self, node: &'a Node, key: &str) -> Result<&'a [Node], InputError> {
        match &node.value {
            Value::Array(a) => Ok(a),
            other => Err(self.error(
                node,
                key,
                Problem::WrongType {
                    expected: "an array",
                    found: other.kind(),
                },
            )),
        }
    }

    /// `node` as a string.
    pub fn string<'a>(&self, node: &'a Node, key: &str) -> Result<&'a str, InputError> {
        match &node.value {
            Value::String(s) => Ok(s),
            other => Err(self.error(
                node,
                key,
                Problem::WrongType {
                    expected: "a string",
                    found: other.kind(),
                },
            )),
        }
    }

    /// `node` as a non-negative integer.
    pub fn usize(&self, node: &Node, key: &str) -> Result<usize, InputError> {
        let text = match &node.value {
            Value::Number(t) | Value::String(t) => t.trim(),
            other => {
                return Err(self.error(
                    node,
                    key,
                    Problem::WrongType {
                        expected: "a non-negative integer",
                        found: other.kind(),
                    },
                ));
            }
        };
        text.parse::<usize>()
            .map_err(|_| self.error(node, key, Problem::NotAnInteger { text: text.into() }))
    }

    /// `node` as an exact rational: a number (its text) or a string in the number syntax.
    pub fn rational(&self, node: &Node, key: &str) -> Result<BigRational, InputError> {
        self.rational_keyed(node, || key.to_string())
    }

    /// [`Self::rational`] with the key spelled out by `key()` only for an error message (the
    /// happy path of a long array allocates no key).
    fn rational_keyed(
        &self,
        node: &Node,
        key: impl FnOnce() -> String,
    ) -> Result<BigRational, InputError> {
        let text = match &node.value {
            Value::Number(t) | Value::String(t) => t,
            other => {
                return Err(self.error(
                    node,
                    &key(),
                    Problem::WrongType {
                        expected: "a number",
                        found: other.kind(),
                    },
                ));
            }
        };
        parse_rational(text).map_err(|e| self.error(node, &key(), e))
    }

    /// `node` as an array of rationals.
    pub fn rationals(&self, node: &Node, key: &str) -> Result<Vec<BigRational>, InputError> {
        self.array(node, key)?
            .iter()
            .enumerate()
            .map(|(i, x)| self.rational_keyed(x, || format!("{key}[{i}]")))
            .collect()
    }

    /// Look up `name` in a table; the keys it does not know are reported by the caller.
    pub fn get<'a>(table: &'a [(String, Node)], name: &str) -> Option<&'a Node> {
        table.iter().find(|(k, _)| k == name).map(|(_, v)| v)
    }

    /// Reject keys outside `known` (a typo should not be silently ignored).
    pub fn check_keys(
        &self,
        node: &Node,
        table: &[(String, Node)],
        known: &[&str],
        prefix: &str,
    ) -> Result<(), InputError> {
        for (k, v) in table {
            if !known.contains(&k.as_str()) {
                let key = if prefix.is_empty() {
                    k.clone()
                } else {
                    format!("{prefix}.{k}")
                };
                let _ = node;
                return Err(self.error(
                    v,
                    &key,
                    Problem::UnknownKey {
                        known: known.iter().map(|k| k.to_string()).collect(),
                    },
                ));
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn json_keeps_number_text_and_lines() {
        let d =
            Document::parse_json("x.json", "{\n \"a\": 0.1,\n \"b\": [1e-3, \"4/9\"]\n}").unwrap();
        let t = d.root_table().unwrap();
        assert_eq!(
            t[0].1,
            Node {
                value: Value::Number("0.1".into()),
                line: 2
            }
        );
        assert_eq!(d.rational(&t[0].1, "a").unwrap().to_string(), "1/10");
        assert_eq!(t[1].1.line, 3);
    }

    #[test]
    fn json_values_are_capped_as_they_are_read() {
        // 7 values: the table; the array and its two numbers; the string; the array and `true`
        let text = "{\"a\": [1, 2],\n \"b\": \"x\",\n \"c\": [true]}";
        assert!(Document::parse_json_capped("x.json", text, 7).is_ok());
        let e = Document::parse_json_capped("x.json", text, 6).unwrap_err();
        assert_eq!(e.line, Some(3), "the seventh value, `true`, is on line 3");
        assert_eq!(*e.problem, Problem::TooManyJsonValues { limit: 6 });
        assert_eq!(
            e.to_string(),
            "x.json:3: more than 6 values (the limit of a JSON file)"
        );
        // the largest points file allowed fits: 1,000,000 points of 17 coordinates, the root
        // array and one array per point
        let largest_points = 1 + crate::io::points::MAX_POINTS * (1 + 17);
        assert!(largest_points <= MAX_JSON_VALUES);
    }

    #[test]
    fn toml_values_are_bounded_before_parsing() {
        // Every value but the root follows a ',', '=', '[' or '.': a file at the bound parses,
        // one more is refused on the line where the bound is passed (before parsing: the
        // second text is not valid TOML)
        let at_bound = "a = [1, 2, 3]\nb = 4\n"; // the root, '=', '[', ',', ',', '='
        assert!(Document::parse_toml_capped("x.toml", at_bound, 6).is_ok());
        assert!(Document::parse_toml_capped("x.toml", at_bound, 5).is_err());
        let e = Document::parse_toml_capped("x.toml", "a = [1, 2]\nb = [3,,,\n", 6).unwrap_err();
        assert_eq!(e.line, Some(2));
        assert_eq!(
            e.to_string(),
            "x.toml:2: more than 6 values (the limit of a TOML file, counting every ',', '=', \
             '[' and '.' as one; write a larger input as JSON)"
        );
        let over = format!(
            "a = 1\nb = [{}]\n",
            vec!["1"; MAX_TOML_VALUES - 2].join(",")
        );
        let e = Document::parse_toml("x.toml", &over).unwrap_err();
        assert_eq!(e.line, Some(2));
        assert_eq!(
            *e.problem,
            Problem::TooManyTomlValues {
                limit: MAX_TOML_VALUES
            }
        );
        // dotted keys and headers make tables: each is introduced by a '.' or a '['
        let text = "a.b.c = 1\n[d.e]\nf = [[1], {g = 2}]\n[[h]]\n";
        let doc = Document::parse_toml("x.toml", text).unwrap();
        assert!(count_nodes(&doc.root) <= 1 + text.matches([',', '=', '[', '.']).count());
        // the largest patch file allowed (246,905 control points of a 3-simplex, as the `read`
        // benchmark writes it) fits twice over
        let line = "\"112,0,0,0\" = [\"785/3\", \"-0.0\", \"112e-3\"]\n";
        let per_point = line.matches([',', '=', '[', '.']).count();
        assert_eq!(per_point, 8);
        assert!(2 * 246_905 * per_point < MAX_TOML_VALUES);
    }

    fn count_nodes(node: &Node) -> usize {
        1 + match &node.value {
            Value::Array(items) => items.iter().map(count_nodes).sum(),
            Value::Table(entries) => entries.iter().map(|(_, n)| count_nodes(n)).sum(),
            _ => 0,
        }
    }

    #[test]
    fn json_rejects_duplicate_keys_with_position() {
        let e = Document::parse_json("x.json", "{\"a\": 1,\n \"a\": 2}").unwrap_err();
        assert_eq!(e.line, Some(2));
        assert_eq!(
            *e.problem,
            Problem::Json(JsonSyntax::DuplicateKey { key: "a".into() })
        );
        assert!(e.to_string().contains("duplicate key \"a\""), "{e}");
    }

    #[test]
    fn toml_keeps_number_text() {
        let d = Document::parse_toml("x.toml", "a = 0.1\n\n[t]\nb = [1_000, -1.5e-3]\n").unwrap();
        let t = d.root_table().unwrap();
        assert_eq!(d.rational(&t[0].1, "a").unwrap().to_string(), "1/10");
        let inner = d.table(&t[1].1, "t").unwrap();
        assert_eq!(inner[0].1.line, 4);
        let xs = d.rationals(&inner[0].1, "t.b").unwrap();
        assert_eq!(xs[0].to_string(), "1000");
        assert_eq!(xs[1].to_string(), "-3/2000");
    }

    #[test]
    fn empty_and_garbage_are_errors() {
        assert!(*Document::parse_json("x.json", "  ").unwrap_err().problem == Problem::EmptyFile);
        assert_eq!(
            Document::parse_json("x.json", "{\"a\": }")
                .unwrap_err()
                .line,
            Some(1)
        );
        let e = Document::parse_toml("x.toml", "a = 1\nb = = 2\n").unwrap_err();
        assert_eq!(e.line, Some(2));
    }
}
