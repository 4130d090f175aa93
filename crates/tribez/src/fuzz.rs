//! Entry points of the fuzz targets (`fuzz/` at the repository root, run with cargo-fuzz) and
//! of the test that replays their regression corpus (`fuzz/regressions/<target>/`) on stable
//! Rust. Each takes arbitrary bytes, feeds them to one parser and discards the outcome: an
//! error is the right answer to bad input; a panic, an abort, a hang or an unbounded
//! allocation is the bug. Not a stable API.

use std::path::PathBuf;

use crate::io::patch_file::{any_patch_from_document, any_patch_to_json, any_patch_to_toml};
use crate::io::points::{parse_csv_points, points_from_document};
use crate::io::tree::Document;

/// Every target's name, as in `fuzz/Cargo.toml` and `fuzz/regressions/`.
pub const TARGETS: &[&str] = &[
    "number",
    "polynomial",
    "patch_toml",
    "patch_json",
    "claims",
    "points",
    "batch_csv",
    "batch_jsonl",
    "batch_json_array",
    "mesh",
    "batch_inverse",
    "fit_data",
    "certify",
    "hunt_answer",
];

/// Run target `name` on `data`; false if there is no such target.
pub fn run(name: &str, data: &[u8]) -> bool {
    match name {
        "number" => number(data),
        "polynomial" => polynomial(data),
        "patch_toml" => patch_toml(data),
        "patch_json" => patch_json(data),
        "claims" => claims(data),
        "points" => points(data),
        "batch_csv" => batch_csv(data),
        "batch_jsonl" => batch_jsonl(data),
        "batch_json_array" => batch_json_array(data),
        "mesh" => mesh(data),
        "batch_inverse" => batch_inverse(data),
        "fit_data" => fit_data(data),
        "certify" => certify(data),
        "hunt_answer" => hunt_answer(data),
        _ => return false,
    }
    true
}

fn text(data: &[u8]) -> Option<&str> {
    std::str::from_utf8(data).ok()
}

/// `parse_rational` on the text.
pub fn number(data: &[u8]) {
    if let Some(t) = text(data) {
        let _ = crate::number::parse_rational(t);
    }
}

/// The work limit of polynomial text in the fuzz target: 2^22 word operations, 256 times below
/// the library's [`crate::symbolic::MAX_WORK`]. The parser's code paths are the same; each input
/// stops after milliseconds instead of up to a second, so a run reaches millions of inputs (the
/// full limit is exercised by the unit tests and by the replayed regressions).
pub const FUZZ_WORK: u64 = 1 << 22;

/// `Polynomial::parse` (with the work limit [`FUZZ_WORK`]): the first byte chooses the variable
/// names, the rest is the text.
pub fn polynomial(data: &[u8]) {
    const NAMES: [&[&str]; 4] = [
        &["u", "v", "w"],
        &["x", "y", "z"],
        &["t"],
        &["u1", "u", "v"],
    ];
    let Some((&first, rest)) = data.split_first() else {
        return;
    };
    if let Some(t) = text(rest) {
        let names = NAMES[usize::from(first) % NAMES.len()];
        let _ = crate::symbolic::Polynomial::parse_with_work_limit(t, names, FUZZ_WORK);
    }
}

/// A patch read from a document, then written back and read again: the same patch.
fn patch(doc: Result<Document, crate::io::InputError>) {
    let Ok(doc) = doc else { return };
    let Ok(p) = any_patch_from_document(&doc, &doc.root, "") else {
        return;
    };
    let toml = any_patch_to_toml(&p);
    let again = Document::parse_toml("again.toml", &toml)
        .and_then(|d| any_patch_from_document(&d, &d.root, ""));
    assert_eq!(again.as_ref(), Ok(&p), "TOML round trip of\n{toml}");
    let json = any_patch_to_json(&p).to_string();
    let again = Document::parse_json("again.json", &json)
        .and_then(|d| any_patch_from_document(&d, &d.root, ""));
    assert_eq!(again.as_ref(), Ok(&p), "JSON round trip of\n{json}");
}

/// A TOML patch file (read, then round-tripped through TOML and JSON).
pub fn patch_toml(data: &[u8]) {
    if let Some(t) = text(data) {
        patch(Document::parse_toml("fuzz.toml", t));
    }
}

/// A JSON patch file (read, then round-tripped through TOML and JSON).
pub fn patch_json(data: &[u8]) {
    if let Some(t) = text(data) {
        patch(Document::parse_json("fuzz.json", t));
    }
}

/// A claim file, read and judged: the first byte chooses TOML (even) or JSON (odd). The text is
/// written to a file in a directory of this process's own (claim files name patch files
/// relative to themselves).
pub fn claims(data: &[u8]) {
    let Some((&first, rest)) = data.split_first() else {
        return;
    };
    let dir = std::env::temp_dir().join(format!("tribez-fuzz-claims-{}", std::process::id()));
    if std::fs::create_dir_all(&dir).is_err() {
        return;
    }
    let path: PathBuf = dir.join(if first % 2 == 0 {
        "fuzz.claims.toml"
    } else {
        "fuzz.claims.json"
    });
    if std::fs::write(&path, rest).is_err() {
        return;
    }
    if let Ok(file) = crate::claims::ClaimFile::read(&path) {
        let _ = file.judge_all();
    }
}

/// A points file: the first byte chooses CSV (even) or JSON (odd) and the width (1 to 4).
pub fn points(data: &[u8]) {
    let Some((&first, rest)) = data.split_first() else {
        return;
    };
    let width = usize::from(first >> 1) % 4 + 1;
    let Some(t) = text(rest) else { return };
    if first % 2 == 0 {
        let _ = parse_csv_points(t, width, "fuzz.csv");
    } else if let Ok(doc) = Document::parse_json("fuzz.json", t) {
        let _ = points_from_document(&doc, width);
    }
}

/// Rows of a CSV results file (`check --results`): the first byte chooses the width, the
/// dimension and the precision.
pub fn batch_csv(data: &[u8]) {
    crate::batch::fuzz_rows(crate::batch::Format::Csv, data);
}

/// Rows of a JSON-lines results file (as [`batch_csv`]).
pub fn batch_jsonl(data: &[u8]) {
    crate::batch::fuzz_rows(crate::batch::Format::JsonLines, data);
}

/// Rows of a results file that is one JSON array of rows (as [`batch_csv`]).
pub fn batch_json_array(data: &[u8]) {
    crate::batch::fuzz_rows(crate::batch::Format::JsonArray, data);
}

/// A mesh file: the first byte chooses TOML (even) or JSON (odd); read, checked, round-tripped
/// and looked up ([`crate::mesh::fuzz_mesh`]).
pub fn mesh(data: &[u8]) {
    crate::mesh::fuzz_mesh(data);
}

/// Rows of an inverse batch (`check --locate-results`, `--ray-results`): the first byte chooses
/// the kind, the format and the precision ([`crate::batch::inverse`]).
pub fn batch_inverse(data: &[u8]) {
    crate::batch::inverse::fuzz_inverse_rows(data);
}

/// A data file of a fit (`tribez fit DATA`): the first byte chooses the degree; parsed, and a
/// small file fitted and its residuals checked ([`crate::fit::fuzz_fit_data`]).
pub fn fit_data(data: &[u8]) {
    crate::fit::fuzz_fit_data(data);
}

/// The caps of the `certify` target, so that one input runs in milliseconds: the patch of
/// degree at most [`CERTIFY_MAX_DEGREE`], written back as TOML in at most
/// [`CERTIFY_MAX_TEXT`] bytes (this bounds the control points and the size of their numbers),
/// at most [`CERTIFY_MAX_POINTS`] points.
pub const CERTIFY_MAX_DEGREE: usize = 12;
/// See [`CERTIFY_MAX_DEGREE`].
pub const CERTIFY_MAX_TEXT: usize = 16 << 10;
/// See [`CERTIFY_MAX_DEGREE`].
pub const CERTIFY_MAX_POINTS: usize = 24;

/// A certification run ([`crate::certify()`]) of a patch file with options. The first byte
/// chooses the precision (`b % 3`: both, f64, f32), the algorithm (`b / 3 % 3`: all, de
/// Casteljau, Bernstein), the patch format (`b / 9 % 2`: TOML, JSON) and the points
/// (`b / 18 % 2`: random or given); the second byte the number of random points (1 to
/// [`CERTIFY_MAX_POINTS`]), the next eight the seed (little-endian). The rest is text: the
/// patch file, then, for given points, a line `%%` and the points as CSV. The report is
/// rendered as text; its worst errors and every row's per-point results are checked for the
/// sizes the report promises.
pub fn certify(data: &[u8]) {
    use crate::certification::{CertifyOptions, CertifyPoints};
    if data.len() < 10 {
        return;
    }
    let (head, rest) = data.split_at(10);
    let b = head[0];
    let precision = match b % 3 {
        0 => None,
        1 => Some(crate::float::Precision::F64),
        _ => Some(crate::float::Precision::F32),
    };
    let algorithm = match b / 3 % 3 {
        0 => None,
        1 => Some(crate::exact::Algorithm::Casteljau),
        _ => Some(crate::exact::Algorithm::Bernstein),
    };
    let json = b / 9 % 2 == 1;
    let given = b / 18 % 2 == 1;
    let count = usize::from(head[1]) % CERTIFY_MAX_POINTS + 1;
    let mut seed = [0u8; 8];
    seed.copy_from_slice(&head[2..10]);
    let seed = u64::from_le_bytes(seed);
    let Some(t) = text(rest) else { return };
    let (patch_text, points_text) = match t.split_once("\n%%\n") {
        Some((p, q)) if given => (p, Some(q)),
        _ => (t, None),
    };
    let doc = if json {
        Document::parse_json("fuzz.json", patch_text)
    } else {
        Document::parse_toml("fuzz.toml", patch_text)
    };
    let Ok(any) = doc.and_then(|d| any_patch_from_document(&d, &d.root, "")) else {
        return;
    };
    if any_patch_to_toml(&any).len() > CERTIFY_MAX_TEXT {
        return;
    }
    let patch = crate::patch_type::Patch::from(any);
    let shape = patch.shape();
    if shape.degree > CERTIFY_MAX_DEGREE {
        return;
    }
    let points = match points_text {
        Some(q) => {
            let Ok(points) = parse_csv_points(q, shape.input.len(), "fuzz.csv") else {
                return;
            };
            if points.len() > CERTIFY_MAX_POINTS {
                return;
            }
            CertifyPoints::Given {
                points,
                source: "fuzz.csv".into(),
            }
        }
        None => CertifyPoints::Random { count, seed },
    };
    let options = CertifyOptions {
        points,
        precision,
        algorithm,
        label: "fuzz.toml".into(),
    };
    let Ok(report) = crate::certification::certify(&patch, &options) else {
        return;
    };
    let _ = report.text();
    assert_eq!(report.worst_errors().len(), report.rows.len());
    for row in &report.rows {
        assert_eq!(row.per_point.len(), report.inputs.len());
        assert!(row.coordinates <= report.inputs.len() * shape.dimension);
    }
}

/// One answer line of a hunted program ([`crate::batch::parse_claimed_line`] and
/// [`crate::batch::read_claimed_line`]): the first byte chooses the number of coordinates (1 to
/// 4) and the precision (f64 or f32), the rest is the line. An accepted line has exactly that
/// many numbers; where the fast path of `read_claimed_line` reads the line, its numbers are the
/// general reader's bit for bit, and where it refuses, it leaves its buffer as it was.
pub fn hunt_answer(data: &[u8]) {
    let Some((&head, rest)) = data.split_first() else {
        return;
    };
    let Some(line) = text(rest) else {
        return;
    };
    let dim = usize::from(head % 4) + 1;
    let precision = if head & 4 == 0 {
        crate::float::Precision::F64
    } else {
        crate::float::Precision::F32
    };
    let library = crate::batch::parse_claimed_line(line, dim, precision);
    if let Ok(values) = &library {
        assert_eq!(values.len(), dim);
    }
    // the fast path of `read_claimed_line` reads what the library reads, bit for bit
    let mut fast = vec![7.0];
    if crate::batch::answer_fast_path(line, precision, &mut fast, dim) {
        let values = library.expect("a line the fast path reads is a valid line");
        let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
        assert_eq!(bits(&fast[1..]), bits(&values), "{line:?}");
    } else {
        assert_eq!(fast, [7.0], "a refused line leaves the buffer unchanged");
    }
    // and the combined reader gives the library's numbers or its error
    let mut out = Vec::new();
    match crate::batch::read_claimed_line(line, dim, precision, &mut out) {
        Ok(()) => assert_eq!(out.len(), dim),
        Err(e) => {
            assert!(out.is_empty());
            assert!(!e.contains('\n'), "one line: {e}");
        }
    }
}
