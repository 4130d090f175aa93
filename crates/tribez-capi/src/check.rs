//! Judging another implementation's float results with the library's batch engine (what
//! `tribez check --patch P --results FILE` runs), and the reports.

use std::ffi::{c_char, c_int};

use tribez_lib::batch::{BatchChecker, BatchOptions, BatchReport};
use tribez_lib::{Algorithm, Patch, Precision, Tolerance};

use crate::patch::{patch_arg, slice_arg};
use crate::{Failure, c_string, guard, status, text_arg, tribez_error, tribez_patch};

/// `tribez_check_options.algorithm`: de Casteljau's algorithm (the default), whose a-priori
/// error bound the tolerance `bound` uses.
pub const TRIBEZ_ALGORITHM_CASTELJAU: u32 = 0;
/// `tribez_check_options.algorithm`: the Bernstein-sum algorithm.
pub const TRIBEZ_ALGORITHM_BERNSTEIN: u32 = 1;

/// How `tribez_check_f64` and `tribez_check_f32` take their rows. All zero (`{0}` in C, `{}` in
/// C++) is the default, the same as passing NULL: barycentric points, rows numbered from 0, de
/// Casteljau's bound, the rows named `<arrays>` and the patch by its own name.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct tribez_check_options {
    /// The points are the `m` Cartesian coordinates in the patch's domain (a functional patch's
    /// domain, else the reference simplex), instead of `m + 1` barycentric coordinates.
    pub cartesian: bool,
    /// `TRIBEZ_ALGORITHM_CASTELJAU` (0) or `TRIBEZ_ALGORITHM_BERNSTEIN` (1): the algorithm
    /// whose a-priori error bound the tolerance `bound` uses (other tolerances ignore it).
    pub algorithm: u32,
    /// The number of the first row in the report (row `i` is `first_row + i`): give each part of
    /// a larger set its own, and `tribez_report_merge` the reports. 1 numbers the rows as the
    /// lines of a CSV file without comments (what `tribez check --results` reports).
    pub first_row: usize,
    /// The rows' name in the report (NULL: `<arrays>`); the command line shows the results
    /// file's path there.
    pub results_name: *const c_char,
    /// The patch's name in the report (NULL: the patch's `name`, else `the patch`); the command
    /// line shows the patch file's path there.
    pub patch_name: *const c_char,
}

/// The report of a check: the counts, the histogram of errors in ULPs, the worst row and the
/// failures, as `tribez check --results` reports them. Created by `tribez_check_f64` and
/// `tribez_check_f32`, freed with [`tribez_report_free`]. May be read from several threads at
/// once.
pub struct tribez_report {
    report: BatchReport,
    /// What the library's merge does not compare: the patch, the algorithm, the input space.
    key: String,
    /// The row numbers judged, as disjoint ranges `[start, end]`, sorted.
    rows: Vec<(usize, usize)>,
}

/// What a report was judged about, beyond the tolerance, precision and patch name (which the
/// library's merge compares): the patch itself (an FNV-1a hash of its JSON patch file), the
/// algorithm and the input space. Reports merge only with equal keys.
fn judged_key(patch: &Patch, algorithm: Algorithm, cartesian: bool) -> String {
    let hash = patch
        .to_json()
        .bytes()
        .fold(0xcbf2_9ce4_8422_2325u64, |h, b| {
            (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3)
        });
    let algorithm = match algorithm {
        Algorithm::Bernstein => "bernstein",
        _ => "casteljau",
    };
    let space = if cartesian {
        "cartesian"
    } else {
        "barycentric"
    };
    format!("patch {hash:016x}, {algorithm}, {space} points")
}

/// Judge rows (as doubles; f32 rows widened exactly) with `precision`.
///
/// # Safety
///
/// As [`tribez_check_f64`], with `points` and `values` already read.
#[allow(clippy::too_many_arguments)]
unsafe fn check(
    patch: *const tribez_patch,
    points: &dyn Fn(usize) -> Result<Vec<f64>, Failure>,
    values: &dyn Fn(usize) -> Result<Vec<f64>, Failure>,
    tolerance: *const c_char,
    opts: *const tribez_check_options,
    precision: Precision,
    out: *mut *mut tribez_report,
) -> Result<(), Failure> {
    // SAFETY: the caller's guarantees, forwarded.
    let patch = unsafe { patch_arg(patch, "patch") }?;
    if out.is_null() {
        return Err(Failure::null("out"));
    }
    // SAFETY: the caller guarantees a string or NULL.
    let tolerance = unsafe { text_arg(tolerance, "tolerance") }?;
    let tolerance =
        Tolerance::parse(tolerance).map_err(|e| Failure::input(format!("tolerance: {e}")))?;
    // SAFETY: the caller guarantees options or NULL.
    let opts = unsafe { opts.as_ref() }
        .copied()
        .unwrap_or(tribez_check_options {
            cartesian: false,
            algorithm: TRIBEZ_ALGORITHM_CASTELJAU,
            first_row: 0,
            results_name: std::ptr::null(),
            patch_name: std::ptr::null(),
        });
    let algorithm = match opts.algorithm {
        TRIBEZ_ALGORITHM_CASTELJAU => Algorithm::Casteljau,
        TRIBEZ_ALGORITHM_BERNSTEIN => Algorithm::Bernstein,
        other => {
            return Err(Failure::input(format!(
                "algorithm: {other} is not an algorithm (TRIBEZ_ALGORITHM_CASTELJAU = 0 or TRIBEZ_ALGORITHM_BERNSTEIN = 1)"
            )));
        }
    };
    let results_name = if opts.results_name.is_null() {
        "<arrays>"
    } else {
        // SAFETY: the caller guarantees a string.
        unsafe { text_arg(opts.results_name, "results_name") }?
    };
    let poly = patch.polynomial().cloned().ok_or_else(|| {
        Failure::input(format!(
            "patch: check judges polynomial Bézier patches, not {} (for those: claim files)",
            patch.kind().plural()
        ))
    })?;
    let patch_name = if opts.patch_name.is_null() {
        patch.name().unwrap_or("the patch").to_string()
    } else {
        // SAFETY: the caller guarantees a string.
        unsafe { text_arg(opts.patch_name, "patch_name") }?.to_string()
    };
    let m = patch.simplex_dim();
    let width = if opts.cartesian { m } else { m + 1 };
    let points = points(width)?;
    let values = values(patch.dimension())?;
    let options = BatchOptions {
        tolerance,
        precision: Some(precision),
        algorithm,
        cartesian: opts.cartesian,
        row_detail: false,
    };
    let key = judged_key(patch, algorithm, opts.cartesian);
    let checker = BatchChecker::new(poly, &options).map_err(Failure::input)?;
    let (report, _) = checker
        .check_rows(&points, &values, opts.first_row, results_name, &patch_name)
        .map_err(Failure::input)?;
    let rows = vec![(opts.first_row, opts.first_row + report.checked as usize - 1)];
    let report = Box::new(tribez_report { report, key, rows });
    // SAFETY: `out` is not NULL and the caller guarantees it is valid for a write.
    unsafe { *out = Box::into_raw(report) };
    Ok(())
}

/// `rows * per_row` numbers of `T` at `ptr`, widened to doubles.
///
/// # Safety
///
/// `ptr` is NULL or valid for reading `rows * per_row` elements.
unsafe fn rows_of<T: Copy + Into<f64>>(
    ptr: *const T,
    rows: usize,
    per_row: usize,
    what: &str,
) -> Result<Vec<f64>, Failure> {
    let len = rows.checked_mul(per_row).ok_or_else(|| {
        Failure::input(format!(
            "{what}: {rows} rows of {per_row} numbers pass the largest size"
        ))
    })?;
    // SAFETY: forwarded from the caller.
    let xs = unsafe { slice_arg(ptr, len, what) }?;
    Ok(xs.iter().map(|&x| x.into()).collect())
}

/// Judge float results of another implementation against the exact values of a polynomial
/// Bézier patch: the engine and the report of `tribez check --patch P --results FILE
/// --precision f64 --tolerance T`.
///
/// `points`: `rows` rows of `m + 1` barycentric coordinates (`m` Cartesian ones with
/// `opts->cartesian`), row-major, each double the input as the code under test saw it;
/// `values`: `rows` rows of `d` claimed coordinates (`d = tribez_patch_dimension(patch)`),
/// row-major. Each claimed value is judged against the exact value at the inputs as seen (the
/// patch's homogeneous form: barycentric inputs need not sum to 1). NaN and infinities are
/// failed rows, not errors.
///
/// `tolerance`: as the command line's `--tolerance`: `exact`, `correctly_rounded`, `faithful`,
/// `ulps=N`, `abs=E`, `rel=E`, `cond=K` (K times the condition number's bound), `bound` (the
/// algorithm's a-priori bound). `opts`: NULL for the defaults (see `tribez_check_options`).
///
/// On success `*out` is a new report (whether or not every row passed: ask
/// `tribez_report_ok`) and the return value `TRIBEZ_OK`; on failure (NULL arguments, a bad
/// tolerance, `rows == 0`, a rational patch or S-patch, an unknown algorithm) an error code,
/// `*err` set when `err` is not NULL and `*out` untouched.
///
/// The rows are judged on every core (rayon's global pool); the call returns when all are.
///
/// Ownership: `patch`, `points`, `values`, `tolerance`, `opts` (and its strings) are borrowed
/// for the call. `*out` is the caller's (`tribez_report_free`); it does not refer to `patch`.
/// `*err`, when set, is the caller's (`tribez_error_free`).
///
/// # Safety
///
/// `patch` is NULL or a live patch; `points` is NULL or valid for reading `rows * (m + 1)`
/// doubles (`rows * m` with `opts->cartesian`), `values` NULL or valid for reading `rows * d`;
/// `tolerance` NULL or a NUL-terminated string; `opts` NULL or valid options whose strings are
/// NULL or NUL-terminated; `out` NULL or valid for a write; `err` NULL or valid for a write.
#[unsafe(no_mangle)]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn tribez_check_f64(
    patch: *const tribez_patch,
    points: *const f64,
    values: *const f64,
    rows: usize,
    tolerance: *const c_char,
    opts: *const tribez_check_options,
    out: *mut *mut tribez_report,
    err: *mut *mut tribez_error,
) -> c_int {
    // SAFETY: forwarded from the caller.
    unsafe {
        status(err, || {
            check(
                patch,
                &|w| rows_of(points, rows, w, "points"),
                &|d| rows_of(values, rows, d, "values"),
                tolerance,
                opts,
                Precision::F64,
                out,
            )
        })
    }
}

/// `tribez_check_f64` for single-precision code: the points and values are floats (each
/// widened exactly), judged as `tribez check --precision f32` judges them (ULPs of f32).
///
/// Ownership: as `tribez_check_f64`.
///
/// # Safety
///
/// As `tribez_check_f64`, with floats instead of doubles.
#[unsafe(no_mangle)]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn tribez_check_f32(
    patch: *const tribez_patch,
    points: *const f32,
    values: *const f32,
    rows: usize,
    tolerance: *const c_char,
    opts: *const tribez_check_options,
    out: *mut *mut tribez_report,
    err: *mut *mut tribez_error,
) -> c_int {
    // SAFETY: forwarded from the caller.
    unsafe {
        status(err, || {
            check(
                patch,
                &|w| rows_of(points, rows, w, "points"),
                &|d| rows_of(values, rows, d, "values"),
                tolerance,
                opts,
                Precision::F32,
                out,
            )
        })
    }
}

/// The report behind a handle, or None for NULL.
///
/// # Safety
///
/// `r` is NULL or a live report.
unsafe fn report_ref<'a>(r: *const tribez_report) -> Option<&'a tribez_report> {
    // SAFETY: the caller guarantees a live handle or NULL.
    unsafe { r.as_ref() }
}

/// Rows that met the tolerance (0 for NULL).
///
/// Ownership: `report` is borrowed.
///
/// # Safety
///
/// `report` is NULL or a live report.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tribez_report_passed(report: *const tribez_report) -> u64 {
    // SAFETY: forwarded from the caller.
    unsafe { report_ref(report) }.map_or(0, |r| r.report.passed)
}

/// Rows that did not (0 for NULL).
///
/// Ownership: `report` is borrowed.
///
/// # Safety
///
/// `report` is NULL or a live report.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tribez_report_failed(report: *const tribez_report) -> u64 {
    // SAFETY: forwarded from the caller.
    unsafe { report_ref(report) }.map_or(0, |r| r.report.failed)
}

/// Rows checked (passed + failed; 0 for NULL).
///
/// Ownership: `report` is borrowed.
///
/// # Safety
///
/// `report` is NULL or a live report.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tribez_report_checked(report: *const tribez_report) -> u64 {
    // SAFETY: forwarded from the caller.
    unsafe { report_ref(report) }.map_or(0, |r| r.report.checked)
}

/// Rows the float filter could not decide, judged in exact big-integer arithmetic (0 for
/// NULL).
///
/// Ownership: `report` is borrowed.
///
/// # Safety
///
/// `report` is NULL or a live report.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tribez_report_fell_back(report: *const tribez_report) -> u64 {
    // SAFETY: forwarded from the caller.
    unsafe { report_ref(report) }.map_or(0, |r| r.report.fell_back)
}

/// True when no row failed (false for NULL): the command line's exit status 0.
///
/// Ownership: `report` is borrowed.
///
/// # Safety
///
/// `report` is NULL or a live report.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tribez_report_ok(report: *const tribez_report) -> bool {
    // SAFETY: forwarded from the caller.
    unsafe { report_ref(report) }.is_some_and(|r| r.report.failed == 0)
}

/// The largest error in ULPs over the rows with finite numbers (that of the worst row,
/// computed exactly); NaN when there is none (every row had a NaN or an infinity) or for NULL.
///
/// Ownership: `report` is borrowed.
///
/// # Safety
///
/// `report` is NULL or a live report.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tribez_report_max_ulps(report: *const tribez_report) -> f64 {
    // SAFETY: forwarded from the caller.
    unsafe { report_ref(report) }
        .and_then(|r| r.report.max_ulps)
        .unwrap_or(f64::NAN)
}

/// The number of the row with the largest error (ties: the smallest number), counted from
/// `first_row`: stored in `*row` with true returned; false (and `*row` untouched) when there is
/// none, or for NULL arguments.
///
/// Ownership: `report` is borrowed; `row` is the caller's.
///
/// # Safety
///
/// `report` is NULL or a live report; `row` is NULL or valid for a write.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tribez_report_worst_row(
    report: *const tribez_report,
    row: *mut usize,
) -> bool {
    // SAFETY: forwarded from the caller.
    let worst = unsafe { report_ref(report) }.and_then(|r| r.report.worst.as_ref());
    match worst {
        Some(w) if !row.is_null() => {
            // SAFETY: `row` is not NULL and the caller guarantees it is valid for a write.
            unsafe { *row = w.line };
            true
        }
        _ => false,
    }
}

/// The report for people: the text `tribez check --results` prints, byte for byte (with the
/// rows named by `opts->results_name`, the patch by `opts->patch_name`, and rows numbered from
/// `opts->first_row`); NULL for a NULL `report`.
///
/// Ownership: `report` is borrowed. The string is the caller's: free it with
/// `tribez_string_free`.
///
/// # Safety
///
/// `report` is NULL or a live report.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tribez_report_text(report: *const tribez_report) -> *mut c_char {
    // SAFETY: forwarded from the caller; a panic gives NULL.
    unsafe {
        guard(std::ptr::null_mut(), std::ptr::null_mut(), || {
            Ok(report_ref(report).map_or(std::ptr::null_mut(), |r| c_string(r.report.text())))
        })
    }
}

/// The report for machines: the JSON `tribez check --results --format json` prints, byte for
/// byte (pretty-printed, with a final newline); NULL for a NULL `report`.
///
/// Ownership: `report` is borrowed. The string is the caller's: free it with
/// `tribez_string_free`.
///
/// # Safety
///
/// `report` is NULL or a live report.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tribez_report_json(report: *const tribez_report) -> *mut c_char {
    // SAFETY: forwarded from the caller; a panic gives NULL.
    unsafe {
        guard(std::ptr::null_mut(), std::ptr::null_mut(), || {
            Ok(report_ref(report).map_or(std::ptr::null_mut(), |r| {
                let json = serde_json::to_value(&r.report).unwrap_or(serde_json::Value::Null);
                c_string(format!("{json:#}\n"))
            }))
        })
    }
}

/// Merge `other` into `into`: afterwards `into` is the report of the union of their rows, the
/// same as one check of all of them (counts and histograms add, the worst row is the larger
/// error, ties to the smaller row number, the listed failures are the first by row number).
/// Check the parts with the same patch, tolerance, precision, algorithm and input space, and
/// give each its `first_row` so that their rows are disjoint.
///
/// Returns `TRIBEZ_OK`, or an error code (`*err` set when `err` is not NULL; `into`
/// unchanged): reports judged differently, or sharing a row number.
///
/// Ownership: `into` is borrowed and changed (no other thread may use it meanwhile); `other`
/// is borrowed, unchanged, and stays the caller's to free. `*err`, when set, is the caller's
/// (`tribez_error_free`).
///
/// # Safety
///
/// `into` is NULL or a live report; `other` is NULL or a live report; `err` is NULL or valid
/// for a write.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tribez_report_merge(
    into: *mut tribez_report,
    other: *const tribez_report,
    err: *mut *mut tribez_error,
) -> c_int {
    // SAFETY: forwarded from the caller.
    unsafe {
        status(err, || {
            let other = report_ref(other).ok_or_else(|| Failure::null("other"))?;
            let into = into.as_mut().ok_or_else(|| Failure::null("into"))?;
            if std::ptr::eq(into, other) {
                return Err(Failure::input(
                    "merge: a report cannot be merged with itself (its rows would be counted twice)",
                ));
            }
            if into.key != other.key {
                return Err(Failure::input(format!(
                    "merge: reports judged differently ({} vs {})",
                    into.key, other.key
                )));
            }
            for &(a, b) in &other.rows {
                if let Some(&(c, _)) = into.rows.iter().find(|&&(c, d)| a <= d && c <= b) {
                    let row = a.max(c);
                    return Err(Failure::input(format!(
                        "merge: both reports have row {row}: merge reports of disjoint row sets (give each part its first_row)"
                    )));
                }
            }
            let mut report = into.report.clone();
            report
                .merge(&other.report)
                .map_err(|e| Failure::input(format!("merge: {e}")))?;
            into.report = report;
            into.rows.extend(other.rows.iter().copied());
            into.rows.sort_unstable();
            Ok(())
        })
    }
}

/// Free a report (NULL: nothing).
///
/// Ownership: takes `report`; it is invalid afterwards.
///
/// # Safety
///
/// `report` is NULL or a report from tribez not yet freed, used by no other thread.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tribez_report_free(report: *mut tribez_report) {
    if !report.is_null() {
        // SAFETY: the caller guarantees a live handle from `Box::into_raw`.
        drop(unsafe { Box::from_raw(report) });
    }
}
