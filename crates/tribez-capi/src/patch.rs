//! Patches: read from a file or a text, or built from doubles; their sizes; exact and correctly
//! rounded evaluation.

use std::ffi::{c_char, c_int};

use num_rational::BigRational;
use num_traits::ToPrimitive;
use tribez_lib::{Degree, Patch, SimplexDim, parse_rational};

use crate::{Failure, c_string, guard, status, text_arg, tribez_error};

pub(crate) use tribez_lib::limits::{MAX_CONTROL_POINTS, MAX_DEGREE, MAX_SIMPLEX_DIMENSION};

/// A patch of any kind (Bézier, rational, functional, S-patch), immutable once made. Created by
/// `tribez_patch_from_*`, freed with [`tribez_patch_free`]. May be read from several threads
/// at once.
pub struct tribez_patch {
    pub(crate) inner: Patch,
}

/// A new handle for `patch`.
fn handle(patch: Patch) -> *mut tribez_patch {
    Box::into_raw(Box::new(tribez_patch { inner: patch }))
}

/// The patch behind a handle argument `what`.
///
/// # Safety
///
/// `p` is NULL or a live patch handle.
pub(crate) unsafe fn patch_arg<'a>(
    p: *const tribez_patch,
    what: &str,
) -> Result<&'a Patch, Failure> {
    // SAFETY: the caller guarantees a live handle or NULL.
    unsafe { p.as_ref() }
        .map(|p| &p.inner)
        .ok_or_else(|| Failure::null(what))
}

/// `len` elements at `ptr` (argument `what`); NULL is an error even for `len == 0`.
///
/// # Safety
///
/// `ptr` is NULL or valid for reading `len` elements that outlive the call.
pub(crate) unsafe fn slice_arg<'a, T>(
    ptr: *const T,
    len: usize,
    what: &str,
) -> Result<&'a [T], Failure> {
    if ptr.is_null() {
        return Err(Failure::null(what));
    }
    if len > isize::MAX as usize / std::mem::size_of::<T>().max(1) {
        return Err(Failure::input(format!(
            "{what}: {len} elements pass the largest size of an array"
        )));
    }
    // SAFETY: the caller guarantees `len` readable elements.
    Ok(unsafe { std::slice::from_raw_parts(ptr, len) })
}

/// The exact value of a double, or why it has none (`what` names it).
pub(crate) fn exact(x: f64, what: &dyn Fn() -> String) -> Result<BigRational, Failure> {
    BigRational::from_float(x).ok_or_else(|| {
        let which = if x.is_nan() {
            "NaN"
        } else if x > 0.0 {
            "infinity"
        } else {
            "-infinity"
        };
        Failure::input(format!("{}: {which} has no exact value", what()))
    })
}

/// Read a patch file (`.toml` or `.json`, any kind of patch; docs/guide.md §3).
///
/// Returns a new patch, or NULL on failure (`*err` set when `err` is not NULL): an unreadable
/// file or a bad patch gives the command line's message, naming the file, the line and key.
///
/// Ownership: `path` (a NUL-terminated path) is borrowed for the call. The returned patch is
/// the caller's: free it with `tribez_patch_free`. `*err`, when set, is the caller's: free it
/// with `tribez_error_free`.
///
/// # Safety
///
/// `path` is NULL or a NUL-terminated string; `err` is NULL or valid for a write.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tribez_patch_from_file(
    path: *const c_char,
    err: *mut *mut tribez_error,
) -> *mut tribez_patch {
    // SAFETY: forwarded from the caller.
    unsafe {
        guard(err, std::ptr::null_mut(), || {
            if path.is_null() {
                return Err(Failure::null("path"));
            }
            let path = path_of(path);
            let patch = Patch::from_file(&path).map_err(Failure::input)?;
            Ok(handle(patch))
        })
    }
}

/// The path of a NUL-terminated string: its bytes as they are on Unix.
///
/// # Safety
///
/// `p` is a NUL-terminated string.
unsafe fn path_of(p: *const c_char) -> std::path::PathBuf {
    // SAFETY: the caller guarantees a NUL-terminated string.
    let c = unsafe { std::ffi::CStr::from_ptr(p) };
    #[cfg(unix)]
    {
        use std::os::unix::ffi::OsStrExt;
        std::ffi::OsStr::from_bytes(c.to_bytes()).into()
    }
    #[cfg(not(unix))]
    {
        c.to_string_lossy().into_owned().into()
    }
}

/// Read a patch from the text of a patch file: `format` is `"toml"` or `"json"`.
///
/// Returns a new patch, or NULL on failure (`*err` set when `err` is not NULL); errors name
/// `<toml>` or `<json>` and the line.
///
/// Ownership: `text` and `format` (NUL-terminated, UTF-8) are borrowed for the call. The
/// returned patch is the caller's (`tribez_patch_free`); `*err`, when set, too
/// (`tribez_error_free`).
///
/// # Safety
///
/// `text` and `format` are NULL or NUL-terminated strings; `err` is NULL or valid for a write.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tribez_patch_from_text(
    text: *const c_char,
    format: *const c_char,
    err: *mut *mut tribez_error,
) -> *mut tribez_patch {
    // SAFETY: forwarded from the caller.
    unsafe {
        guard(err, std::ptr::null_mut(), || {
            let text = text_arg(text, "text")?;
            let format = text_arg(format, "format")?;
            let patch = match format {
                "toml" => Patch::from_toml(text),
                "json" => Patch::from_json(text),
                other => {
                    return Err(Failure::input(format!(
                        "format: `{other}` is not a patch format (expected \"toml\" or \"json\")"
                    )));
                }
            }
            .map_err(Failure::input)?;
            Ok(handle(patch))
        })
    }
}

/// `C(n + m, m)`, or None past `MAX_CONTROL_POINTS`.
fn control_point_count(m: usize, n: usize) -> Option<usize> {
    let mut c: u128 = 1;
    for i in 1..=m as u128 {
        c = c.checked_mul(n as u128 + i)? / i;
    }
    usize::try_from(c).ok().filter(|&c| c <= MAX_CONTROL_POINTS)
}

/// A polynomial Bézier simplex from doubles, each taken exactly (the double's own value, no
/// rounding): degree `degree` over the `m`-simplex (`m = 2`: a triangle), points in
/// `R^d`.
///
/// `control_points` holds `C(degree + m, m) * d` doubles: control point after control point,
/// `d` coordinates each. The control points are in the canonical order of the patch files:
/// multi-indices `(a_0, …, a_m)` with `a_0 + … + a_m = degree`, ordered by `a_m` ascending,
/// then `a_(m-1)` ascending, and so on (`a_0` is what is left). Quadratic triangle: 200, 110,
/// 020, 101, 011, 002; cubic triangle: 300, 210, 120, 030, 201, 111, 021, 102, 012, 003.
///
/// Limits (those of the patch files): `1 <= m <= 16`, `degree <= 200`, at most 250,000 control
/// points, `d >= 1`. A NaN or an infinity is an error naming its index.
///
/// Returns a new patch, or NULL on failure (`*err` set when `err` is not NULL).
///
/// Ownership: `control_points` is borrowed for the call (copied). The returned patch is the
/// caller's (`tribez_patch_free`); `*err`, when set, too (`tribez_error_free`).
///
/// # Safety
///
/// `control_points` is NULL or valid for reading `C(degree + m, m) * d` doubles; `err` is NULL
/// or valid for a write.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tribez_patch_from_f64(
    m: usize,
    degree: usize,
    d: usize,
    control_points: *const f64,
    err: *mut *mut tribez_error,
) -> *mut tribez_patch {
    // SAFETY: forwarded from the caller.
    unsafe {
        guard(err, std::ptr::null_mut(), || {
            if m == 0 || m > MAX_SIMPLEX_DIMENSION {
                return Err(Failure::input(format!(
                    "m: {m} is not a simplex dimension (1 to {MAX_SIMPLEX_DIMENSION})"
                )));
            }
            if degree > MAX_DEGREE {
                return Err(Failure::input(format!(
                    "degree: {degree} is above the limit of {MAX_DEGREE}"
                )));
            }
            if d == 0 {
                return Err(Failure::input(
                    "d: 0 coordinates (a control point has at least one)",
                ));
            }
            let count = control_point_count(m, degree).ok_or_else(|| {
                Failure::input(format!(
                    "degree {degree} over the {m}-simplex has more than {MAX_CONTROL_POINTS} control points (the limit)"
                ))
            })?;
            let total = count.checked_mul(d).ok_or_else(|| {
                Failure::input(format!(
                    "{count} control points of {d} coordinates pass the largest size"
                ))
            })?;
            let xs = slice_arg(control_points, total, "control_points")?;
            let mut net = Vec::with_capacity(count);
            for (i, point) in xs.chunks_exact(d).enumerate() {
                let coords = point
                    .iter()
                    .enumerate()
                    .map(|(j, &x)| {
                        exact(x, &|| {
                            format!(
                                "control_points[{}] (control point {i}, coordinate {j})",
                                i * d + j
                            )
                        })
                    })
                    .collect::<Result<Vec<_>, _>>()?;
                net.push(coords);
            }
            let patch =
                Patch::bezier(SimplexDim(m), Degree(degree), net).map_err(Failure::input)?;
            Ok(handle(patch))
        })
    }
}

/// Free a patch (NULL: nothing).
///
/// Ownership: takes `patch`; it is invalid afterwards. Reports made with it stay valid.
///
/// # Safety
///
/// `patch` is NULL or a patch from tribez not yet freed, used by no other thread.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tribez_patch_free(patch: *mut tribez_patch) {
    if !patch.is_null() {
        // SAFETY: the caller guarantees a live handle from `Box::into_raw`.
        drop(unsafe { Box::from_raw(patch) });
    }
}

/// The simplex dimension `m` of the patch's control net (2 for a triangle; an S-patch over an
/// N-gon: N - 1); 0 for a NULL `patch`.
///
/// Ownership: `patch` is borrowed.
///
/// # Safety
///
/// `patch` is NULL or a live patch.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tribez_patch_simplex_dim(patch: *const tribez_patch) -> usize {
    // SAFETY: the caller guarantees a live handle or NULL.
    unsafe { patch.as_ref() }.map_or(0, |p| p.inner.simplex_dim())
}

/// The patch's degree `n` (an S-patch's depth); 0 for a NULL `patch`.
///
/// Ownership: `patch` is borrowed.
///
/// # Safety
///
/// `patch` is NULL or a live patch.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tribez_patch_degree(patch: *const tribez_patch) -> usize {
    // SAFETY: the caller guarantees a live handle or NULL.
    unsafe { patch.as_ref() }.map_or(0, |p| p.inner.degree())
}

/// The dimension `d` of the patch's points (the number of values an evaluation gives); 0 for
/// a NULL `patch`.
///
/// Ownership: `patch` is borrowed.
///
/// # Safety
///
/// `patch` is NULL or a live patch.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tribez_patch_dimension(patch: *const tribez_patch) -> usize {
    // SAFETY: the caller guarantees a live handle or NULL.
    unsafe { patch.as_ref() }.map_or(0, |p| p.inner.dimension())
}

/// How many numbers a point of the patch's domain has for evaluation: `m + 1` barycentric
/// coordinates (2 Cartesian ones for an S-patch); 0 for a NULL `patch`.
///
/// Ownership: `patch` is borrowed.
///
/// # Safety
///
/// `patch` is NULL or a live patch.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tribez_patch_point_len(patch: *const tribez_patch) -> usize {
    // SAFETY: the caller guarantees a live handle or NULL.
    unsafe { patch.as_ref() }.map_or(0, |p| p.inner.shape().input.len())
}

/// Check a point's length against the patch's.
fn check_point_len(patch: &Patch, len: usize) -> Result<(), Failure> {
    let want = patch.shape().input.len();
    if len != want {
        return Err(Failure::input(format!(
            "point: {len} coordinates, but a point of this patch has {want}"
        )));
    }
    Ok(())
}

/// The exact value of the patch at an exact point, as strings.
///
/// `point` holds `point_len` NUL-terminated exact numbers (`"1/3"`, `"0.25"`, `"-2"`,
/// `"1e-3"`, `"0x1.8p-1"`: the syntax of the patch files): the `m + 1` barycentric coordinates,
/// which must sum to exactly 1 (an S-patch: its 2 Cartesian coordinates in the polygon).
/// `point_len` must be `tribez_patch_point_len(patch)`.
///
/// On success `*values` is a new array of `*values_len` (= `tribez_patch_dimension(patch)`)
/// strings, each an exact value in lowest terms, `"p/q"` (or `"p"` when `q = 1`), e.g.
/// `"29/36"`. Returns `TRIBEZ_OK`, or an error code (`*err` set when `err` is not NULL;
/// `*values` and `*values_len` untouched).
///
/// Ownership: `patch` and `point` are borrowed for the call. `*values` (the array and its
/// strings) is the caller's: free it with `tribez_strings_free(*values, *values_len)`. `*err`,
/// when set, is the caller's (`tribez_error_free`).
///
/// # Safety
///
/// `patch` is NULL or a live patch; `point` is NULL or valid for reading `point_len` pointers
/// to NUL-terminated strings; `values` and `values_len` are NULL or valid for a write; `err`
/// is NULL or valid for a write.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tribez_eval_exact(
    patch: *const tribez_patch,
    point: *const *const c_char,
    point_len: usize,
    values: *mut *mut *mut c_char,
    values_len: *mut usize,
    err: *mut *mut tribez_error,
) -> c_int {
    // SAFETY: forwarded from the caller.
    unsafe {
        status(err, || {
            let patch = patch_arg(patch, "patch")?;
            let texts = slice_arg(point, point_len, "point")?;
            if values.is_null() {
                return Err(Failure::null("values"));
            }
            if values_len.is_null() {
                return Err(Failure::null("values_len"));
            }
            check_point_len(patch, point_len)?;
            let mut xs = Vec::with_capacity(point_len);
            for (i, &t) in texts.iter().enumerate() {
                let what = format!("point[{i}]");
                let t = text_arg(t, &what)?;
                xs.push(
                    parse_rational(t).map_err(|e| Failure::input(format!("{what}: `{t}`: {e}")))?,
                );
            }
            let value = patch.evaluate(&xs).map_err(Failure::input)?;
            let strings: Box<[*mut c_char]> =
                value.iter().map(|v| c_string(v.to_string())).collect();
            *values_len = strings.len();
            *values = Box::into_raw(strings).cast::<*mut c_char>();
            Ok(())
        })
    }
}

/// Free an array of strings from `tribez_eval_exact` (NULL: nothing).
///
/// Ownership: takes `values` and its `len` strings; they are invalid afterwards.
///
/// # Safety
///
/// `values` is NULL or an array from `tribez_eval_exact` not yet freed, and `len` its length
/// (`*values_len`).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tribez_strings_free(values: *mut *mut c_char, len: usize) {
    if values.is_null() {
        return;
    }
    // SAFETY: the caller guarantees the array of `len` strings `tribez_eval_exact` made.
    let strings = unsafe { Box::from_raw(std::ptr::slice_from_raw_parts_mut(values, len)) };
    for &s in strings.iter() {
        // SAFETY: each element is a string from `CString::into_raw`.
        unsafe { crate::tribez_string_free(s) };
    }
}

/// The correctly rounded value of the patch at a point given as doubles: each coordinate of the
/// exact value rounded to the nearest double (ties to even; past the largest double, an
/// infinity, as IEEE 754 rounds).
///
/// The point's `point_len` (= `tribez_patch_point_len(patch)`) doubles are taken exactly, as
/// the code under test saw them: barycentric coordinates that do not sum to exactly 1 (as
/// `(0.5, 1/3., 1/6.)` does not) evaluate the patch's homogeneous form there, which is the
/// exact value `tribez_check_f64` judges a result against. NaN and infinities are errors.
/// `out` receives `out_len` (= `tribez_patch_dimension(patch)`) doubles.
///
/// Returns `TRIBEZ_OK`, or an error code (`*err` set when `err` is not NULL; `out` untouched).
///
/// Ownership: `patch`, `point` are borrowed for the call; `out` is the caller's buffer.
/// `*err`, when set, is the caller's (`tribez_error_free`).
///
/// # Safety
///
/// `patch` is NULL or a live patch; `point` is NULL or valid for reading `point_len` doubles;
/// `out` is NULL or valid for writing `out_len` doubles; `err` is NULL or valid for a write.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tribez_eval_f64_correctly_rounded(
    patch: *const tribez_patch,
    point: *const f64,
    point_len: usize,
    out: *mut f64,
    out_len: usize,
    err: *mut *mut tribez_error,
) -> c_int {
    // SAFETY: forwarded from the caller.
    unsafe {
        status(err, || {
            let patch = patch_arg(patch, "patch")?;
            let xs = slice_arg(point, point_len, "point")?;
            if out.is_null() {
                return Err(Failure::null("out"));
            }
            check_point_len(patch, point_len)?;
            let d = patch.dimension();
            if out_len != d {
                return Err(Failure::input(format!(
                    "out: room for {out_len} values, but the patch's points have {d} coordinates"
                )));
            }
            let input = xs
                .iter()
                .enumerate()
                .map(|(i, &x)| exact(x, &|| format!("point[{i}]")))
                .collect::<Result<Vec<_>, _>>()?;
            let value = patch.evaluate_homogeneous(&input).map_err(Failure::input)?;
            let rounded: Vec<f64> = value
                .iter()
                .map(|v| v.to_f64().unwrap_or(f64::NAN))
                .collect();
            std::slice::from_raw_parts_mut(out, out_len).copy_from_slice(&rounded);
            Ok(())
        })
    }
}
