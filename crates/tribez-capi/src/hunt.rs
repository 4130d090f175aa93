//! The search for the inputs where a C function is least accurate (the library's
//! `tribez::hunt`, what `tribez hunt` runs), with the C function as a callback.

use std::ffi::{c_char, c_int, c_void};

use tribez_lib::hunt::{HuntOptions, HuntReport, hunt};
use tribez_lib::{Precision, Tolerance};

use crate::patch::patch_arg;
use crate::{Failure, status, text_arg, tribez_error, tribez_patch};

/// The function under test: given `rows` rows of inputs (row-major: `m + 1` barycentric
/// coordinates per row, or `m` Cartesian ones with `tribez_hunt_options.cartesian`), it writes
/// `rows` rows of the patch's `d` coordinates to `outputs`. `ctx` is the caller's pointer, passed
/// through. `inputs` is valid only during the call; `outputs` has room for `rows * d` doubles
/// (NaN until written: a row left unwritten fails). The target must not unwind (no C++
/// exception may leave it).
pub type tribez_hunt_target = Option<
    unsafe extern "C" fn(ctx: *mut c_void, inputs: *const f64, rows: usize, outputs: *mut f64),
>;

/// How `tribez_hunt` searches. All zero, or a NULL `opts`, is the default: 10,000 rows, seed
/// 0, barycentric rows, 4,096 rows per call of the target, the 10 worst rows kept.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct tribez_hunt_options {
    /// Rows given to the target, at most (0: 10,000; at most 2^40).
    pub budget: u64,
    /// The seed of the search: the same seed gives the same rows and the same report.
    pub seed: u64,
    /// The rows are the `m` Cartesian coordinates of points of the patch's domain.
    pub cartesian: bool,
    /// The most rows given to the target in one call (0: 4,096; at most 2^20).
    pub batch: usize,
    /// The worst rows the report keeps (0: 10; at most 10,000).
    pub top: usize,
}

/// What a hunt found: the rows evaluated and broken, and the worst rows (worst first). Created
/// by `tribez_hunt`, freed with [`tribez_hunt_report_free`].
pub struct tribez_hunt_report {
    report: HuntReport,
}

/// Hunt for the inputs where `target` is least accurate on a polynomial Bézier patch, judging
/// every row as `tribez_check_f64` would with `tolerance` (the engine of `tribez hunt`).
///
/// The search is deterministic for a seed: uniform points, then the places floats fail
/// (corners, edges, tiny coordinates, binade boundaries, large condition numbers), then local
/// search around the worst rows found, within `opts->budget` rows. `target` is called on the
/// calling thread, one call at a time, with at most `opts->batch` rows.
///
/// On success `*out` is a new report and the return value `TRIBEZ_OK`; on failure (NULL
/// arguments, a bad tolerance, options out of range, a rational patch or S-patch) an error
/// code, `*err` set when `err` is not NULL and `*out` untouched.
///
/// Ownership: `patch`, `tolerance` and `opts` are borrowed for the call; `ctx` is passed to
/// `target` and never dereferenced by tribez. `*out` is the caller's
/// (`tribez_hunt_report_free`); `*err`, when set, too (`tribez_error_free`).
///
/// # Safety
///
/// `patch` is NULL or a live patch; `target` is NULL or a function meeting
/// `tribez_hunt_target`'s contract; `tolerance` NULL or a NUL-terminated string; `opts` NULL or
/// valid; `out` and `err` NULL or valid for a write.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tribez_hunt(
    patch: *const tribez_patch,
    target: tribez_hunt_target,
    ctx: *mut c_void,
    tolerance: *const c_char,
    opts: *const tribez_hunt_options,
    out: *mut *mut tribez_hunt_report,
    err: *mut *mut tribez_error,
) -> c_int {
    // SAFETY: forwarded from the caller.
    unsafe {
        status(err, || {
            let patch = patch_arg(patch, "patch")?;
            let target = target.ok_or_else(|| Failure::null("target"))?;
            if out.is_null() {
                return Err(Failure::null("out"));
            }
            let tolerance = text_arg(tolerance, "tolerance")?;
            let tolerance = Tolerance::parse(tolerance)
                .map_err(|e| Failure::input(format!("tolerance: {e}")))?;
            let o = opts.as_ref().copied();
            let mut options = HuntOptions::new(Precision::F64, tolerance);
            if let Some(o) = o {
                if o.budget != 0 {
                    options.budget = o.budget;
                }
                options.seed = o.seed;
                options.cartesian = o.cartesian;
                if o.batch != 0 {
                    options.batch = o.batch;
                }
                if o.top != 0 {
                    options.top = o.top;
                }
            }
            let d = patch.dimension();
            let width = if options.cartesian {
                patch.simplex_dim()
            } else {
                patch.simplex_dim() + 1
            };
            let mut call = |inputs: &[f64]| -> Result<Vec<f64>, std::convert::Infallible> {
                let rows = inputs.len() / width.max(1);
                let mut outputs = vec![f64::NAN; rows * d];
                target(ctx, inputs.as_ptr(), rows, outputs.as_mut_ptr());
                Ok(outputs)
            };
            let report = hunt(patch, &options, &mut call).map_err(Failure::input)?;
            *out = Box::into_raw(Box::new(tribez_hunt_report { report }));
            Ok(())
        })
    }
}

/// Rows given to the target and judged (0 for NULL).
///
/// Ownership: `report` is borrowed.
///
/// # Safety
///
/// `report` is NULL or a live hunt report.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tribez_hunt_report_evaluated(report: *const tribez_hunt_report) -> u64 {
    // SAFETY: the caller guarantees a live handle or NULL.
    unsafe { report.as_ref() }.map_or(0, |r| r.report.evaluated)
}

/// Rows that broke the tolerance (0 for NULL).
///
/// Ownership: `report` is borrowed.
///
/// # Safety
///
/// `report` is NULL or a live hunt report.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tribez_hunt_report_broke(report: *const tribez_hunt_report) -> u64 {
    // SAFETY: the caller guarantees a live handle or NULL.
    unsafe { report.as_ref() }.map_or(0, |r| r.report.broke)
}

/// The number of worst rows kept (at most `opts->top`; 0 for NULL).
///
/// Ownership: `report` is borrowed.
///
/// # Safety
///
/// `report` is NULL or a live hunt report.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tribez_hunt_report_worst_len(report: *const tribez_hunt_report) -> usize {
    // SAFETY: the caller guarantees a live handle or NULL.
    unsafe { report.as_ref() }.map_or(0, |r| r.report.worst.len())
}

/// The `i`-th worst row (0: the worst): its error in ULPs (computed exactly; infinite for a
/// non-finite answer), and when `input` / `claimed` are not NULL, its input (the row's width:
/// `m + 1`, or `m` Cartesian) and the target's answer (`d` numbers) copied there. Returns the
/// error, or NaN when `report` is NULL or `i` is past the last row (nothing copied).
///
/// Ownership: `report` is borrowed; `input` and `claimed` are the caller's buffers.
///
/// # Safety
///
/// `report` is NULL or a live hunt report; `input` NULL or valid for writing the row's width
/// of doubles; `claimed` NULL or valid for writing `d` doubles.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tribez_hunt_report_worst(
    report: *const tribez_hunt_report,
    i: usize,
    input: *mut f64,
    claimed: *mut f64,
) -> f64 {
    // SAFETY: the caller guarantees a live handle or NULL.
    let Some(row) = unsafe { report.as_ref() }.and_then(|r| r.report.worst.get(i)) else {
        return f64::NAN;
    };
    if !input.is_null() {
        // SAFETY: the caller guarantees room for the row's inputs.
        unsafe { std::ptr::copy_nonoverlapping(row.input.as_ptr(), input, row.input.len()) };
    }
    if !claimed.is_null() {
        // SAFETY: the caller guarantees room for `d` numbers.
        unsafe { std::ptr::copy_nonoverlapping(row.claimed.as_ptr(), claimed, row.claimed.len()) };
    }
    row.ulps
}

/// Free a hunt report (NULL: nothing).
///
/// Ownership: takes `report`; it is invalid afterwards.
///
/// # Safety
///
/// `report` is NULL or a hunt report not yet freed, used by no other thread.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tribez_hunt_report_free(report: *mut tribez_hunt_report) {
    if !report.is_null() {
        // SAFETY: the caller guarantees a live handle from `Box::into_raw`.
        drop(unsafe { Box::from_raw(report) });
    }
}
