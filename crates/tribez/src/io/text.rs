//! Text files read whole, safely: a size cap, regular files only, a UTF-8 byte-order mark
//! dropped, invalid UTF-8 located by line; and a line index that turns byte offsets into
//! (line, column) in logarithmic time, so that locating every value of a file is linear overall.

use std::io::Read;
use std::path::Path;

use super::{InputError, Problem};

/// The largest file read whole (patch files, claim files, points files, baselines): 256 MiB.
///
/// The largest patch file allowed ([`super::patch_file::MAX_CONTROL_POINTS`] control points)
/// takes a few megabytes when its numbers are short, and stays far below this limit with numbers
/// of a thousand digits each. Results files (`check --results`) are streamed instead and have no
/// size limit; only one row's length is capped there.
pub const MAX_FILE_BYTES: u64 = 256 << 20;

/// The UTF-8 byte-order mark, accepted (and ignored) at the start of every text format.
pub const BOM: &str = "\u{feff}";

/// `text` without a leading UTF-8 byte-order mark.
pub fn strip_bom(text: &str) -> &str {
    text.strip_prefix(BOM).unwrap_or(text)
}

/// Check that `path` names a regular file (following symbolic links) before it is opened:
/// opening a FIFO blocks, and a device such as `/dev/zero` never ends.
pub fn check_regular(path: &Path, file: &str) -> Result<std::fs::Metadata, InputError> {
    let meta = std::fs::metadata(path).map_err(|e| {
        InputError::file(
            file,
            Problem::CannotRead {
                reason: plain_io_error(&e),
            },
        )
    })?;
    if meta.is_file() {
        Ok(meta)
    } else {
        Err(InputError::file(
            file,
            Problem::NotRegularFile {
                kind: not_regular_kind(&meta),
            },
        ))
    }
}

/// What a path that is not a regular file is, for messages: "a directory, not a regular file",
/// "a FIFO (named pipe), not a regular file", "a device, not a regular file", …
pub fn not_regular(meta: &std::fs::Metadata) -> String {
    Problem::NotRegularFile {
        kind: not_regular_kind(meta),
    }
    .to_string()
}

/// What a path that is not a regular file is: `"a directory"`, `"a FIFO (named pipe)"`,
/// `"a device"`, `"a socket"`; `None` for anything else.
pub fn not_regular_kind(meta: &std::fs::Metadata) -> Option<&'static str> {
    let ft = meta.file_type();
    let mut kind = if ft.is_dir() { "a directory" } else { "" };
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if ft.is_fifo() {
            kind = "a FIFO (named pipe)";
        } else if ft.is_char_device() || ft.is_block_device() {
            kind = "a device";
        } else if ft.is_socket() {
            kind = "a socket";
        }
    }
    (!kind.is_empty()).then_some(kind)
}

/// An I/O error without the "(os error N)" suffix.
pub fn plain_io_error(e: &std::io::Error) -> String {
    let s = e.to_string();
    match s.find(" (os error") {
        Some(i) => s[..i].to_string(),
        None => s,
    }
}

/// Read a whole text file: a regular file of at most [`MAX_FILE_BYTES`], valid UTF-8 (the error
/// names the line of the first invalid byte); a leading byte-order mark is removed.
pub fn read_text(path: &Path) -> Result<String, InputError> {
    let file = path.display().to_string();
    let meta = check_regular(path, &file)?;
    let too_big = || {
        InputError::file(
            &file,
            Problem::FileTooLarge {
                limit_mib: MAX_FILE_BYTES >> 20,
            },
        )
    };
    if meta.len() > MAX_FILE_BYTES {
        return Err(too_big());
    }
    let f = std::fs::File::open(path).map_err(|e| {
        InputError::file(
            &file,
            Problem::CannotRead {
                reason: plain_io_error(&e),
            },
        )
    })?;
    let mut bytes = Vec::with_capacity(usize::try_from(meta.len()).unwrap_or(0));
    f.take(MAX_FILE_BYTES + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| {
            InputError::file(
                &file,
                Problem::CannotRead {
                    reason: plain_io_error(&e),
                },
            )
        })?;
    if bytes.len() as u64 > MAX_FILE_BYTES {
        return Err(too_big());
    }
    text_from_bytes(bytes, &file)
}

/// Bytes to text: valid UTF-8 (else an error naming the line and column of the first invalid
/// byte), without a leading byte-order mark.
pub fn text_from_bytes(bytes: Vec<u8>, file: &str) -> Result<String, InputError> {
    let mut text = match String::from_utf8(bytes) {
        Ok(t) => t,
        Err(e) => {
            let bytes = e.as_bytes();
            let at = e.utf8_error().valid_up_to();
            return Err(not_utf8(file, bytes, at));
        }
    };
    if text.starts_with(BOM) {
        text.drain(..BOM.len());
    }
    Ok(text)
}

/// The error for invalid UTF-8 at byte `at` of `bytes` (everything before `at` is valid).
pub fn not_utf8(file: &str, bytes: &[u8], at: usize) -> InputError {
    let before = &bytes[..at];
    let line = before.iter().filter(|&&b| b == b'\n').count() + 1;
    let line_start = before
        .iter()
        .rposition(|&b| b == b'\n')
        .map_or(0, |i| i + 1);
    // the prefix is valid UTF-8, so the column counts characters
    let column = std::str::from_utf8(&before[line_start..])
        .map_or(at - line_start, |s| s.chars().count())
        + 1;
    InputError::at(
        file,
        Some(line),
        Some(column),
        Problem::NotUtf8 {
            byte: bytes.get(at).copied().unwrap_or(0),
        },
    )
}

/// The start of every line of a text, to locate byte offsets in `O(log lines)`.
#[derive(Clone, Debug)]
pub struct LineIndex {
    /// Byte offset of the start of each line; `starts[0] == 0`. Offsets are `u32` (texts read
    /// whole are at most [`MAX_FILE_BYTES`]), so that a text of line feeds only takes four bytes
    /// of index per byte, not eight.
    starts: Vec<u32>,
}

impl LineIndex {
    /// Index the lines of `text` (one pass). Lines that start beyond `u32::MAX` bytes, which a
    /// text of at most [`MAX_FILE_BYTES`] never has, are not indexed (offsets there read as the
    /// last line indexed).
    pub fn new(text: &[u8]) -> Self {
        let mut starts = vec![0];
        starts.extend(
            text.iter()
                .enumerate()
                .filter(|&(_, &b)| b == b'\n')
                .map_while(|(i, _)| u32::try_from(i + 1).ok()),
        );
        LineIndex { starts }
    }

    /// The 1-based line of byte `offset`.
    pub fn line(&self, offset: usize) -> usize {
        // the number of line starts at or before `offset`
        self.starts.partition_point(|&s| s as usize <= offset)
    }

    /// The 1-based (line, column) of byte `offset` of `text` (the text indexed); the column
    /// counts bytes from the line's start.
    pub fn line_col(&self, offset: usize) -> (usize, usize) {
        let line = self.line(offset);
        (line, offset - self.starts[line - 1] as usize + 1)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn line_index_agrees_with_counting_newlines() {
        let text = "ab\n\ncd\nefg\n";
        let index = LineIndex::new(text.as_bytes());
        for offset in 0..=text.len() {
            let before = &text[..offset];
            let line = before.matches('\n').count() + 1;
            let col = offset - before.rfind('\n').map_or(0, |i| i + 1) + 1;
            assert_eq!(index.line_col(offset), (line, col), "offset {offset}");
        }
    }

    #[test]
    fn invalid_utf8_names_the_line_and_column() {
        let e = text_from_bytes(b"a = 1\nb = \"\xc3\xa9\xff\"\n".to_vec(), "f.toml").unwrap_err();
        assert_eq!((e.line, e.column), (Some(2), Some(7)));
        assert!(*e.problem == Problem::NotUtf8 { byte: 0xff }, "{e}");
    }

    #[test]
    fn a_byte_order_mark_is_dropped() {
        let t = text_from_bytes(b"\xef\xbb\xbfdegree = 1".to_vec(), "f.toml").unwrap();
        assert_eq!(t, "degree = 1");
    }
}
