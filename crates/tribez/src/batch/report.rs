//! The batch report: text and JSON (the command line adds JUnit).

use num_rational::BigRational;
use serde_json::Value as Json;

use super::UlpHistogram;
use crate::certify::measures::{Measures, Tolerance};
use crate::float::Precision;
use crate::number::to_decimal_string;

/// A failed row, in full.
#[derive(Clone, Debug)]
pub struct FailedRow {
    /// The row's number: the line where it starts in a file (1-based), its index in memory.
    pub line: usize,
    /// Why it fails (the first coordinate that breaks the tolerance, or a non-finite number).
    pub reason: String,
    /// Every claimed coordinate's figures.
    pub coords: Vec<FailedCoord>,
}

/// One claimed coordinate of a row, measured exactly.
#[derive(Clone, Debug)]
pub struct FailedCoord {
    /// The coordinate (0-based).
    pub index: usize,
    /// The claimed float, shortest decimal that reads back to it.
    pub decimal: String,
    /// The claimed float in hexadecimal (exact).
    pub hex: String,
    /// The exact value at the inputs as the code saw them (the floats).
    pub exact_seen: BigRational,
    /// The claimed value's error against it.
    pub seen: Measures,
    /// The exact value at the inputs as intended (their exact text), when known.
    pub exact_intended: Option<BigRational>,
    /// The claimed value's error against that.
    pub intended: Option<Measures>,
}

/// The row with the largest error.
#[derive(Clone, Debug)]
pub struct WorstRow {
    /// Its error in ULPs (the largest over its coordinates), computed exactly.
    pub ulps: f64,
    /// The row's number (as [`FailedRow::line`]).
    pub line: usize,
    /// Its coordinates' figures.
    pub coords: Vec<FailedCoord>,
}

/// One row's figures, kept with [`super::BatchOptions::row_detail`].
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct RowDetail {
    /// The row's number (as [`FailedRow::line`]).
    pub row: usize,
    /// It meets the tolerance.
    pub passed: bool,
    /// The largest error in ULPs over its coordinates at the inputs as seen (infinite for a
    /// non-finite number).
    pub ulps_seen: f64,
    /// The same at the inputs as intended, when known.
    pub ulps_intended: Option<f64>,
    /// Every coordinate is the correctly rounded exact value at the inputs as seen.
    pub correctly_rounded: bool,
}

/// The batch report.
///
/// [`BatchReport::merge`] combines the reports of disjoint sets of rows (checked with the same
/// patch and options) into exactly the report of their union: counts and histograms add, the
/// worst row is the one with the largest error, ties going to the smallest row number, the
/// listed failures are the first [`super::MAX_LISTED`] by row number.
#[derive(Clone, Debug)]
pub struct BatchReport {
    /// The results file (`<memory>` for rows in memory).
    pub file: String,
    /// The patch's name.
    pub patch: String,
    /// The tolerance every row was judged with.
    pub tolerance: Tolerance,
    /// The precision of the numbers (`None`: exact numbers).
    pub precision: Option<Precision>,
    /// Rows checked.
    pub checked: u64,
    /// Rows that meet the tolerance.
    pub passed: u64,
    /// Rows that do not.
    pub failed: u64,
    /// Rows the float filter could not decide (judged in exact arithmetic).
    pub fell_back: u64,
    /// The errors in ULPs.
    pub histogram: UlpHistogram,
    /// Errors of filter-decided rows enter the histogram as the upper ends of their compensated
    /// enclosures.
    pub histogram_upper_bounds: bool,
    /// Filter-decided rows whose error was computed exactly for the histogram (its enclosure
    /// straddled a bucket boundary).
    pub histogram_exact: usize,
    /// The largest error in ULPs over the rows with finite numbers (that of [`Self::worst`]).
    pub max_ulps: Option<f64>,
    /// The row with the largest error (ties: the smallest row number).
    pub worst: Option<WorstRow>,
    /// The first failed rows, in full (at most [`super::MAX_LISTED`]).
    pub failures: Vec<FailedRow>,
    /// Every row's figures, in row order, with [`super::BatchOptions::row_detail`].
    pub rows: Option<Vec<RowDetail>>,
    /// Worst errors that got worse than a recorded baseline's, one line each (filled in by the
    /// caller that compares baselines; empty otherwise).
    pub baseline_regressions: Vec<String>,
}

impl BatchReport {
    /// Combine with the report of a disjoint set of rows checked with the same patch and
    /// options: the result is the report of the union, whatever the order of merging.
    ///
    /// Errors: reports judged with different tolerances or precisions, or about different
    /// patches (nothing is changed).
    pub fn merge(&mut self, other: &BatchReport) -> Result<(), super::BatchError> {
        let mismatch = |what, this: String, other: String| {
            Err(super::BatchError::Mismatch { what, this, other })
        };
        if self.tolerance != other.tolerance {
            return mismatch(
                "judged with different tolerances",
                self.tolerance.text(),
                other.tolerance.text(),
            );
        }
        if self.precision != other.precision {
            let name = |p: Option<Precision>| p.map_or("exact numbers", |p| p.name()).to_string();
            return mismatch(
                "judged with different precisions",
                name(self.precision),
                name(other.precision),
            );
        }
        if self.patch != other.patch {
            return mismatch(
                "about different patches",
                self.patch.clone(),
                other.patch.clone(),
            );
        }
        self.checked += other.checked;
        self.passed += other.passed;
        self.failed += other.failed;
        self.fell_back += other.fell_back;
        for (a, b) in self.histogram.counts.iter_mut().zip(other.histogram.counts) {
            *a += b;
        }
        self.histogram_upper_bounds &= other.histogram_upper_bounds;
        self.histogram_exact += other.histogram_exact;
        let better = match (&self.worst, &other.worst) {
            (_, None) => false,
            (None, Some(_)) => true,
            (Some(a), Some(b)) => b.ulps > a.ulps || (b.ulps == a.ulps && b.line < a.line),
        };
        if better {
            self.worst = other.worst.clone();
        }
        self.max_ulps = self.worst.as_ref().map(|w| w.ulps);
        self.failures.extend(other.failures.iter().cloned());
        self.failures.sort_by_key(|f| f.line);
        self.failures.truncate(super::MAX_LISTED);
        if let (Some(rows), Some(more)) = (&mut self.rows, &other.rows) {
            rows.extend(more.iter().cloned());
            rows.sort_by_key(|r| r.row);
        }
        Ok(())
    }

    /// The failed rows not listed in [`Self::failures`].
    pub fn failures_not_listed(&self) -> usize {
        self.failed as usize - self.failures.len()
    }
}

impl serde::Serialize for UlpHistogram {
    /// Bucket label → count.
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeMap;
        let mut map = s.serialize_map(Some(self.counts.len()))?;
        for (label, count) in super::ULP_BUCKETS.iter().zip(self.counts) {
            map.serialize_entry(label, &count)?;
        }
        map.end()
    }
}

/// The report as JSON (the layout of `tribez check --format json`).
#[derive(serde::Serialize)]
struct ReportJson<'a> {
    results: &'a str,
    patch: &'a str,
    tolerance: String,
    precision: Option<&'static str>,
    summary: SummaryJson<'a>,
    worst: Option<WorstJson>,
    failures: Vec<FailureJson<'a>>,
    failures_not_listed: usize,
    #[serde(skip_serializing_if = "Option::is_none")]
    rows: Option<&'a [RowDetail]>,
    #[serde(skip_serializing_if = "<[String]>::is_empty")]
    baseline_regressions: &'a [String],
}

#[derive(serde::Serialize)]
struct SummaryJson<'a> {
    claims: u64,
    passed: u64,
    failed: u64,
    filter_used: bool,
    decided_by_filter: u64,
    fell_back_to_exact: u64,
    ulp_histogram: &'a UlpHistogram,
    histogram_upper_bounds: bool,
    histogram_settled_exactly: usize,
}

#[derive(serde::Serialize)]
struct WorstJson {
    ulps: f64,
    line: usize,
    coordinates: Vec<CoordJson>,
}

#[derive(serde::Serialize)]
struct FailureJson<'a> {
    line: usize,
    reason: &'a str,
    coordinates: Vec<CoordJson>,
}

#[derive(serde::Serialize)]
struct ClaimedJson {
    decimal: String,
    hex: String,
}

#[derive(serde::Serialize)]
struct CoordJson {
    coordinate: usize,
    claimed: ClaimedJson,
    exact_at_inputs_as_seen: String,
    error_at_inputs_as_seen: Json,
    exact_at_intended_inputs: Option<String>,
    error_at_intended_inputs: Option<Json>,
}

impl From<&FailedCoord> for CoordJson {
    fn from(c: &FailedCoord) -> Self {
        CoordJson {
            coordinate: c.index,
            claimed: ClaimedJson {
                decimal: c.decimal.clone(),
                hex: c.hex.clone(),
            },
            exact_at_inputs_as_seen: c.exact_seen.to_string(),
            error_at_inputs_as_seen: c.seen.to_json(),
            exact_at_intended_inputs: c.exact_intended.as_ref().map(ToString::to_string),
            error_at_intended_inputs: c.intended.as_ref().map(Measures::to_json),
        }
    }
}

impl serde::Serialize for BatchReport {
    /// The layout of `tribez check --format json` (plus `rows` when kept).
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let coords = |cs: &[FailedCoord]| cs.iter().map(CoordJson::from).collect();
        ReportJson {
            results: &self.file,
            patch: &self.patch,
            tolerance: self.tolerance.text(),
            precision: self.precision.map(|p| p.name()),
            summary: SummaryJson {
                claims: self.checked,
                passed: self.passed,
                failed: self.failed,
                filter_used: self.histogram_upper_bounds,
                decided_by_filter: if self.histogram_upper_bounds {
                    self.checked - self.fell_back
                } else {
                    0
                },
                fell_back_to_exact: self.fell_back,
                ulp_histogram: &self.histogram,
                histogram_upper_bounds: self.histogram_upper_bounds,
                histogram_settled_exactly: self.histogram_exact,
            },
            worst: self.worst.as_ref().map(|w| WorstJson {
                ulps: w.ulps,
                line: w.line,
                coordinates: coords(&w.coords),
            }),
            failures: self
                .failures
                .iter()
                .map(|f| FailureJson {
                    line: f.line,
                    reason: &f.reason,
                    coordinates: coords(&f.coords),
                })
                .collect(),
            failures_not_listed: self.failures_not_listed(),
            rows: self.rows.as_deref(),
            baseline_regressions: &self.baseline_regressions,
        }
        .serialize(s)
    }
}

fn coord_text(c: &FailedCoord) -> String {
    let mut s = format!(
        "claimed {} = {}; exact at the inputs as seen {} ({})",
        c.decimal,
        c.hex,
        to_decimal_string(&c.exact_seen, 20),
        c.seen.text()
    );
    if let (Some(e), Some(m)) = (&c.exact_intended, &c.intended) {
        s += &format!(
            "; at the intended inputs {} ({})",
            to_decimal_string(e, 20),
            m.text()
        );
    }
    s
}

impl BatchReport {
    /// The report for people.
    pub fn text(&self) -> String {
        let mut out = format!(
            "{}: {} rows checked against {} (tolerance {}, {})\n",
            self.file,
            self.checked,
            self.patch,
            self.tolerance,
            self.precision
                .map_or("exact numbers".to_string(), |p| format!(
                    "each number the nearest {}",
                    p.name()
                ))
        );
        if self.histogram_upper_bounds {
            out += &format!(
                "  passed {}, failed {}; decided by the float filter {}, fell back to exact arithmetic {}\n",
                self.passed,
                self.failed,
                self.checked - self.fell_back,
                self.fell_back
            );
        } else {
            out += &format!(
                "  passed {}, failed {}; every row computed exactly (no float filter without --precision, or with --cartesian)\n",
                self.passed, self.failed
            );
        }
        if !self.histogram.is_empty() {
            out += &format!(
                "\nErrors in ULPs against the exact value at the inputs as the code saw them{}\n",
                if self.histogram_upper_bounds {
                    " (rows the float filter decided: the upper end of a compensated enclosure of the error; exact where it straddles a bucket boundary)"
                } else {
                    ""
                }
            );
            out += &self.histogram.text();
        }
        if let Some(WorstRow {
            ulps: u,
            line,
            coords,
        }) = &self.worst
        {
            out += &format!(
                "\nworst row (the largest error, computed exactly): line {line}, {} ulp\n",
                crate::number::ulps_decimal(&BigRational::from_float(*u).unwrap_or_default())
            );
            for c in coords {
                out += &format!("  [{}] {}\n", c.index, coord_text(c));
            }
        }
        if !self.failures.is_empty() {
            out += "\nFailures\n";
            for f in &self.failures {
                out += &format!("  line {}: {}\n", f.line, f.reason);
                for c in &f.coords {
                    out += &format!("    [{}] {}\n", c.index, coord_text(c));
                }
            }
            if self.failed as usize > self.failures.len() {
                out += &format!(
                    "  … and {} more\n",
                    self.failed as usize - self.failures.len()
                );
            }
        }
        out += &format!(
            "\n{} claim{}: {} passed, {} failed\n",
            self.checked,
            if self.checked == 1 { "" } else { "s" },
            self.passed,
            self.failed
        );
        for r in &self.baseline_regressions {
            out += &format!("baseline regression: {r}\n");
        }
        out
    }

    /// The report for machines (see the [`serde::Serialize`] impl).
    pub fn json(&self) -> Json {
        serde_json::to_value(self).unwrap_or(Json::Null)
    }
}
