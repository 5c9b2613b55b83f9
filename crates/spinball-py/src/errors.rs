//! Rust errors and panics as Python exceptions.
//!
//! Invalid input (a bad table, α, option, initial state) raises `ValueError`
//! with the Rust message; a run that fails on the way (a step error, an
//! engine mismatch) raises `RuntimeError`; a panic never crosses into Python:
//! it is caught and raised as `RuntimeError`.

use std::panic::{AssertUnwindSafe, catch_unwind};

use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use spinball_analysis::AnalysisError;
use spinball_core::SpinLawError;
use spinball_geometry::GeometryError;

/// `ValueError(message)`.
pub fn value_error(message: impl Into<String>) -> PyErr {
    PyValueError::new_err(message.into())
}

/// A table that cannot be built, as `ValueError`.
pub fn geometry(e: GeometryError) -> PyErr {
    value_error(e.to_string())
}

/// An invalid α, as `ValueError` (with the Python way to the extension).
pub fn spin_law(e: SpinLawError) -> PyErr {
    match e {
        SpinLawError::Unphysical(_) => value_error(format!(
            "{e} (from Python: pass extended=True for the mathematical extension)"
        )),
        other => value_error(other.to_string()),
    }
}

/// An analysis error: invalid input as `ValueError`, a failed run as
/// `RuntimeError`.
pub fn analysis(e: AnalysisError) -> PyErr {
    match e {
        AnalysisError::InvalidOption { .. }
        | AnalysisError::Launch { .. }
        | AnalysisError::Geometry(_)
        | AnalysisError::NoRoom(_) => value_error(e.to_string()),
        AnalysisError::SpinLaw(law) => spin_law(law),
        other => PyRuntimeError::new_err(other.to_string()),
    }
}

/// Run `f`, turning a panic into `RuntimeError` (so no panic unwinds into
/// Python) and an error into a Python exception with `map`.
pub fn guarded<T, E>(
    f: impl FnOnce() -> Result<T, E>,
    map: impl FnOnce(E) -> PyErr,
) -> PyResult<T> {
    match catch_unwind(AssertUnwindSafe(f)) {
        Ok(Ok(v)) => Ok(v),
        Ok(Err(e)) => Err(map(e)),
        Err(payload) => {
            let what = payload
                .downcast_ref::<&str>()
                .map(|s| (*s).to_string())
                .or_else(|| payload.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "unknown panic".to_string());
            Err(PyRuntimeError::new_err(format!(
                "internal error in spinball (a Rust panic; please report it): {what}"
            )))
        }
    }
}
