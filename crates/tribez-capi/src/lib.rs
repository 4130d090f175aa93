//! # The C ABI of tribez
//!
//! `libtribez.so` / `libtribez.a` and `include/tribez.h`: exact evaluation of Bézier patches
//! and the batch judge of `tribez check --results`, for C and C++ test suites (docs/c.md).
//!
//! Conventions, the same for every function (the header says them once at the top, then per
//! function what each pointer is and who owns it):
//!
//! * Opaque handles: [`tribez_patch`], [`tribez_report`], [`tribez_error`], each created by
//!   tribez and freed by its `*_free` function (which accepts NULL).
//! * Status codes: functions that do work return [`TRIBEZ_OK`] (0) or an error code, and
//!   constructors return a handle or NULL; either way, when `err` is not NULL, `*err` receives
//!   a new [`tribez_error`] on failure (its message is the command line's one-line message) and
//!   is left alone on success.
//! * No panic crosses the boundary: every entry point runs inside [`std::panic::catch_unwind`];
//!   a panic (a bug in tribez) becomes [`TRIBEZ_ERROR_INTERNAL`].
//! * Threads: functions on distinct handles may run concurrently; a patch or report may be read
//!   (evaluated, checked against, rendered) from several threads at once; only
//!   `tribez_report_merge` (its `into`) and the `*_free` functions need the handle alone.
//!
//! This crate uses only the public API of the `tribez` library (named `tribez_lib` here, since
//! this library target is itself named `tribez`: see Cargo.toml).

#![allow(non_camel_case_types)]
#![warn(missing_docs)]

use std::ffi::{CStr, CString, c_char, c_int};
use std::panic::{AssertUnwindSafe, catch_unwind};

mod check;
mod hunt;
mod patch;
#[cfg(test)]
mod tests;

pub use check::*;
pub use hunt::*;
pub use patch::*;

/// Success.
pub const TRIBEZ_OK: c_int = 0;
/// Bad input: a file, a text, a number, a size or an option that tribez cannot take (the
/// command line's exit status 2). The message says which and why, on one line.
pub const TRIBEZ_ERROR_INPUT: c_int = 1;
/// A pointer that must not be NULL was NULL (the message names the argument).
pub const TRIBEZ_ERROR_NULL: c_int = 2;
/// A bug inside tribez (a panic, caught at the boundary); please report it with the message.
pub const TRIBEZ_ERROR_INTERNAL: c_int = 3;

/// An error: a status code and a one-line message. Created by tribez in a `tribez_error **err`
/// out-parameter, owned by the caller, freed with [`tribez_error_free`].
pub struct tribez_error {
    code: c_int,
    message: CString,
}

/// Why a call failed (before it becomes a [`tribez_error`]).
#[derive(Debug)]
pub(crate) struct Failure {
    pub(crate) code: c_int,
    pub(crate) message: String,
}

impl Failure {
    /// Bad input, with its one-line message.
    pub(crate) fn input(message: impl std::fmt::Display) -> Self {
        Failure {
            code: TRIBEZ_ERROR_INPUT,
            message: message.to_string(),
        }
    }

    /// The argument `what` was NULL.
    pub(crate) fn null(what: &str) -> Self {
        Failure {
            code: TRIBEZ_ERROR_NULL,
            message: format!("{what}: NULL pointer"),
        }
    }
}

/// The message of a panic's payload.
fn panic_message(payload: &(dyn std::any::Any + Send)) -> String {
    payload
        .downcast_ref::<&str>()
        .map(|s| (*s).to_string())
        .or_else(|| payload.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "unknown panic".into())
}

/// Run `f`, catching any panic: on failure (an error or a panic) store a new error in `*err`
/// (when `err` is not NULL) and return `failed`.
///
/// # Safety
///
/// `err` is NULL or valid for one write of a pointer.
pub(crate) unsafe fn guard<T>(
    err: *mut *mut tribez_error,
    failed: T,
    f: impl FnOnce() -> Result<T, Failure>,
) -> T {
    let failure = match catch_unwind(AssertUnwindSafe(f)) {
        Ok(Ok(value)) => return value,
        Ok(Err(failure)) => failure,
        Err(payload) => Failure {
            code: TRIBEZ_ERROR_INTERNAL,
            message: format!(
                "internal error in tribez (please report it): {}",
                panic_message(&*payload)
            ),
        },
    };
    if !err.is_null() {
        let message = CString::new(failure.message.replace('\0', "\\0"))
            .unwrap_or_else(|_| c"internal error in tribez: unprintable message".into());
        let error = Box::new(tribez_error {
            code: failure.code,
            message,
        });
        // SAFETY: the caller guarantees `err` is valid for a write when not NULL.
        unsafe { *err = Box::into_raw(error) };
    }
    failed
}

/// Run `f` (returning a status code), catching any panic.
///
/// # Safety
///
/// As [`guard`].
pub(crate) unsafe fn status(
    err: *mut *mut tribez_error,
    f: impl FnOnce() -> Result<(), Failure>,
) -> c_int {
    let mut code = TRIBEZ_ERROR_INTERNAL;
    let code_ref = &mut code;
    // SAFETY: forwarded from the caller.
    unsafe {
        guard(err, (), || {
            let r = f();
            *code_ref = match &r {
                Ok(()) => TRIBEZ_OK,
                Err(e) => e.code,
            };
            r
        })
    };
    code
}

/// The text of a NUL-terminated string argument `what`.
///
/// # Safety
///
/// `s` is NULL or a NUL-terminated string that outlives the call.
pub(crate) unsafe fn text_arg<'a>(s: *const c_char, what: &str) -> Result<&'a str, Failure> {
    if s.is_null() {
        return Err(Failure::null(what));
    }
    // SAFETY: the caller guarantees a NUL-terminated string.
    let c = unsafe { CStr::from_ptr(s) };
    c.to_str()
        .map_err(|e| Failure::input(format!("{what}: not valid UTF-8 ({e})")))
}

/// A new C string (for the caller to free with [`tribez_string_free`]).
pub(crate) fn c_string(s: String) -> *mut c_char {
    CString::new(s.replace('\0', "\\0"))
        .unwrap_or_default()
        .into_raw()
}

/// The error's one-line message: the message of the command line for the same input (without
/// its `tribez: ` prefix), e.g. `patch.toml:7: control_points."0,1,1"[1]: …`. NULL for a NULL
/// `err`.
///
/// Ownership: `err` is borrowed. The returned string belongs to `err`: valid until
/// [`tribez_error_free`] of `err`; do not free it.
///
/// # Safety
///
/// `err` is NULL or an error from tribez not yet freed.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tribez_error_message(err: *const tribez_error) -> *const c_char {
    // SAFETY: the caller guarantees a live error or NULL.
    match unsafe { err.as_ref() } {
        Some(e) => e.message.as_ptr(),
        None => std::ptr::null(),
    }
}

/// The error's status code (`TRIBEZ_ERROR_INPUT`, `TRIBEZ_ERROR_NULL` or
/// `TRIBEZ_ERROR_INTERNAL`); `TRIBEZ_OK` for a NULL `err`.
///
/// Ownership: `err` is borrowed.
///
/// # Safety
///
/// `err` is NULL or an error from tribez not yet freed.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tribez_error_code(err: *const tribez_error) -> c_int {
    // SAFETY: the caller guarantees a live error or NULL.
    unsafe { err.as_ref() }.map_or(TRIBEZ_OK, |e| e.code)
}

/// Free an error (NULL: nothing).
///
/// Ownership: takes `err` (created by tribez in an `err` out-parameter); it and its message are
/// invalid afterwards.
///
/// # Safety
///
/// `err` is NULL or an error from tribez not yet freed.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tribez_error_free(err: *mut tribez_error) {
    if !err.is_null() {
        // SAFETY: the caller guarantees a live error from `Box::into_raw`.
        drop(unsafe { Box::from_raw(err) });
    }
}

/// Free a string returned by tribez (`tribez_report_text`, `tribez_report_json`); NULL:
/// nothing.
///
/// Ownership: takes `s`; it is invalid afterwards.
///
/// # Safety
///
/// `s` is NULL or a string returned by tribez not yet freed (not one from
/// `tribez_error_message` or `tribez_version`, which are not the caller's).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tribez_string_free(s: *mut c_char) {
    if !s.is_null() {
        // SAFETY: the caller guarantees a string from `CString::into_raw`.
        drop(unsafe { CString::from_raw(s) });
    }
}

/// The version of tribez, e.g. `"0.1.0"` (the crates' version).
///
/// Ownership: a static string; do not free it.
#[unsafe(no_mangle)]
pub extern "C" fn tribez_version() -> *const c_char {
    static VERSION: &CStr =
        match CStr::from_bytes_with_nul(concat!(env!("CARGO_PKG_VERSION"), "\0").as_bytes()) {
            Ok(v) => v,
            Err(_) => c"unknown",
        };
    VERSION.as_ptr()
}

/// For tests only (not in the header): panic inside tribez, on the calling thread
/// (`in_worker == 0`) or in a worker thread of the parallel engine, to show that the panic is
/// caught and reported as `TRIBEZ_ERROR_INTERNAL` with `message` in the error's message.
///
/// # Safety
///
/// `message` is a NUL-terminated string; `err` is NULL or valid for a write.
#[doc(hidden)]
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tribez__panic_for_test(
    message: *const c_char,
    in_worker: c_int,
    err: *mut *mut tribez_error,
) -> c_int {
    // SAFETY: forwarded from the caller.
    unsafe {
        status(err, || {
            let message = text_arg(message, "message")?.to_string();
            if in_worker != 0 {
                use rayon::prelude::*;
                // the panic happens on a thread of rayon's pool, as one inside a check would
                (0..64).into_par_iter().for_each(|i| {
                    if i == 63 {
                        panic!("{message}")
                    }
                });
                Ok(())
            } else {
                panic!("{message}")
            }
        })
    }
}
