//! The batch report: text and JSON (the command line adds JUnit).

use num_rational::BigRational;
use serde_json::{Value as Json, json};

use super::UlpHistogram;
use crate::certify::measures::{Measures, Tolerance};
use crate::float::Precision;
use crate::number::to_decimal_string;

/// A failed row, in full.
#[derive(Clone, Debug)]
pub struct FailedRow {
    pub line: usize,
    pub reason: String,
    pub coords: Vec<FailedCoord>,
}

#[derive(Clone, Debug)]
pub struct FailedCoord {
    pub index: usize,
    pub decimal: String,
    pub hex: String,
    pub exact_seen: BigRational,
    pub seen: Measures,
    pub exact_intended: Option<BigRational>,
    pub intended: Option<Measures>,
}

/// The batch report.
#[derive(Clone, Debug)]
pub struct BatchReport {
    pub file: String,
    pub patch: String,
    pub tolerance: Tolerance,
    pub precision: Option<Precision>,
    pub rows: u64,
    pub passed: u64,
    pub failed: u64,
    pub fell_back: u64,
    pub histogram: UlpHistogram,
    /// Errors of filter-decided rows enter the histogram as the upper ends of their compensated
    /// enclosures.
    pub histogram_upper_bounds: bool,
    /// Filter-decided rows whose error was computed exactly for the histogram (its enclosure
    /// straddled a bucket boundary).
    pub histogram_exact: usize,
    pub worst: Option<(f64, usize, Vec<FailedCoord>)>,
    pub failures: Vec<FailedRow>,
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

fn coord_json(c: &FailedCoord) -> Json {
    json!({
        "coordinate": c.index,
        "claimed": {"decimal": c.decimal, "hex": c.hex},
        "exact_at_inputs_as_seen": c.exact_seen.to_string(),
        "error_at_inputs_as_seen": c.seen.to_json(),
        "exact_at_intended_inputs": c.exact_intended.as_ref().map(ToString::to_string),
        "error_at_intended_inputs": c.intended.as_ref().map(Measures::to_json),
    })
}

impl BatchReport {
    /// The report for people.
    pub fn text(&self) -> String {
        let mut out = format!(
            "{}: {} rows checked against {} (tolerance {}, {})\n",
            self.file,
            self.rows,
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
                self.rows - self.fell_back,
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
        if let Some((u, line, coords)) = &self.worst {
            out += &format!(
                "\nworst row (the largest error, computed exactly): line {line}, {} ulp\n",
                to_decimal_string(&BigRational::from_float(*u).unwrap_or_default(), 4)
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
            self.rows,
            if self.rows == 1 { "" } else { "s" },
            self.passed,
            self.failed
        );
        out
    }

    /// The report for machines.
    pub fn json(&self) -> Json {
        json!({
            "results": self.file,
            "patch": self.patch,
            "tolerance": self.tolerance.text(),
            "precision": self.precision.map(|p| p.name()),
            "summary": {
                "claims": self.rows, "passed": self.passed, "failed": self.failed,
                "filter_used": self.histogram_upper_bounds,
                "decided_by_filter": if self.histogram_upper_bounds { self.rows - self.fell_back } else { 0 }, "fell_back_to_exact": self.fell_back,
                "ulp_histogram": self.histogram.json(), "histogram_upper_bounds": self.histogram_upper_bounds, "histogram_settled_exactly": self.histogram_exact,
            },
            "worst": self.worst.as_ref().map(|(u, line, coords)| json!({"ulps": u, "line": line, "coordinates": coords.iter().map(coord_json).collect::<Vec<_>>()})),
            "failures": self.failures.iter().map(|f| json!({"line": f.line, "reason": f.reason, "coordinates": f.coords.iter().map(coord_json).collect::<Vec<_>>()})).collect::<Vec<_>>(),
            "failures_not_listed": self.failed as usize - self.failures.len(),
        })
    }
}
