//! In-memory rows: judge float arrays (points and claimed values, row-major `f64`) without any
//! text, and merge reports of disjoint row sets. Added for the Python package (`python/`), which
//! passes numpy arrays; the same engine, verdicts and report as a results file.
//!
//! A row's index plays the part of a file's line number: the report's worst row and failures
//! name rows by index, counted from `first_row` (so that partitions of one set, judged apart
//! with their `first_row`, merge into the report of the whole set).

use rayon::prelude::*;

use super::judge::{RowOutcome, RowScratch};
use super::parse::Num;
use super::report::{BatchReport, FailedRow};
use super::{BatchChecker, BatchError, MAX_CANDIDATES, MAX_LISTED, UlpHistogram};
use crate::float::Precision;
use crate::io::InputError;

/// What one row came to (for per-row arrays).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RowVerdict {
    /// The row's index (counted from `first_row`).
    pub row: usize,
    /// Within the tolerance.
    pub pass: bool,
    /// The float filter could not decide it: judged in exact arithmetic.
    pub fell_back: bool,
    /// The largest error in ULPs over its coordinates at the inputs as seen (exact when
    /// computed exactly, else the upper end of a compensated enclosure; infinite for a
    /// non-finite number).
    pub ulps: f64,
}

impl BatchChecker {
    /// Judge in-memory rows: `points` (`rows × width`, row-major: barycentric coordinates, or
    /// Cartesian with `cartesian`) and `values` (`rows × dimension`), each number the float it is
    /// (rounded to f32 first when the precision is f32). `first_row` is the index of the first row
    /// (rows are named by index in the report, as lines are for a file); `file` and `patch_name`
    /// name the results and the patch in the report. Returns the report and every row's verdict.
    pub fn check_rows(
        &self,
        points: &[f64],
        values: &[f64],
        first_row: usize,
        file: &str,
        patch_name: &str,
    ) -> Result<(BatchReport, Vec<RowVerdict>), BatchError> {
        let p = &self.prepared;
        let (width, dim) = (p.width(), p.patch.net.dim());
        let rows = points.len() / width.max(1);
        if points.len() != rows * width || values.len() != rows * dim {
            return Err(InputError::file(
                file,
                format!(
                    "{} point numbers and {} value numbers are not {rows} rows of {width} and {dim}",
                    points.len(),
                    values.len()
                ),
            )
            .into());
        }
        if rows == 0 {
            return Err(InputError::file(file, "no result rows").into());
        }
        let num = |x: f64| -> Num {
            let x = match p.precision {
                Some(Precision::F32) => f64::from(x as f32),
                _ => x,
            };
            if x.is_finite() {
                Num::Value {
                    float: x,
                    text_exact: crate::number::exact_f64(x),
                }
            } else if x.is_nan() {
                Num::NotFinite("`nan`".into())
            } else {
                Num::NotFinite(format!("`{x}`"))
            }
        };
        let row_nums = |i: usize| -> (Vec<Num>, Vec<Num>) {
            (
                points[i * width..(i + 1) * width]
                    .iter()
                    .map(|&x| num(x))
                    .collect(),
                values[i * dim..(i + 1) * dim]
                    .iter()
                    .map(|&x| num(x))
                    .collect(),
            )
        };
        let outcomes: Vec<RowOutcome> = (0..rows)
            .into_par_iter()
            .map_init(RowScratch::default, |scratch, i| {
                let (inputs, claimed) = row_nums(i);
                let mut o = p.row(first_row + i, inputs, claimed, scratch);
                p.settle_ulps(&mut o, scratch);
                o
            })
            .collect();
        let mut report = BatchReport {
            file: file.into(),
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
        let mut verdicts = Vec::with_capacity(rows);
        let mut floor = 0f64;
        let mut candidates: Vec<(f64, usize)> = Vec::new();
        for (i, o) in outcomes.iter().enumerate() {
            report.rows += 1;
            report.histogram.add(o.ulps);
            report.fell_back += u64::from(o.fell_back);
            report.histogram_exact += usize::from(o.settled_exactly);
            if o.ulps.is_finite() {
                if o.ulps_lower > floor {
                    floor = o.ulps_lower;
                    candidates.retain(|c| c.0 >= floor);
                }
                if o.ulps >= floor && candidates.len() < MAX_CANDIDATES {
                    candidates.push((o.ulps, i));
                }
            }
            if o.pass {
                report.passed += 1;
            } else {
                report.failed += 1;
                if report.failures.len() < MAX_LISTED {
                    report.failures.push(self.failed_row(o));
                }
            }
            verdicts.push(RowVerdict {
                row: o.line,
                pass: o.pass,
                fell_back: o.fell_back,
                ulps: o.ulps,
            });
        }
        // the candidates' exact errors; the first of the largest
        let worst = candidates
            .into_iter()
            .map(|(_, i)| {
                let o = &outcomes[i];
                (p.exact_row(&o.inputs, &o.claimed, None, false).1, i)
            })
            .fold(None, |best: Option<(f64, usize)>, c| match best {
                Some(b) if b.0 >= c.0 => best,
                _ => Some(c),
            });
        if let Some((_, i)) = worst {
            let o = &outcomes[i];
            let (_, u, _, coords) = p.exact_row(&o.inputs, &o.claimed, Some(&texts(o)[..]), true);
            report.worst = Some((u, o.line, coords));
        }
        Ok((report, verdicts))
    }

    fn failed_row(&self, o: &RowOutcome) -> FailedRow {
        let (_, _, reason, coords) =
            self.prepared
                .exact_row(&o.inputs, &o.claimed, Some(&texts(o)[..]), true);
        let reason = o
            .failure
            .clone()
            .filter(|r| !r.is_empty())
            .or(reason)
            .unwrap_or_else(|| "fails".into());
        FailedRow {
            line: o.line,
            reason,
            coords,
        }
    }
}

/// The intended inputs of an in-memory row are the floats themselves (`text_exact` holds their
/// exact values, which take precedence over the text).
fn texts(o: &RowOutcome) -> Vec<&'static str> {
    vec![""; o.inputs.len()]
}

impl BatchReport {
    /// Combine with the report of a disjoint set of rows (judged with the same patch, tolerance
    /// and precision): counts and histograms add; the worst row is the one with the larger error
    /// (on a tie, the smaller row or line number, as a single run keeps the first); the listed
    /// failures are the first [`MAX_LISTED`] by row. Merging the reports of a partition of a set
    /// gives the report of one run over the whole set. `file` stays this report's.
    pub fn merge(&mut self, other: &BatchReport) -> Result<(), String> {
        if self.tolerance != other.tolerance || self.precision != other.precision {
            return Err(format!(
                "reports judged differently (tolerance {} vs {}, precision {:?} vs {:?})",
                self.tolerance, other.tolerance, self.precision, other.precision
            ));
        }
        if self.patch != other.patch {
            return Err(format!(
                "reports about different patches ({} vs {})",
                self.patch, other.patch
            ));
        }
        self.rows += other.rows;
        self.passed += other.passed;
        self.failed += other.failed;
        self.fell_back += other.fell_back;
        for (a, b) in self.histogram.counts.iter_mut().zip(other.histogram.counts) {
            *a += b;
        }
        self.histogram_upper_bounds &= other.histogram_upper_bounds;
        self.histogram_exact += other.histogram_exact;
        let take_other = match (&self.worst, &other.worst) {
            (_, None) => false,
            (None, Some(_)) => true,
            (Some(a), Some(b)) => b.0 > a.0 || (b.0 == a.0 && b.1 < a.1),
        };
        if take_other {
            self.worst = other.worst.clone();
        }
        self.failures.extend(other.failures.iter().cloned());
        self.failures.sort_by_key(|f| f.line);
        self.failures.truncate(MAX_LISTED);
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::batch::{BatchOptions, Format};
    use crate::certify::measures::Tolerance;
    use crate::io::patch_file::read_patch;

    /// In-memory rows give the report a CSV of the same floats gives (hex text, exact), and the
    /// reports of a partition merge into the report of the whole.
    #[test]
    fn rows_equal_the_file_path_and_merge_into_the_whole() {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../fixtures");
        let patch = read_patch(&dir.join("finn_day30.toml")).unwrap();
        let options = BatchOptions {
            tolerance: Tolerance::parse("ulps=1").unwrap(),
            precision: Some(Precision::F64),
            ..BatchOptions::default()
        };
        let checker = BatchChecker::new(patch, &options).unwrap();
        let (mut points, mut values) = (Vec::new(), Vec::new());
        let mut csv = String::new();
        for i in 0..40u32 {
            let u = f64::from(i) / 41.0;
            let v = (1.0 - u) * f64::from((i * 7) % 13) / 13.0;
            let w = 1.0 - u - v;
            // p = (2uv + 2vw, 2uw + 2v² + 2vw + 2w², 4uv + 2vw + w²), some rows nudged
            let mut p = [
                2.0 * u * v + 2.0 * v * w,
                2.0 * u * w + 2.0 * v * v + 2.0 * v * w + 2.0 * w * w,
                4.0 * u * v + 2.0 * v * w + w * w,
            ];
            if i % 9 == 4 {
                p[1] += 4.0 * f64::EPSILON * p[1].abs().max(f64::MIN_POSITIVE);
            }
            points.extend([u, v, w]);
            values.extend(p);
            let row: Vec<String> = [u, v, w, p[0], p[1], p[2]]
                .iter()
                .map(|&x| crate::number::hex_f64(x))
                .collect();
            csv += &(row.join(",") + "\n");
        }
        // a CSV's rows are named by line (1-based), in-memory rows by index: start at 1
        let (rows, verdicts) = checker
            .check_rows(&points, &values, 1, "r.csv", "p")
            .unwrap();
        let file = checker
            .check_reader(csv.as_bytes(), Format::Csv, "r.csv", "p", &mut |_, _| {})
            .unwrap();
        assert_eq!(rows.text(), file.text());
        assert!(rows.failed > 0 && rows.passed > 0);
        assert_eq!(
            verdicts.iter().filter(|v| !v.pass).count() as u64,
            rows.failed
        );
        let (a, _) = checker
            .check_rows(&points[..45], &values[..45], 1, "r.csv", "p")
            .unwrap();
        let (mut b, _) = checker
            .check_rows(&points[45..], &values[45..], 16, "r.csv", "p")
            .unwrap();
        b.merge(&a).unwrap();
        assert_eq!(b.text(), rows.text());
        assert_eq!(b.json(), rows.json());
    }
}
