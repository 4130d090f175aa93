//! `tribez check --patch PATCH --results FILE`: judge a large batch of evaluation results from
//! another implementation, streamed in chunks (bounded memory), judged in parallel, reported in
//! input order.
//!
//! Each row: the barycentric coordinates (or `x, y, …` with `--cartesian`), then the claimed
//! coordinates of the point. CSV (`#` starts a comment line), JSON lines (`.jsonl`, `.ndjson`,
//! `.json`: one array per line; numbers or strings), or one JSON array of such rows (a `.json`
//! file starting with `[` then `[`, rows spread over any number of lines; see `parse`). With
//! `--precision`, each number denotes the float
//! nearest its text (hex floats are exact); the claimed value is judged against the exact value
//! at the inputs as the code saw them (those floats; homogeneous form, they need not sum to 1),
//! and the error at the intended inputs (the exact text) is reported for failures and for the
//! worst row. Without a precision numbers are exact and every row is computed exactly.
//!
//! Clear rows are decided by the float filter ([`tribez::certify::filter`]); only undecided ones
//! fall back to exact big-integer evaluation, and the report counts them.
//!
//! This file drives a run (streaming chunks, judging them on all cores, assembling the report in
//! input order); `parse` reads rows, `judge` judges one row (filter, then exact), `report`
//! renders the report (text, JSON, JUnit).

use std::io::{BufReader, IsTerminal, Write};
use std::path::Path;

use rayon::prelude::*;

mod judge;
mod parse;
mod report;

pub use report::{BatchReport, FailedRow};

use super::check::Args;
use super::{CliError, Outcome};
use crate::report::{Exporter, UlpHistogram};
use judge::{Prepared, RowOutcome, RowScratch};
use parse::{Chunk, Format, Num, RowReader, parse_row, texts_of};
use tribez::exact::Algorithm;
use tribez::io::InputError;
use tribez::io::patch_file::read_patch;

/// Rows judged per chunk (the memory bound: one chunk of lines is held at a time).
pub const CHUNK: usize = 1 << 16;
/// Failures listed in full in a report (the rest are counted).
pub const MAX_LISTED: usize = 100;
/// At most this many rows tied (within their enclosures) for the largest error are kept to be
/// settled exactly; past it, later ties are dropped (any of them would do).
const MAX_CANDIDATES: usize = 256;

/// The algorithm a `bound` tolerance refers to.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum AlgorithmChoice {
    /// de Casteljau (bound γ_{(m+1)n} Σ|c_i|B_i(|λ|)).
    Casteljau,
    /// The direct Bernstein form (bound γ_{N+n+m+2} Σ|c_i|B_i(|λ|)).
    Bernstein,
}

impl AlgorithmChoice {
    /// The corresponding algorithm.
    pub fn algorithm(self) -> Algorithm {
        match self {
            AlgorithmChoice::Casteljau => Algorithm::Casteljau,
            AlgorithmChoice::Bernstein => Algorithm::Bernstein,
        }
    }
}

/// Run the batch mode of `tribez check`.
pub fn run(args: &Args) -> Result<Outcome, CliError> {
    let patch_path = args
        .patch
        .as_ref()
        .expect("clap requires --patch with --results");
    let results = args.results.as_ref().expect("checked by the caller");
    let patch = read_patch(patch_path)?;
    let prepared = Prepared::new(args, patch)?;
    let report = check_file(&prepared, results, &patch_path.display().to_string())?;
    let success = report.failed == 0;
    if let Some(path) = &args.junit {
        super::write_atomically(path, report.junit().as_bytes())?;
    }
    let worst = report.worst_errors(prepared.algorithm);
    if let Some(path) = &args.record_baseline {
        super::baseline::record(path, &worst)?;
    }
    let mut regressions = Vec::new();
    if let Some(path) = &args.baseline {
        regressions = super::baseline::compare(path, &worst)?;
    }
    let mut outcome =
        Outcome::rendered(&report, args.out.format, success && regressions.is_empty())?;
    for r in regressions {
        outcome.output += &format!("baseline regression: {r}\n");
    }
    Ok(outcome)
}

fn check_file(p: &Prepared, path: &Path, patch_name: &str) -> Result<BatchReport, CliError> {
    let file = path.display().to_string();
    let format = Format::of(path, &file)?;
    let reader = std::fs::File::open(path)
        .map_err(|e| InputError::file(&file, format!("cannot read: {e}")))?;
    let mut reader = RowReader::new(BufReader::with_capacity(1 << 20, reader), format, &file);
    let (width, dim) = (p.width(), p.patch.net.dim());
    let progress = std::io::stderr().is_terminal();
    let mut report = BatchReport {
        file: file.clone(),
        patch: patch_name.into(),
        tolerance: p.tolerance.clone(),
        precision: p.precision,
        rows: 0,
        passed: 0,
        failed: 0,
        fell_back: 0,
        histogram: UlpHistogram::default(),
        histogram_upper_bounds: p.filter.is_some(),
        histogram_exact: 0,
        worst: None,
        failures: Vec::new(),
    };
    // The worst row: the largest lower bound seen (`floor`) and every row whose upper bound
    // reaches it (the bounds are tight after `Prepared::settle_ulps`, so only near-ties stay);
    // settled exactly at the end.
    let mut floor = 0f64;
    // (upper bound, line, inputs, claimed, the row's text and where it starts)
    type Candidate = (f64, usize, Vec<Num>, Vec<Num>, String, usize);
    let mut candidates: Vec<Candidate> = Vec::new();
    // Chunks of CHUNK rows: the next one is read (one thread) while the current one is judged
    // (the others), so reading overlaps the work and memory stays bounded.
    let mut chunk = Chunk::default();
    let mut next = Chunk::default();
    let mut eof = reader.read(&mut chunk)?;
    loop {
        let (read, outcomes) = rayon::join(
            || {
                if eof {
                    Ok(true)
                } else {
                    reader.read(&mut next)
                }
            },
            || -> Result<Vec<Option<RowOutcome>>, InputError> {
                chunk
                    .rows()
                    .collect::<Vec<_>>()
                    .par_iter()
                    .map_init(
                        RowScratch::default,
                        |scratch, (no, col, text)| -> Result<Option<RowOutcome>, InputError> {
                            let Some((inputs, claimed)) =
                                parse_row(format, text, *no, *col, width, dim, p.precision, &file)?
                            else {
                                return Ok(None);
                            };
                            let mut o = p.row(*no, inputs, claimed, scratch);
                            p.settle_ulps(&mut o, scratch);
                            Ok(Some(o))
                        },
                    )
                    .collect()
            },
        );
        let outcomes = outcomes?;
        let next_eof = read?;
        for (i, o) in outcomes.into_iter().enumerate() {
            let Some(o) = o else { continue };
            report.rows += 1;
            report.histogram.add(o.ulps);
            if o.fell_back {
                report.fell_back += 1;
            }
            if o.settled_exactly {
                report.histogram_exact += 1;
            }
            if o.ulps.is_finite() {
                if o.ulps_lower > floor {
                    floor = o.ulps_lower;
                    candidates.retain(|c| c.0 >= floor);
                }
                if o.ulps >= floor && candidates.len() < MAX_CANDIDATES {
                    let col = chunk.position(i).1;
                    candidates.push((
                        o.ulps,
                        o.line,
                        o.inputs.clone(),
                        o.claimed.clone(),
                        chunk.row(i).to_string(),
                        col,
                    ));
                }
            }
            if o.pass {
                report.passed += 1;
            } else {
                report.failed += 1;
                if report.failures.len() < MAX_LISTED {
                    let texts = texts_of(format, chunk.row(i), o.line, chunk.position(i).1, &file);
                    let refs: Vec<&str> = texts.iter().map(String::as_str).collect();
                    let (_, _, reason, coords) =
                        p.exact_row(&o.inputs, &o.claimed, Some(&refs), true);
                    let reason = o
                        .failure
                        .filter(|r| !r.is_empty())
                        .or(reason)
                        .unwrap_or_else(|| "fails".into());
                    report.failures.push(FailedRow {
                        line: o.line,
                        reason,
                        coords,
                    });
                }
            }
        }
        if progress {
            eprint!(
                "\rtribez check: {} rows, {} failed",
                report.rows, report.failed
            );
            let _ = std::io::stderr().flush();
        }
        if eof {
            break;
        }
        std::mem::swap(&mut chunk, &mut next);
        eof = next_eof;
    }
    if progress {
        eprintln!();
    }
    if report.rows == 0 {
        return Err(InputError::file(file, "no result rows").into());
    }
    // the candidates' exact errors; the first of the largest
    let worst_row = candidates
        .into_iter()
        .map(|(_, line, inputs, claimed, text, col)| {
            let (_, u, _, _) = p.exact_row(&inputs, &claimed, None, false);
            (u, line, inputs, claimed, text, col)
        })
        .fold(None, |best: Option<Candidate>, c| match &best {
            Some(b) if b.0 >= c.0 => best,
            _ => Some(c),
        });
    if let Some((_, line, inputs, claimed, text, col)) = worst_row {
        // Recompute the worst row exactly (its filter figure is an upper bound).
        let texts = texts_of(format, &text, line, col, &file);
        let refs: Vec<&str> = texts.iter().map(String::as_str).collect();
        let (_, u, _, coords) = p.exact_row(&inputs, &claimed, Some(&refs), true);
        report.worst = Some((u, line, coords));
    }
    Ok(report)
}
