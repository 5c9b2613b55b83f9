//! Python arguments to Rust options, with the messages a Python user needs.
//!
//! Counts arrive as Python ints (a negative one is a `ValueError` here, not
//! an `OverflowError`), names as strings, arrays as anything
//! `numpy.asarray(..., dtype=float64)` reads.

use numpy::{PyReadonlyArray2, PyUntypedArrayMethods};
use pyo3::prelude::*;
use pyo3::types::PyAnyMethods;
use spinball_analysis::estimators::{Method, PAPER_DELTA0};
use spinball_analysis::run::{Engine, RunDefaults, StopRule, Threads};
use spinball_core::{Sampler, SpinLaw, State};

use crate::errors::{spin_law, value_error};

/// A count that must be `>= min`.
pub fn count(name: &str, value: i64, min: i64) -> PyResult<u64> {
    if value < min {
        return Err(value_error(format!(
            "{name} must be at least {min}, got {value}"
        )));
    }
    Ok(value as u64)
}

/// The spin law for `alpha` (α > 1 only with `extended`).
pub fn law(alpha: f64, extended: bool) -> PyResult<SpinLaw> {
    if extended {
        SpinLaw::extended(alpha)
    } else {
        SpinLaw::new(alpha)
    }
    .map_err(spin_law)
}

/// `"fd"` (with `delta0`, default the paper's 1e-7) or `"tangent"`.
pub fn method(name: &str, delta0: Option<f64>) -> PyResult<Method> {
    let m: Method = name
        .parse()
        .map_err(|e: spinball_analysis::AnalysisError| value_error(e.to_string()))?;
    let m = match (m, delta0) {
        (Method::FiniteDifference { .. }, d) => Method::FiniteDifference {
            delta0: d.unwrap_or(PAPER_DELTA0),
        },
        (Method::Tangent, None) => Method::Tangent,
        (Method::Tangent, Some(_)) => {
            return Err(value_error(
                "delta0 is the separation of method='fd'; the tangent method has none",
            ));
        }
    };
    m.validate()
        .map_err(|e| value_error(e.to_string()))
        .map(|()| m)
}

/// `"paper"` or `"microcanonical"` (default `"paper"`).
pub fn sampler(name: Option<&str>) -> PyResult<Sampler> {
    name.map_or(Ok(RunDefaults::SAMPLER), |s| {
        s.parse()
            .map_err(|e: spinball_core::UnknownSampler| value_error(e.to_string()))
    })
}

/// `"lanes"` or `"scalar"`.
pub fn engine(name: &str) -> PyResult<Engine> {
    match name.trim().to_ascii_lowercase().as_str() {
        "lanes" => Ok(Engine::Lanes),
        "scalar" => Ok(Engine::Scalar),
        other => Err(value_error(format!(
            "unknown engine `{other}` (expected lanes or scalar)"
        ))),
    }
}

/// `None`: all cores; `n >= 1`: a pool of `n` threads.
pub fn threads(n: Option<i64>) -> PyResult<Threads> {
    match n {
        None => Ok(RunDefaults::THREADS),
        Some(n) => Ok(Threads::Fixed(count("threads", n, 1)? as usize)),
    }
}

/// A stop rule when a target or a time budget is given.
pub fn stop_rule(
    target_rel_sem: Option<f64>,
    batch: i64,
    time_budget: Option<f64>,
) -> PyResult<Option<StopRule>> {
    if target_rel_sem.is_none() && time_budget.is_none() {
        return Ok(None);
    }
    let mut rule = StopRule::new(count("batch", batch, 2)?, target_rel_sem.unwrap_or(0.0));
    if let Some(seconds) = time_budget {
        if !(seconds.is_finite() && seconds >= 0.0) {
            return Err(value_error(format!(
                "time_budget must be a finite number of seconds >= 0, got {seconds}"
            )));
        }
        rule = rule.with_time_budget(std::time::Duration::from_secs_f64(seconds));
    }
    rule.validate().map_err(|e| value_error(e.to_string()))?;
    Ok(Some(rule))
}

/// `obj` as a float64 array of shape `(n, columns)` (a single row of
/// `columns` values is read as `n = 1`), row-major.
pub fn rows(obj: &Bound<'_, PyAny>, columns: usize, what: &str) -> PyResult<Vec<Vec<f64>>> {
    let py = obj.py();
    let np = py.import("numpy")?;
    let array = np
        .call_method1("asarray", (obj, "float64"))
        .map_err(|e| value_error(format!("{what}: cannot read as an array of numbers: {e}")))?;
    let array = if array.getattr("ndim")?.extract::<usize>()? == 1 {
        array.call_method1("reshape", (1, -1))?
    } else {
        array
    };
    let array: PyReadonlyArray2<'_, f64> = array
        .extract()
        .map_err(|_| value_error(format!("{what}: expected an array of shape (n, {columns})")))?;
    let shape = array.shape();
    if shape[1] != columns {
        return Err(value_error(format!(
            "{what}: expected an array of shape (n, {columns}), got shape ({}, {})",
            shape[0], shape[1]
        )));
    }
    let view = array.as_array();
    Ok(view.rows().into_iter().map(|r| r.to_vec()).collect())
}

/// Initial states from an `(n, 5)` array of `(x, y, vx, vy, u)`.
pub fn states(obj: &Bound<'_, PyAny>) -> PyResult<Vec<State>> {
    rows(obj, 5, "initial_states")?
        .into_iter()
        .map(|r| {
            let s = State::from_array([r[0], r[1], r[2], r[3], r[4]]);
            s.validate()
                .map_err(|e| value_error(format!("initial_states: {e}")))
                .map(|()| s)
        })
        .collect()
}

/// `object` if it is a 2-sequence of numbers, as `(x, y)`.
pub fn pair(obj: &Bound<'_, PyAny>, what: &str) -> PyResult<(f64, f64)> {
    let r = rows(obj, 2, what)?;
    match r.as_slice() {
        [p] => Ok((p[0], p[1])),
        _ => Err(value_error(format!("{what}: expected two numbers (x, y)"))),
    }
}
