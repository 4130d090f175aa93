//! Hunting for the inputs where another implementation is least accurate (what `tribez hunt`
//! and `tribez.hunt` run; docs/theory.md, "Hunting for the worst inputs").
//!
//! A *target* is any function from rows of inputs to rows of results: it is given `n` rows of
//! `w` numbers (row-major; `w = m + 1` barycentric coordinates `λ_0, …, λ_m`, or with
//! [`HuntOptions::cartesian`] the `m` Cartesian coordinates of a point of the patch's domain),
//! every number a float of the hunt's precision, and answers `n` rows of the patch's `d`
//! coordinates. Rows are numbered from 1 in the order they are given to the target.
//!
//! The search (deterministic for a [`HuntOptions::seed`]): about 15% of the budget on uniform
//! points of the domain, 25% on the places floats fail (corners and edges, coordinates `2^-k · r`
//! at every scale, binade boundaries `2^-k` moved by a few floats, near zeros of a coordinate of
//! the value, points of large condition number), then local search around the worst rows
//! found (one coordinate moved by `±2^k` floats, `k` uniform in `0..=52` for `f64`, `0..=23`
//! for `f32`, the largest other coordinate set to the float nearest `1 − Σ others`, or the
//! Cartesian point kept inside the domain, exactly), each later row a fresh place instead with
//! probability 1/5, and a restart of the local search when three rounds bring no worse row. The
//! budget counts rows given to the target.
//!
//! Every row is judged by the batch engine exactly as `tribez check --results` judges it
//! (float filter first, exact arithmetic when undecided; the same tolerances, `cond` without
//! `K` meaning `K = (m+1)·n`): the error in ULPs is that of the result against the exact value
//! at the inputs as the target saw them.

mod render;
mod sample;

use std::collections::HashSet;

use num_rational::BigRational;

use crate::batch::{BatchChecker, BatchError, BatchOptions};
use crate::certify::measures::Tolerance;
use crate::certify::sample::SplitMix;
use crate::domain::Domain;
use crate::exact::Algorithm;
use crate::float::Precision;
use crate::patch_type::Patch;
use sample::Space;

pub use render::{HuntJson, HuntLabels, HuntRowJson, hexes, ulps_text};

/// The most rows a hunt may be given as its budget (2^40).
pub const MAX_BUDGET: u64 = 1 << 40;
/// The most rows given to the target at once.
pub const MAX_BATCH: usize = 1 << 20;
/// The most rows a report lists.
pub const MAX_TOP: usize = 10_000;

/// How a hunt searches and judges.
#[derive(Clone, Debug)]
pub struct HuntOptions {
    /// The precision of the inputs and of the results.
    pub precision: Precision,
    /// The tolerance every row is judged with (as `check --results`).
    pub tolerance: Tolerance,
    /// Rows given to the target, at most.
    pub budget: u64,
    /// The seed of the search (the same seed gives the same rows and report).
    pub seed: u64,
    /// Rows are Cartesian points of the domain (else barycentric coordinates).
    pub cartesian: bool,
    /// The most rows given to the target in one call.
    pub batch: usize,
    /// The worst rows the report lists.
    pub top: usize,
}

impl HuntOptions {
    /// A budget of 10,000 rows, seed 0, barycentric rows, batches of 4,096, the 10 worst rows.
    pub fn new(precision: Precision, tolerance: Tolerance) -> Self {
        HuntOptions {
            precision,
            tolerance,
            budget: 10_000,
            seed: 0,
            cartesian: false,
            batch: 4096,
            top: 10,
        }
    }
}

/// Why a hunt stopped.
#[derive(Debug, thiserror::Error)]
pub enum HuntError<E> {
    /// The target's own error, as it gave it.
    #[error("{0}")]
    Target(E),
    /// The target answered the wrong number of numbers.
    #[error(
        "the target answered {got} numbers for rows {first}..={last} ({expected} expected: {dim} per row)"
    )]
    Answer {
        /// The first row of the call.
        first: u64,
        /// The last row of the call.
        last: u64,
        /// Numbers expected.
        expected: usize,
        /// Numbers per row (the patch's dimension).
        dim: usize,
        /// Numbers answered.
        got: usize,
    },
    /// A patch the hunt does not take (it takes polynomial Bézier patches, as `check --results`).
    #[error("hunt takes a polynomial Bézier patch (as check --results), not {0}")]
    Patch(&'static str),
    /// An option out of range.
    #[error("{0}")]
    Options(String),
    /// The batch engine refused the patch or the options.
    #[error(transparent)]
    Batch(#[from] BatchError),
}

/// One of the worst rows found.
#[derive(Clone, Debug)]
pub struct HuntRow {
    /// Its number (from 1, in the order rows were given to the target).
    pub row: u64,
    /// The input given to the target (floats of the precision).
    pub input: Vec<f64>,
    /// The target's answer (rounded to the precision as the judge reads it).
    pub claimed: Vec<f64>,
    /// The exact value the row was judged against: at the input as the target saw it, with the
    /// control points rounded to the precision (barycentric: the homogeneous form at those
    /// floats; Cartesian: at their exact barycentric coordinates).
    pub exact: Vec<BigRational>,
    /// The error in ULPs (the largest over the coordinates), computed exactly; infinite for a
    /// non-finite answer.
    pub ulps: f64,
    /// It meets the tolerance.
    pub passed: bool,
    /// Why it breaks the tolerance (as `check --results` says it).
    pub reason: Option<String>,
}

/// One evaluated row, as [`hunt_each_row`] shows it (what an error map draws).
#[derive(Clone, Copy, Debug)]
pub struct HuntPoint<'a> {
    /// Its number (from 1).
    pub row: u64,
    /// The input given to the target.
    pub input: &'a [f64],
    /// The target's answer.
    pub claimed: &'a [f64],
    /// Its error in ULPs (exact, or the upper end of a tight enclosure; infinite for a
    /// non-finite answer).
    pub ulps: f64,
    /// It meets the tolerance.
    pub pass: bool,
}

/// What a hunt found.
#[derive(Clone, Debug)]
pub struct HuntReport {
    /// The precision.
    pub precision: Precision,
    /// The tolerance, `cond` with the patch's `K = (m+1)·n` (`cond=9` for a cubic triangle).
    pub tolerance: Tolerance,
    /// The seed (give it again to repeat the hunt).
    pub seed: u64,
    /// The budget.
    pub budget: u64,
    /// Rows were Cartesian.
    pub cartesian: bool,
    /// Rows given to the target and judged.
    pub evaluated: u64,
    /// Rows that broke the tolerance.
    pub broke: u64,
    /// Rows of each kind: uniform, at the places floats fail, local moves.
    pub by_kind: [u64; 3],
    /// The worst rows, worst first (ties: the earlier row), at most [`HuntOptions::top`],
    /// distinct inputs.
    pub worst: Vec<HuntRow>,
}

impl HuntReport {
    /// The largest error found, in ULPs.
    pub fn max_ulps(&self) -> Option<f64> {
        self.worst.first().map(|r| r.ulps)
    }
}

/// A target implementation: given rows of inputs (row-major), it answers one result per row
/// (row-major, the patch's dimension per row), or fails with its own error.
pub type Target<'t, E> = dyn FnMut(&[f64]) -> Result<Vec<f64>, E> + 't;

/// Hunt for the rows where `target` is least accurate on `patch` (see the module
/// documentation): `target` is given rows and answers results, row-major.
///
/// Errors: the target's own error ([`HuntError::Target`], at once: no later row is given), a
/// wrong number of numbers answered, a patch that is not a polynomial Bézier patch, options out
/// of range (budget 0 or over [`MAX_BUDGET`], batch 0 or over [`MAX_BATCH`], top 0 or over
/// [`MAX_TOP`]), or a patch the batch engine refuses in the precision.
pub fn hunt<E>(
    patch: &Patch,
    options: &HuntOptions,
    target: &mut Target<'_, E>,
) -> Result<HuntReport, HuntError<E>> {
    hunt_each_row(patch, options, target, &mut |_| {})
}

/// [`hunt`], calling `each_row` with every evaluated row (in row order).
pub fn hunt_each_row<E>(
    patch: &Patch,
    options: &HuntOptions,
    target: &mut Target<'_, E>,
    each_row: &mut dyn FnMut(HuntPoint<'_>),
) -> Result<HuntReport, HuntError<E>> {
    let bezier = match patch.as_any() {
        crate::any_patch::AnyPatch::Bezier(b) => b.clone(),
        other => return Err(HuntError::Patch(other.described())),
    };
    if options.budget == 0 || options.budget > MAX_BUDGET {
        return Err(HuntError::Options(format!(
            "budget {} is not between 1 and {MAX_BUDGET}",
            options.budget
        )));
    }
    if options.batch == 0 || options.batch > MAX_BATCH {
        return Err(HuntError::Options(format!(
            "batch {} is not between 1 and {MAX_BATCH}",
            options.batch
        )));
    }
    if options.top == 0 || options.top > MAX_TOP {
        return Err(HuntError::Options(format!(
            "top {} is not between 1 and {MAX_TOP}",
            options.top
        )));
    }
    let m = bezier.net.m();
    let dim = bezier.net.dim();
    let domain = bezier
        .domain
        .clone()
        .unwrap_or_else(|| Domain::reference(m));
    let space = space(&bezier, &domain, options);
    let checker = BatchChecker::new(
        bezier.clone(),
        &BatchOptions {
            tolerance: options.tolerance.clone(),
            precision: Some(options.precision),
            algorithm: Algorithm::Casteljau,
            cartesian: options.cartesian,
            row_detail: false,
        },
    )?;
    let mut search = Search::new(space, options);
    let w = search.space.width();
    let mut report = HuntReport {
        precision: options.precision,
        tolerance: options.tolerance.for_patch(m, bezier.net.degree()),
        seed: options.seed,
        budget: options.budget,
        cartesian: options.cartesian,
        evaluated: 0,
        broke: 0,
        by_kind: [0; 3],
        worst: Vec::new(),
    };
    while report.evaluated < options.budget {
        let n = (options.budget - report.evaluated).min(search.round as u64) as usize;
        let (rows, kinds) = search.next_round(n);
        let first = report.evaluated + 1;
        let values = target(&rows).map_err(HuntError::Target)?;
        if values.len() != n * dim {
            return Err(HuntError::Answer {
                first,
                last: first + n as u64 - 1,
                expected: n * dim,
                dim,
                got: values.len(),
            });
        }
        let first_row = usize::try_from(first).unwrap_or(usize::MAX);
        let (_, verdicts) = checker.check_rows(&rows, &values, first_row, "<hunt>", "patch")?;
        for (i, v) in verdicts.iter().enumerate() {
            let input = &rows[i * w..(i + 1) * w];
            let claimed = &values[i * dim..(i + 1) * dim];
            let row = first + i as u64;
            if !v.pass {
                report.broke += 1;
            }
            report.by_kind[kinds[i] as usize] += 1;
            each_row(HuntPoint {
                row,
                input,
                claimed,
                ulps: v.ulps,
                pass: v.pass,
            });
            search.offer(Candidate {
                ulps: if v.ulps.is_nan() {
                    f64::INFINITY
                } else {
                    v.ulps
                },
                row,
                input: input.to_vec(),
                claimed: claimed
                    .iter()
                    .map(|&y| round_claim(options.precision, y))
                    .collect(),
            });
        }
        report.evaluated += n as u64;
        search.end_round();
    }
    report.worst = settle(&checker, &bezier, &domain, options, &search.best)?;
    Ok(report)
}

/// A claimed number as the judge reads it: the nearest float of the precision.
fn round_claim(p: Precision, y: f64) -> f64 {
    sample::round(p, y)
}

fn space(bezier: &crate::patch::BezierPatch, domain: &Domain, options: &HuntOptions) -> Space {
    let net = crate::float::net_to::<f64>(&bezier.net);
    let m = bezier.net.m();
    let vertices: Vec<Vec<f64>> = domain
        .vertices()
        .iter()
        .map(|v| v.iter().map(crate::number::round_f64).collect())
        .collect();
    // the inverse of the matrix whose column k is V_k − V_m, in f64 (Gauss–Jordan)
    let mut a: Vec<Vec<f64>> = (0..m)
        .map(|i| {
            let mut row: Vec<f64> = (0..m).map(|k| vertices[k][i] - vertices[m][i]).collect();
            row.extend((0..m).map(|j| if i == j { 1.0 } else { 0.0 }));
            row
        })
        .collect();
    for c in 0..m {
        let p = (c..m)
            .max_by(|&i, &j| a[i][c].abs().total_cmp(&a[j][c].abs()))
            .unwrap_or(c);
        a.swap(c, p);
        let pivot = a[c][c];
        if pivot != 0.0 {
            for x in a[c].iter_mut() {
                *x /= pivot;
            }
        }
        for i in 0..m {
            if i != c {
                let f = a[i][c];
                let pivot_row = a[c].clone();
                for (x, y) in a[i].iter_mut().zip(&pivot_row) {
                    *x -= f * y;
                }
            }
        }
    }
    let inverse = a.into_iter().map(|row| row[m..].to_vec()).collect();
    Space::new(
        options.precision,
        net,
        vertices,
        inverse,
        domain.clone(),
        options.cartesian,
    )
}

/// A judged row kept as one of the worst.
#[derive(Clone, Debug)]
struct Candidate {
    ulps: f64,
    row: u64,
    input: Vec<f64>,
    claimed: Vec<f64>,
}

/// The kinds of row (the report's [`HuntReport::by_kind`]).
#[derive(Clone, Copy)]
enum Kind {
    Uniform = 0,
    Special = 1,
    Local = 2,
}

/// Worst-first list of distinct inputs, at most `cap` long (ties: the earlier row first).
struct Ranked {
    cap: usize,
    rows: Vec<Candidate>,
}

impl Ranked {
    fn offer(&mut self, c: &Candidate) -> bool {
        if self.rows.len() == self.cap && self.rows.last().is_some_and(|last| last.ulps >= c.ulps) {
            return false;
        }
        if self.rows.iter().any(|r| same_bits(&r.input, &c.input)) {
            return false;
        }
        let at = self.rows.partition_point(|r| r.ulps >= c.ulps);
        self.rows.insert(at, c.clone());
        self.rows.truncate(self.cap);
        true
    }
}

fn same_bits(a: &[f64], b: &[f64]) -> bool {
    a.iter().zip(b).all(|(x, y)| x.to_bits() == y.to_bits())
}

fn row_key(row: &[f64]) -> u64 {
    row.iter().fold(0x243F_6A88_85A3_08D3u64, |h, x| {
        (h ^ x.to_bits())
            .wrapping_mul(0x9E37_79B9_7F4A_7C15)
            .rotate_left(29)
    })
}

/// The state of a search: its generator, the rows still to explore, the worst rows overall and
/// the pool local search moves from.
struct Search {
    space: Space,
    rng: SplitMix,
    round: usize,
    uniform_left: u64,
    special_left: u64,
    best: Ranked,
    pool: Ranked,
    pool_best: f64,
    stale: u32,
    seen: HashSet<u64>,
}

/// Rows the local search moves from.
const POOL: usize = 16;
/// Rounds without a worse row before the local search restarts.
const STALE_ROUNDS: u32 = 3;

impl Search {
    fn new(space: Space, options: &HuntOptions) -> Self {
        let b = options.budget;
        // rounds of at most `batch` rows, at least 8 rounds where the batch allows (so that
        // the local search has rounds to follow up on), at least 64 rows a round
        let round = (b.div_ceil(8).max(64) as usize).min(options.batch);
        let explore = (b * 2).div_ceil(5);
        let uniform_left = explore * 3 / 8;
        Search {
            space,
            rng: SplitMix(options.seed ^ 0x7472_6962_657A_6875),
            round,
            uniform_left,
            special_left: explore - uniform_left,
            best: Ranked {
                cap: options.top.max(POOL),
                rows: Vec::new(),
            },
            pool: Ranked {
                cap: POOL,
                rows: Vec::new(),
            },
            pool_best: f64::NEG_INFINITY,
            stale: 0,
            seen: HashSet::new(),
        }
    }

    /// The next `n` rows (row-major) and their kinds.
    fn next_round(&mut self, n: usize) -> (Vec<f64>, Vec<Kind>) {
        let mut rows = Vec::with_capacity(n * self.space.width());
        let mut kinds = Vec::with_capacity(n);
        for _ in 0..n {
            let (row, kind) = self.next_row();
            rows.extend_from_slice(&row);
            kinds.push(kind);
        }
        (rows, kinds)
    }

    fn next_row(&mut self) -> (Vec<f64>, Kind) {
        let mut last = None;
        for _ in 0..8 {
            let (row, kind) = self.propose();
            if self.seen.insert(row_key(&row)) {
                return (row, kind);
            }
            last = Some((row, kind));
        }
        // (only when nearly every proposal repeats a row: a tiny domain of floats)
        last.unwrap_or_else(|| (self.space.uniform_row(&mut self.rng), Kind::Uniform))
    }

    fn propose(&mut self) -> (Vec<f64>, Kind) {
        let explore = self.uniform_left + self.special_left;
        if explore > 0 {
            let r = &mut self.rng;
            let uniform = r.next_u64() % explore < self.uniform_left;
            return if uniform {
                self.uniform_left -= 1;
                (self.space.uniform_row(r), Kind::Uniform)
            } else {
                self.special_left -= 1;
                (self.space.special_row(r), Kind::Special)
            };
        }
        let r = &mut self.rng;
        if self.pool.rows.is_empty() || r.next_u64().is_multiple_of(5) {
            return if r.next_u64().is_multiple_of(4) {
                (self.space.uniform_row(r), Kind::Uniform)
            } else {
                (self.space.special_row(r), Kind::Special)
            };
        }
        for _ in 0..8 {
            let u = self.rng.unit();
            let parent = ((u * u) * self.pool.rows.len() as f64) as usize;
            let parent = parent.min(self.pool.rows.len() - 1);
            let input = self.pool.rows[parent].input.clone();
            if let Some(row) = self.space.local_move(&mut self.rng, &input) {
                return (row, Kind::Local);
            }
        }
        (self.space.special_row(&mut self.rng), Kind::Special)
    }

    fn offer(&mut self, c: Candidate) {
        self.pool.offer(&c);
        self.best.offer(&c);
    }

    /// After a round: restart the local search when it has found no worse row in
    /// [`STALE_ROUNDS`] rounds (once exploration is over).
    fn end_round(&mut self) {
        if self.uniform_left + self.special_left > 0 {
            return;
        }
        let top = self.pool.rows.first().map_or(f64::NEG_INFINITY, |c| c.ulps);
        if top > self.pool_best {
            self.pool_best = top;
            self.stale = 0;
        } else {
            self.stale += 1;
            if self.stale >= STALE_ROUNDS {
                self.pool.rows.clear();
                self.pool_best = f64::NEG_INFINITY;
                self.stale = 0;
            }
        }
    }
}

/// The worst rows in full: each judged again alone (its exact error and verdict), with the
/// exact value at its input.
fn settle<E>(
    checker: &BatchChecker,
    bezier: &crate::patch::BezierPatch,
    domain: &Domain,
    options: &HuntOptions,
    best: &Ranked,
) -> Result<Vec<HuntRow>, HuntError<E>> {
    let patch = Patch::from(crate::any_patch::AnyPatch::Bezier(bezier.clone()));
    let mut out = Vec::new();
    for c in best.rows.iter().take(options.top) {
        let row = usize::try_from(c.row).unwrap_or(usize::MAX);
        let (report, _) = checker.check_rows(&c.input, &c.claimed, row, "<hunt>", "patch")?;
        // the exact value the judge used: at the inputs as the target saw them, with the control
        // points rounded to the precision (what float code sees, guide §7); recomputed the same
        // way only where the report has no worst row (a row without a finite input)
        let exact = match &report.worst {
            Some(w) => w.coords.iter().map(|k| k.exact_seen.clone()).collect(),
            None => exact_as_seen(&patch, domain, options, &c.input),
        };
        out.push(HuntRow {
            row: c.row,
            input: c.input.clone(),
            claimed: c.claimed.clone(),
            exact,
            ulps: report.max_ulps.unwrap_or(f64::INFINITY),
            passed: report.failed == 0,
            reason: report.failures.first().map(|f| f.reason.clone()),
        });
    }
    // the exact figures may reorder rows whose enclosures overlapped
    out.sort_by(|a, b| b.ulps.total_cmp(&a.ulps).then(a.row.cmp(&b.row)));
    Ok(out)
}

/// The exact value at `input` (floats) of the patch with its control points rounded to the
/// hunt's precision; empty where an input is not finite or a Cartesian point has no barycentric
/// coordinates.
fn exact_as_seen(
    patch: &Patch,
    domain: &Domain,
    options: &HuntOptions,
    input: &[f64],
) -> Vec<BigRational> {
    let crate::any_patch::AnyPatch::Bezier(b) = patch.as_any() else {
        return Vec::new();
    };
    let mut seen = b.clone();
    seen.net = b.net.map(|q| {
        crate::certify::measures::as_float(q, options.precision).unwrap_or_else(|| q.clone())
    });
    let seen = Patch::from(crate::any_patch::AnyPatch::Bezier(seen));
    let exact_input: Option<Vec<BigRational>> =
        input.iter().map(|&x| crate::number::exact_f64(x)).collect();
    let lambda = exact_input.and_then(|x| {
        if options.cartesian {
            domain.barycentric(&x).ok()
        } else {
            Some(x)
        }
    });
    lambda
        .and_then(|l| seen.evaluate_homogeneous(&l).ok())
        .unwrap_or_default()
}

/// The exact hex-float text of `x` as a float of `precision` (`0x1.5555555555555p-2`; an `f32`
/// with 6 fraction digits): how a hunt writes its rows to a target and its reports.
pub fn hex(precision: Precision, x: f64) -> String {
    match precision {
        Precision::F64 => crate::number::hex_f64(x),
        Precision::F32 => crate::number::hex_f32(x as f32),
    }
}

/// An exact number as a decimal of `digits` significant digits (`0.33333` for 1/3 to 5).
pub fn decimal(q: &BigRational, digits: usize) -> String {
    crate::number::to_decimal_string(q, digits)
}

#[cfg(test)]
mod tests;
