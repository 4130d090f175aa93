//! `tribez._native`: the native half of the Python package `tribez`.
//!
//! The public API is the Python layer (`tribez/__init__.py`), which converts Python numbers and
//! numpy arrays into what this module takes: numbers as text in tribez's number syntax (exact:
//! a float arrives as its hex form, a `Fraction` as `p/q`), float arrays as the bytes of
//! row-major native-endian `f64`. Everything mathematical is the library's (`crates/tribez`):
//! this module only converts, and reports the library's own errors and verdicts.
//!
//! Every entry point runs under [`guard`]: a Rust panic never crosses into Python, it becomes
//! `tribez.InternalError`. Bad input becomes `tribez.InputError` (a `ValueError`) whose message
//! is the line the command line prints after `tribez: `.

use std::panic::{AssertUnwindSafe, catch_unwind};

use pyo3::prelude::*;
use pyo3::sync::PyOnceLock;
use pyo3::types::PyType;
use tribez::{Precision, Tolerance};

mod claims;
mod hunt;
mod inverse;
mod patch;
mod report;

/// The Python exception classes, defined in `tribez/_errors.py` (so that `InputError` can be
/// both a `tribez.TribezError` and a `ValueError`), looked up once.
fn error_class<'py>(py: Python<'py>, name: &'static str) -> PyResult<Bound<'py, PyType>> {
    static MODULE: PyOnceLock<Py<PyModule>> = PyOnceLock::new();
    let module = MODULE.get_or_try_init(py, || py.import("tribez._errors").map(Bound::unbind))?;
    Ok(module.bind(py).getattr(name)?.cast_into::<PyType>()?)
}

fn raise(py: Python<'_>, class: &'static str, message: String) -> PyErr {
    match error_class(py, class) {
        Ok(ty) => PyErr::from_type(ty, message),
        Err(e) => e,
    }
}

/// `tribez.InputError(message)`.
pub(crate) fn input_error(py: Python<'_>, message: impl std::fmt::Display) -> PyErr {
    raise(py, "InputError", message.to_string())
}

/// The `tolerance` argument of a native call, read as the command line's `--tolerance`.
pub(crate) fn tolerance_arg(py: Python<'_>, text: &str) -> PyResult<Tolerance> {
    Tolerance::parse(text).map_err(|e| input_error(py, format!("tolerance: {e}")))
}

/// The `precision` argument of a native call: `"f64"` or `"f32"`.
pub(crate) fn precision_arg(py: Python<'_>, text: &str) -> PyResult<Precision> {
    text.parse()
        .map_err(|e| input_error(py, format!("precision: {e}")))
}

/// Run `f`, turning a panic into `tribez.InternalError` (never a `PanicException`).
pub(crate) fn guard<T>(py: Python<'_>, f: impl FnOnce() -> PyResult<T>) -> PyResult<T> {
    match catch_unwind(AssertUnwindSafe(f)) {
        Ok(result) => result,
        Err(payload) => {
            let what = payload
                .downcast_ref::<&str>()
                .map(|s| (*s).to_string())
                .or_else(|| payload.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "unknown panic".into());
            Err(raise(
                py,
                "InternalError",
                format!("internal error in tribez (please report it): {what}"),
            ))
        }
    }
}

/// Panic on purpose, to test that a panic becomes `tribez.InternalError`.
#[pyfunction]
fn _panic_for_test(py: Python<'_>, message: &str) -> PyResult<()> {
    guard(py, || panic!("{message}"))
}

/// Panic on purpose in a rayon worker with the GIL released.
#[pyfunction]
fn _panic_in_worker_for_test(py: Python<'_>) -> PyResult<usize> {
    guard(py, || {
        Ok(py.detach(|| {
            use rayon::prelude::*;
            (0..64usize)
                .into_par_iter()
                .map(|i| if i == 37 { panic!("worker {i}") } else { i })
                .sum()
        }))
    })
}

/// The stop test of long library calls run with the GIL released (`check`, `certify`): takes
/// the GIL for a moment and runs Python's pending signal handlers, so that Ctrl-C (SIGINT)
/// raises `KeyboardInterrupt` between slabs of rows or points, not when the call ends. Python
/// runs signal handlers on its main thread only; elsewhere this answers `None`.
pub(crate) fn interrupted() -> Option<PyErr> {
    Python::attach(|py| py.check_signals().err())
}

/// Number of threads the batch engine uses (rayon's global pool).
#[pyfunction]
fn threads() -> usize {
    rayon::current_num_threads()
}

#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    // the package's version: pyproject.toml takes it from this crate's (`dynamic = ["version"]`)
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add_class::<patch::NativePatch>()?;
    m.add_class::<report::NativeReport>()?;
    m.add_class::<claims::NativeDocument>()?;
    m.add_class::<hunt::NativeHunt>()?;
    m.add_function(wrap_pyfunction!(hunt::hunt, m)?)?;
    m.add("MAX_HUNT_BUDGET", tribez::hunt::MAX_BUDGET)?;
    m.add("MAX_HUNT_BATCH", tribez::hunt::MAX_BATCH)?;
    m.add("MAX_HUNT_TOP", tribez::hunt::MAX_TOP)?;
    m.add_function(wrap_pyfunction!(claims::check_claims, m)?)?;
    m.add_function(wrap_pyfunction!(claims::certify, m)?)?;
    m.add_function(wrap_pyfunction!(inverse::check_inverse, m)?)?;
    m.add("MAX_INVERSE_ROWS", inverse::MAX_INVERSE_ROWS)?;
    m.add("MAX_RANDOM_POINTS", claims::MAX_RANDOM_POINTS)?;
    m.add_function(wrap_pyfunction!(report::check_rows, m)?)?;
    m.add_function(wrap_pyfunction!(patch::parse_number, m)?)?;
    m.add_function(wrap_pyfunction!(threads, m)?)?;
    m.add_function(wrap_pyfunction!(_panic_for_test, m)?)?;
    m.add_function(wrap_pyfunction!(_panic_in_worker_for_test, m)?)?;
    m.add("MAX_DEGREE", tribez::limits::MAX_DEGREE)?;
    m.add("MAX_CONTROL_POINTS", tribez::limits::MAX_CONTROL_POINTS)?;
    m.add(
        "MAX_SIMPLEX_DIMENSION",
        tribez::limits::MAX_SIMPLEX_DIMENSION,
    )?;
    Ok(())
}
