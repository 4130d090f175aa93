//! Routed batches: each row judged by one of several checkers, chosen from its inputs as the
//! code saw them (what `tribez check --mesh MESH --results FILE` runs: a row goes to the
//! triangle containing its point). Streamed in chunks like [`super::BatchChecker::check_file`];
//! within a chunk the rows are routed in parallel, then each checker judges its rows in
//! parallel, and the reports are merged ([`BatchReport::merge`], rows keep their numbers).

use std::io::{BufReader, Read};

use num_rational::BigRational;
use rayon::prelude::*;

use super::parse::{Num, RowReader, each_chunk, parse_row};
use super::{Accumulator, BatchChecker, BatchError, BatchReport, FailedRow, Format};
use crate::float::Precision;
use crate::io::InputError;

/// Where a row goes.
pub enum Route {
    /// To checker `k`.
    To(usize),
    /// Nowhere: a failed row with this reason (a point outside the mesh).
    Fails(String),
}

impl BatchChecker {
    /// Judge rows of a chunk (`(row, column, text)` as read), in parallel, into a report.
    fn judge_texts(
        &self,
        rows: &[(usize, usize, &str)],
        format: Format,
        file: &str,
        patch_name: &str,
    ) -> Result<BatchReport, InputError> {
        let mut acc = Accumulator::new(&self.prepared, file, patch_name, Some(format));
        let slabs = acc.judge_slabs(rows, format, false);
        acc.merge(slabs, rows, None)?;
        Ok(acc.finish())
    }
}

/// How the rows of a routed batch are read and judged: each row has `width` inputs and `dim`
/// claimed numbers and is judged by `checker(route(inputs as seen))`; `checker(k)` may build
/// checker `k` on first use. `template` gives the report's tolerance, precision, file and patch
/// names (for the rows that fail to route, and for merging).
pub struct Routing<'a, 'c> {
    pub width: usize,
    pub dim: usize,
    pub precision: Option<Precision>,
    pub template: BatchReport,
    pub route: &'a (dyn Fn(&[Option<BigRational>]) -> Route + Sync),
    pub checker: &'a (dyn Fn(usize) -> Result<&'c BatchChecker, BatchError> + Sync),
}

/// Check the rows read from `reader` in `format` (`file` names it in errors) as `routing` says.
pub fn check_routed<R: Read + Send>(
    reader: R,
    format: Format,
    file: &str,
    routing: Routing<'_, '_>,
    progress: &mut dyn FnMut(u64, u64),
) -> Result<BatchReport, BatchError> {
    let Routing {
        width,
        dim,
        precision,
        template,
        route,
        checker,
    } = routing;
    let mut reader = RowReader::new(BufReader::with_capacity(1 << 20, reader), format, file)
        .expect_columns(width + dim);
    let mut total = template.clone();
    each_chunk(&mut reader, file, progress, |rows| {
        let routes: Vec<Option<Route>> = rows
            .par_iter()
            .map(|&(no, col, text)| -> Result<Option<Route>, InputError> {
                let Some((inputs, _)) =
                    parse_row(format, text, no, col, width, dim, precision, file)?
                else {
                    return Ok(None);
                };
                let seen: Vec<Option<BigRational>> = inputs
                    .iter()
                    .map(|x| match x {
                        Num::Value { float, text_exact } => match precision {
                            Some(_) => crate::number::exact_f64(*float),
                            None => text_exact.clone(),
                        },
                        Num::NotFinite(..) => None,
                    })
                    .collect();
                Ok(Some(route(&seen)))
            })
            .collect::<Result<_, _>>()?;
        let mut groups: std::collections::BTreeMap<usize, Vec<(usize, usize, &str)>> =
            Default::default();
        let mut failed = template.clone();
        for (r, row) in routes.into_iter().zip(rows) {
            match r {
                None => {}
                Some(Route::To(k)) => groups.entry(k).or_default().push(*row),
                Some(Route::Fails(reason)) => {
                    failed.checked += 1;
                    failed.failed += 1;
                    failed.histogram.add(f64::INFINITY);
                    if failed.failures.len() < super::MAX_LISTED {
                        failed.failures.push(FailedRow {
                            line: row.0,
                            reason,
                            coords: Vec::new(),
                        });
                    }
                }
            }
        }
        total.merge(&failed)?;
        for (k, rows) in groups {
            let part = checker(k)?.judge_texts(&rows, format, file, &template.patch)?;
            total.merge(&part)?;
        }
        Ok((total.checked, total.failed))
    })?;
    Ok(total)
}
