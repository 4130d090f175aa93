//! Batches of another implementation's lookups, judged (`tribez check --mesh MESH --results
//! FILE`): rows `x, y, value`. Each row goes to the lowest-numbered triangle containing its
//! point *as the code saw it* (the floats, with a precision) and is judged there exactly as
//! `check --patch TRIANGLE --cartesian --results` judges it, with every tolerance
//! ([`crate::batch`]). By C0 every triangle containing the point gives the same exact value;
//! the error at the intended point is measured with the same triangle's polynomial. A point
//! outside the mesh is a failed row.

use std::io::Read;
use std::sync::OnceLock;

use num_rational::BigRational;

use super::routed::{Route, Routing, check_routed};
use super::{
    BatchChecker, BatchError, BatchOptions, BatchReport, Format, ResultsChecker, UlpHistogram,
};
use crate::any_patch::AnyPatch;
use crate::mesh::Mesh;

/// Judges batches of lookups in one mesh (one batch checker per triangle, built on first use).
pub struct MeshBatchChecker {
    mesh: Mesh,
    options: BatchOptions,
    /// `None`: the triangle's ordinates overflow the precision.
    checkers: Vec<OnceLock<Option<BatchChecker>>>,
}

impl MeshBatchChecker {
    /// Prepare to judge lookups in `mesh` with `options` (`cartesian` is implied). An invalid
    /// mesh is an error (its first problem, [`Mesh::check`]).
    pub fn new(mesh: Mesh, options: &BatchOptions) -> Result<Self, BatchError> {
        if let Some(problem) = mesh.check().into_iter().next() {
            return Err(BatchError::Mesh(problem));
        }
        if options.tolerance.needs_precision() && options.precision.is_none() {
            return Err(BatchError::ToleranceNeedsPrecision {
                tolerance: options.tolerance.clone(),
            });
        }
        let options = BatchOptions {
            cartesian: true,
            row_detail: false,
            ..options.clone()
        };
        let checkers = (0..mesh.triangles().len())
            .map(|_| OnceLock::new())
            .collect();
        Ok(MeshBatchChecker {
            mesh,
            options,
            checkers,
        })
    }

    fn checker(&self, t: usize) -> Result<&BatchChecker, BatchError> {
        let built = self.checkers[t].get_or_init(|| {
            // A valid mesh has every ordinate: the patch exists.
            let AnyPatch::Functional(p) = self.mesh.triangle_patch(t).ok()?.into_any() else {
                return None;
            };
            BatchChecker::new(p, &self.options).ok()
        });
        built.as_ref().ok_or(BatchError::ControlPointOverflows {
            precision: self
                .options
                .precision
                .unwrap_or(crate::float::Precision::F64),
        })
    }
}

/// Rows `x, y, value` (another implementation's lookups, from a file, memory or a pipe);
/// `subject` names the mesh in the report.
impl ResultsChecker for MeshBatchChecker {
    type Report = BatchReport;

    fn check_reader<R: Read + Send>(
        &self,
        reader: R,
        format: Format,
        file: &str,
        subject: &str,
        progress: &mut dyn FnMut(u64, u64),
    ) -> Result<BatchReport, BatchError> {
        let n = self.mesh.degree();
        let template = BatchReport {
            file: file.into(),
            patch: subject.into(),
            tolerance: self.options.tolerance.for_patch(2, n),
            precision: self.options.precision,
            checked: 0,
            passed: 0,
            failed: 0,
            fell_back: 0,
            histogram: UlpHistogram::default(),
            histogram_upper_bounds: self.options.precision.is_some(),
            histogram_exact: 0,
            max_ulps: None,
            worst: None,
            failures: Vec::new(),
            rows: None,
            baseline_regressions: Vec::new(),
        };
        let route = |seen: &[Option<BigRational>]| -> Route {
            let (Some(x), Some(y)) = (&seen[0], &seen[1]) else {
                return Route::Fails("the point is not a finite number".into());
            };
            match self.mesh.locate(&[x.clone(), y.clone()]).first() {
                Some(l) => Route::To(l.triangle),
                None => Route::Fails(format!("the point ({x}, {y}) is outside the mesh")),
            }
        };
        let checker = |t: usize| self.checker(t);
        let routing = Routing {
            width: 2,
            dim: 1,
            precision: self.options.precision,
            template,
            route: &route,
            checker: &checker,
        };
        check_routed(reader, format, file, routing, progress)
    }
}
