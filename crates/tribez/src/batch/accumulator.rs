//! The report of a run assembled row by row in input order: counts summed per slab, failures
//! listed in order, the worst row kept among candidates and settled exactly at the end.

use num_rational::BigRational;
use rayon::prelude::*;

use super::driver::{MemoryRows, RowPoint, RowVerdict, memory_num};
use super::judge::{Prepared, RowOutcome, RowScratch};
use super::parse::{self, Format, Num, parse_row, texts_of};
use super::{
    BatchReport, FailedRow, MAX_CANDIDATES, MAX_LISTED, RowDetail, UlpHistogram, WorstRow,
};
use crate::io::InputError;

#[cfg(doc)]
use super::{BatchChecker, BatchOptions, STOP_SLAB};

/// Where a row came from, to find its inputs as intended: a file's row text (and the column it
/// starts at), or memory (the numbers themselves).
pub(super) enum Source<'a> {
    Text(&'a str, usize),
    Memory,
}

/// A row judged, with its detail when asked for.
pub(super) struct Judged {
    pub(super) outcome: RowOutcome,
    pub(super) detail: Option<RowDetail>,
}

/// Rows judged together on one thread (a task of a chunk's parallel pass).
const SLAB: usize = 4096;

/// The most in-memory rows judged together on one thread ([`Accumulator::judge_memory`]): small
/// enough that a slab between two stop tests ([`STOP_SLAB`]) splits over every core.
const MEMORY_SLAB: usize = 1024;

/// The counts of a report, summed over rows (any order).
#[derive(Default)]
struct Tally {
    checked: u64,
    passed: u64,
    failed: u64,
    fell_back: u64,
    histogram_exact: usize,
    histogram: UlpHistogram,
}

impl Tally {
    /// Count a judged row.
    fn count(&mut self, o: &RowOutcome) {
        self.checked += 1;
        self.histogram.add(o.ulps);
        if o.fell_back {
            self.fell_back += 1;
        }
        if o.settled_exactly {
            self.histogram_exact += 1;
        }
        if o.pass {
            self.passed += 1;
        } else {
            self.failed += 1;
        }
    }

    /// Add the counts to a report's.
    fn add_to(&self, report: &mut BatchReport) {
        report.checked += self.checked;
        report.passed += self.passed;
        report.failed += self.failed;
        report.fell_back += self.fell_back;
        report.histogram_exact += self.histogram_exact;
        for (a, b) in report
            .histogram
            .counts
            .iter_mut()
            .zip(self.histogram.counts)
        {
            *a += b;
        }
    }
}

/// Which rows of a slab may matter to the report's listed failures and worst row
/// ([`Accumulator::note`]), told without the rows of the slabs before it: the slab's first
/// [`MAX_LISTED`] failures, and every row with finite figures whose upper bound reaches a floor
/// no higher than the report's at that row (the report's floor before the chunk, raised by the
/// slab's own rows' lower bounds). A row it drops neither raises the report's floor nor becomes
/// a candidate: it would change nothing in [`Accumulator::note`], so noting only the rows it
/// keeps gives the same report.
struct Sieve {
    floor: f64,
    failures: usize,
}

impl Sieve {
    /// Whether to keep a row (in input order).
    fn keep(&mut self, o: &RowOutcome) -> bool {
        let mut keep = false;
        if !o.pass && self.failures < MAX_LISTED {
            self.failures += 1;
            keep = true;
        }
        if o.ulps.is_finite() {
            // (a row that raises the floor has ulps ≥ ulps_lower > floor)
            keep |= o.ulps >= self.floor;
            self.floor = self.floor.max(o.ulps_lower);
        }
        keep
    }
}

/// What a slab of rows came to: its counts, the rows [`Sieve`] kept (index into the rows,
/// judged row with its numbers), every row's detail (with [`BatchOptions::row_detail`]) and
/// [`RowPoint`] (when asked for), in order, and the first error, which ends the slab.
#[derive(Default)]
pub(super) struct Slab {
    tally: Tally,
    kept: Vec<(usize, Judged)>,
    details: Vec<RowDetail>,
    points: Vec<RowPoint>,
    error: Option<InputError>,
}

/// A row that may be the worst: its upper bound, its number, its numbers and where it came from.
struct Candidate {
    upper: f64,
    lower: f64,
    row: usize,
    inputs: Vec<Num>,
    claimed: Vec<Num>,
    text: Option<(String, usize)>,
}

/// The report being assembled, row by row in order.
pub(super) struct Accumulator<'p> {
    p: &'p Prepared,
    format: Option<Format>,
    pub(super) report: BatchReport,
    /// The largest lower bound seen.
    floor: f64,
    /// Some candidate's lower bound reaches `floor` (a later row whose upper bound is at most
    /// `floor` can at best tie it, and ties go to the earlier row).
    certified: bool,
    candidates: Vec<Candidate>,
}

impl<'p> Accumulator<'p> {
    pub(super) fn new(p: &'p Prepared, file: &str, patch: &str, format: Option<Format>) -> Self {
        Accumulator {
            p,
            format,
            report: BatchReport {
                file: file.into(),
                patch: patch.into(),
                tolerance: p.tolerance.clone(),
                precision: p.precision,
                checked: 0,
                passed: 0,
                failed: 0,
                fell_back: 0,
                histogram: UlpHistogram::default(),
                histogram_upper_bounds: p.filter.is_some(),
                histogram_exact: 0,
                max_ulps: None,
                worst: None,
                failures: Vec::new(),
                rows: p.row_detail.then(Vec::new),
                baseline_regressions: Vec::new(),
            },
            floor: 0.0,
            certified: false,
            candidates: Vec::new(),
        }
    }

    /// The inputs of a row as intended.
    fn intended(
        &self,
        inputs: &[Num],
        row: usize,
        source: &Source<'_>,
    ) -> Option<Vec<BigRational>> {
        match (source, self.format) {
            (Source::Text(text, col), Some(format)) => {
                let texts = texts_of(format, text, row, *col, &self.report.file);
                inputs
                    .iter()
                    .zip(&texts)
                    .map(|(x, s)| x.text_value(s))
                    .collect()
            }
            _ => inputs
                .iter()
                .map(|x| match x {
                    Num::Value {
                        text_exact: Some(q),
                        ..
                    } => Some(q.clone()),
                    // a memory row of an `f64` batch: the `f64` given is the float (`memory_num`)
                    Num::Value {
                        float,
                        text_exact: None,
                    } if matches!(source, Source::Memory) => crate::number::exact_f64(*float),
                    _ => None,
                })
                .collect(),
        }
    }

    /// Judge one row (any thread): the filter, exact arithmetic when undecided, the ULP figures
    /// settled, and the row's detail when asked for.
    pub(super) fn judge(
        &self,
        row: usize,
        inputs: Vec<Num>,
        claimed: Vec<Num>,
        source: &Source<'_>,
        scratch: &mut RowScratch,
    ) -> Judged {
        let p = self.p;
        let outcome = p.row(row, inputs, claimed, scratch);
        let detail = p.row_detail.then(|| {
            let intended = self.intended(&outcome.inputs, row, source);
            let (passed, ulps, _, coords) =
                p.exact_row(&outcome.inputs, &outcome.claimed, intended.as_deref(), true);
            let finite = coords.len() == outcome.claimed.len();
            RowDetail {
                row,
                passed,
                ulps_seen: ulps,
                ulps_intended: coords
                    .iter()
                    .map(|c| {
                        c.intended
                            .as_ref()
                            .and_then(|m| m.ulps.as_ref())
                            .map(crate::number::round_up_f64)
                    })
                    .collect::<Option<Vec<f64>>>()
                    .filter(|_| finite)
                    .map(|us| us.into_iter().fold(0.0, f64::max)),
                correctly_rounded: finite
                    && coords
                        .iter()
                        .all(|c| c.seen.correctly_rounded == Some(true)),
            }
        });
        Judged { outcome, detail }
    }

    /// Judge a row of a results file (any thread): `None` for a blank or comment line. A CSV row
    /// of plain numbers that the float filter decides is judged from its floats alone, without
    /// parsing its numbers in full (the outcome's numbers are then empty).
    fn judge_text(
        &self,
        format: Format,
        (line, col, text): (usize, usize, &str),
        scratch: &mut RowScratch,
    ) -> Result<Option<Judged>, InputError> {
        let p = self.p;
        let (width, dim) = (p.width(), p.patch.net.dim());
        if let (Format::Csv, Some(precision), Some(_), false) =
            (format, p.precision, &p.filter, p.row_detail)
            && parse::csv_floats(
                text,
                width,
                dim,
                precision,
                &mut scratch.lambda,
                &mut scratch.ys,
            )
            && let Some(outcome) = p.filtered(line, scratch)
        {
            return Ok(Some(Judged {
                outcome,
                detail: None,
            }));
        }
        let file = &self.report.file;
        let Some((inputs, claimed)) =
            parse_row(format, text, line, col, width, dim, p.precision, file)?
        else {
            return Ok(None);
        };
        Ok(Some(self.judge(
            line,
            inputs,
            claimed,
            &Source::Text(text, col),
            scratch,
        )))
    }

    /// Judge rows of a results file (`(line, column, text)` as read, in input order) in
    /// parallel, in slabs of [`SLAB`] rows, each slab on one thread; `points`: keep every row's
    /// [`RowPoint`]. [`Accumulator::merge`] then adds the slabs to the report.
    pub(super) fn judge_slabs(
        &self,
        rows: &[(usize, usize, &str)],
        format: Format,
        points: bool,
    ) -> Vec<Slab> {
        let p = self.p;
        let file = &self.report.file;
        rows.par_chunks(SLAB)
            .enumerate()
            .map_init(RowScratch::default, |scratch, (s, slab_rows)| {
                let mut slab = Slab::default();
                let mut sieve = Sieve {
                    floor: self.floor,
                    failures: 0,
                };
                for (k, &row) in slab_rows.iter().enumerate() {
                    let (line, col, text) = row;
                    let judged = match self.judge_text(format, row, scratch) {
                        Ok(Some(j)) => j,
                        Ok(None) => continue,
                        Err(e) => {
                            slab.error = Some(e);
                            break;
                        }
                    };
                    let Judged {
                        mut outcome,
                        detail,
                    } = judged;
                    slab.tally.count(&outcome);
                    slab.details.extend(detail);
                    let keep = sieve.keep(&outcome);
                    if (keep || points) && outcome.inputs.is_empty() {
                        // a row judged from its floats: its numbers in full
                        let width = p.width();
                        let parsed = parse_row(
                            format,
                            text,
                            line,
                            col,
                            width,
                            p.patch.net.dim(),
                            p.precision,
                            file,
                        );
                        match parsed {
                            Ok(Some((inputs, claimed))) => {
                                outcome.inputs = inputs;
                                outcome.claimed = claimed;
                            }
                            // invariant: the row was read by csv_floats just before, so parsing it again succeeds
                            _ => unreachable!("csv_floats read the row"),
                        }
                    }
                    if points {
                        slab.points.push(RowPoint::of(&outcome));
                    }
                    if keep {
                        slab.kept.push((
                            s * SLAB + k,
                            Judged {
                                outcome,
                                detail: None,
                            },
                        ));
                    }
                }
                slab
            })
            .collect()
    }

    /// Add judged slabs to the report, in input order (`rows` as given to
    /// [`Accumulator::judge_slabs`]); `each_row` is called with every row's [`RowPoint`]. The
    /// first error in input order is returned, after the rows before it were added.
    pub(super) fn merge(
        &mut self,
        slabs: Vec<Slab>,
        rows: &[(usize, usize, &str)],
        mut each_row: Option<&mut (dyn FnMut(RowPoint) + '_)>,
    ) -> Result<(), InputError> {
        for slab in slabs {
            slab.tally.add_to(&mut self.report);
            if let Some(rows) = &mut self.report.rows {
                rows.extend(slab.details);
            }
            if let Some(f) = each_row.as_mut() {
                slab.points.into_iter().for_each(f);
            }
            for (i, judged) in slab.kept {
                let (_, col, text) = rows[i];
                self.note(judged.outcome, &Source::Text(text, col));
            }
            if let Some(e) = slab.error {
                return Err(e);
            }
        }
        Ok(())
    }

    /// Judge the in-memory rows `start..start + out.len()` in parallel, in pieces of at most
    /// [`MEMORY_SLAB`] rows, each piece on one thread, writing each row's verdict to `out`.
    /// [`Accumulator::merge_memory`] then adds the slabs to the report. A row whose numbers are
    /// finite floats of the precision and that the float filter decides is judged from them
    /// alone, without allocating; its numbers ([`Num`]) are made only if [`Sieve`] keeps it for
    /// the report. Any other row is judged as [`Accumulator::judge`] judges it.
    pub(super) fn judge_memory(
        &self,
        rows: &MemoryRows<'_>,
        start: usize,
        out: &mut [RowVerdict],
    ) -> Vec<Slab> {
        let p = self.p;
        let (width, dim) = (p.width(), p.patch.net.dim());
        let fast = p.filter.is_some() && !p.row_detail;
        let nums =
            |xs: &[f64]| -> Vec<Num> { xs.iter().map(|&x| memory_num(x, p.precision)).collect() };
        // a few pieces per thread however few the rows (a slab of slow rows is small)
        let piece = out
            .len()
            .div_ceil(4 * rayon::current_num_threads())
            .clamp(1, MEMORY_SLAB);
        out.par_chunks_mut(piece)
            .enumerate()
            .map_init(RowScratch::default, |scratch, (s, out)| {
                let mut slab = Slab::default();
                let mut sieve = Sieve {
                    floor: self.floor,
                    failures: 0,
                };
                for (k, verdict) in out.iter_mut().enumerate() {
                    let i = start + s * piece + k;
                    let row = rows.first_row + i;
                    let xs = &rows.points[i * width..(i + 1) * width];
                    let ys = &rows.values[i * dim..(i + 1) * dim];
                    let filtered = if fast && scratch.load_floats(xs, ys, p.precision) {
                        p.filtered(row, scratch)
                    } else {
                        None
                    };
                    let Judged {
                        mut outcome,
                        detail,
                    } = match filtered {
                        Some(outcome) => Judged {
                            outcome,
                            detail: None,
                        },
                        None => self.judge(row, nums(xs), nums(ys), &Source::Memory, scratch),
                    };
                    slab.tally.count(&outcome);
                    slab.details.extend(detail);
                    *verdict = RowVerdict {
                        row,
                        pass: outcome.pass,
                        fell_back: outcome.fell_back,
                        ulps: outcome.ulps,
                    };
                    if sieve.keep(&outcome) {
                        if outcome.inputs.is_empty() {
                            // a row judged from its floats: its numbers in full
                            outcome.inputs = nums(xs);
                            outcome.claimed = nums(ys);
                        }
                        slab.kept.push((
                            k,
                            Judged {
                                outcome,
                                detail: None,
                            },
                        ));
                    }
                }
                slab
            })
            .collect()
    }

    /// Add slabs judged by [`Accumulator::judge_memory`] to the report, in row order.
    pub(super) fn merge_memory(&mut self, slabs: Vec<Slab>) {
        for slab in slabs {
            slab.tally.add_to(&mut self.report);
            if let Some(rows) = &mut self.report.rows {
                rows.extend(slab.details);
            }
            for (_, judged) in slab.kept {
                self.note(judged.outcome, &Source::Memory);
            }
        }
    }

    /// Note a judged row (in input order; counted apart) for the report's listed failures and
    /// worst row.
    fn note(&mut self, o: RowOutcome, source: &Source<'_>) {
        let report = &mut self.report;
        if !o.pass && report.failures.len() < MAX_LISTED {
            let intended = self.intended(&o.inputs, o.line, source);
            let (_, _, reason, coords) =
                self.p
                    .exact_row(&o.inputs, &o.claimed, intended.as_deref(), true);
            let reason = o
                .failure
                .clone()
                .filter(|r| !r.is_empty())
                .or(reason)
                .unwrap_or_else(|| "fails".into());
            self.report.failures.push(FailedRow {
                line: o.line,
                reason,
                coords,
            });
        }
        if !o.ulps.is_finite() {
            return;
        }
        if o.ulps_lower > self.floor {
            self.floor = o.ulps_lower;
            let floor = self.floor;
            self.candidates.retain(|c| c.upper >= floor);
            self.certified = false;
        }
        if o.ulps > self.floor || (o.ulps >= self.floor && !self.certified) {
            if o.ulps_lower >= self.floor {
                self.certified = true;
            }
            let text = match source {
                Source::Text(t, col) => Some((t.to_string(), *col)),
                Source::Memory => None,
            };
            self.candidates.push(Candidate {
                upper: o.ulps,
                lower: o.ulps_lower,
                row: o.line,
                inputs: o.inputs,
                claimed: o.claimed,
                text,
            });
            if self.candidates.len() >= MAX_CANDIDATES {
                self.settle_candidates();
            }
        }
    }

    /// Compute the candidates' errors exactly and keep the first of the largest.
    fn settle_candidates(&mut self) {
        for c in &mut self.candidates {
            if c.lower < c.upper {
                let (_, u, _, _) = self.p.exact_row(&c.inputs, &c.claimed, None, false);
                c.lower = u;
                c.upper = u;
            }
        }
        let best =
            self.candidates
                .iter()
                .enumerate()
                .fold(None, |best: Option<(usize, f64)>, (i, c)| match best {
                    Some((_, u)) if u >= c.upper => best,
                    _ => Some((i, c.upper)),
                });
        if let Some((i, u)) = best {
            let c = self.candidates.swap_remove(i);
            self.candidates.clear();
            self.candidates.push(c);
            self.floor = self.floor.max(u);
            self.certified = true;
        }
    }

    /// The report, with the worst row computed exactly.
    pub(super) fn finish(mut self) -> BatchReport {
        self.settle_candidates();
        if let Some(c) = self.candidates.pop() {
            let source = match &c.text {
                Some((t, col)) => Source::Text(t, *col),
                None => Source::Memory,
            };
            let intended = self.intended(&c.inputs, c.row, &source);
            let (_, u, _, coords) =
                self.p
                    .exact_row(&c.inputs, &c.claimed, intended.as_deref(), true);
            self.report.max_ulps = Some(u);
            self.report.worst = Some(WorstRow {
                ulps: u,
                line: c.row,
                coords,
            });
        }
        self.report
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::batch::BatchOptions;
    use crate::certify::measures::Tolerance;
    use crate::float::Precision;
    use proptest::prelude::*;

    /// A row with figures `lower ≤ upper` (its numbers: the point (1, 0, 0), claimed 0).
    fn outcome(line: usize, pass: bool, lower: f64, upper: f64) -> RowOutcome {
        let num = |x: f64| Num::Value {
            float: x,
            text_exact: None,
        };
        RowOutcome {
            line,
            pass,
            fell_back: false,
            ulps: upper,
            ulps_lower: lower,
            settled_exactly: false,
            failure: (!pass).then(|| "fails".to_string()),
            inputs: vec![num(1.0), num(0.0), num(0.0)],
            claimed: vec![num(0.0); 3],
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]
        /// Noting only the rows [`Sieve`] keeps, slab by slab (each sieve starting from the
        /// report's floor before its chunk), leaves the report's failures, floor and candidates
        /// for the worst row as noting every row does. The figures come from a few values, so
        /// that ties and overlapping enclosures are common (and all rows may have no error).
        #[test]
        fn noting_the_rows_the_sieve_keeps_is_noting_every_row(
            rows in prop::collection::vec((0usize..5, 0usize..3, proptest::bool::weighted(0.9), proptest::bool::weighted(0.05)), 1..200),
            chunk in 1usize..40,
            slab in 1usize..12,
            exact in proptest::bool::weighted(0.2),
        ) {
            let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
                .join("../../fixtures/finn_day30.toml");
            let patch = crate::io::patch_file::read_patch(&path).unwrap();
            let options = BatchOptions {
                tolerance: Tolerance::Ulps(num_rational::BigRational::from_integer(1.into())),
                precision: Some(Precision::F64),
                ..BatchOptions::default()
            };
            let p = Prepared::new(&options, patch).unwrap();
            let lowers = [0.0, 0.5, 1.0, 1.5, 3.0];
            let widths = [0.0, 0.25, 1.0];
            let outcomes = || {
                rows.iter().enumerate().map(|(i, &(l, w, pass, infinite))| {
                    let (lo, hi) = if infinite {
                        (f64::INFINITY, f64::INFINITY)
                    } else if exact {
                        // errors computed exactly: every row a tie at first
                        (lowers[l / 3], lowers[l / 3])
                    } else {
                        (lowers[l], lowers[l] + widths[w])
                    };
                    outcome(i + 1, pass, lo, hi)
                })
            };
            let mut every = Accumulator::new(&p, "f", "p", None);
            for o in outcomes() {
                every.note(o, &Source::Memory);
            }
            let mut sieved = Accumulator::new(&p, "f", "p", None);
            let all: Vec<RowOutcome> = outcomes().collect();
            for c in all.chunks(chunk) {
                let floor = sieved.floor;
                let kept: Vec<RowOutcome> = c
                    .chunks(slab)
                    .flat_map(|s| {
                        let mut sieve = Sieve { floor, failures: 0 };
                        s.iter().filter(|o| sieve.keep(o)).map(|o| outcome(o.line, o.pass, o.ulps_lower, o.ulps)).collect::<Vec<_>>()
                    })
                    .collect();
                for o in kept {
                    sieved.note(o, &Source::Memory);
                }
            }
            let state = |a: &Accumulator<'_>| {
                (
                    a.floor,
                    a.certified,
                    a.candidates.iter().map(|c| (c.row, c.lower, c.upper)).collect::<Vec<_>>(),
                    a.report.failures.iter().map(|f| f.line).collect::<Vec<_>>(),
                )
            };
            prop_assert_eq!(state(&every), state(&sieved));
        }
    }
}
