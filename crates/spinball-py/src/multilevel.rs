//! `lyapunov(..., estimator="multilevel", target_error=...)`: multilevel
//! ensembles over run length, and their result object.

use pyo3::prelude::*;
use spinball_analysis::precision::{EnsembleLevels, Multilevel, MultilevelEstimate};
use spinball_analysis::run::Ensemble;
use spinball_geometry::Boundary;

use crate::errors::{analysis, guarded, value_error};

/// The result of `lyapunov(..., estimator="multilevel")`.
///
/// `mean`, `sem`: λ at the top run length `collisions` (the sum of the
/// level means) and its standard error; `total_error` (SEM, finite-time
/// and method bias together), `finite_time_bias`, `method_bias`;
/// `limit`, `limit_sem`: λ extrapolated to infinite run length, and
/// `bias_law` (`"1/T"`, `"ln T / T"` or `"neither"`); `chaotic_fraction`
/// and `chaotic_fraction_sem` (classified at the shortest run),
/// `chaotic_mean` and `chaotic_mean_sem` (`None` without chaotic initial
/// conditions); `levels`: one dict per level (`collisions`, `n_ics`,
/// `mean`, `variance`, `cost`, `wall_time_s`); `target_error`,
/// `target_met`, `wall_time_s`.
#[pyclass(frozen, name = "MultilevelResult", module = "spinball")]
pub struct PyMultilevelResult {
    inner: MultilevelEstimate,
}

#[pymethods]
impl PyMultilevelResult {
    /// λ at the top run length.
    #[getter]
    fn mean(&self) -> f64 {
        self.inner.lambda().value
    }
    /// Its standard error.
    #[getter]
    fn sem(&self) -> f64 {
        self.inner.lambda().sem
    }
    /// Total error: SEM and both biases, each at its estimate and its uncertainty.
    #[getter]
    fn total_error(&self) -> f64 {
        self.inner.budget.total.value
    }
    /// Finite-time bias λ_T − λ at the top run length.
    #[getter]
    fn finite_time_bias(&self) -> f64 {
        self.inner.budget.finite_time_bias.value
    }
    /// Method bias λ_fd − λ_tangent (0 for tangent).
    #[getter]
    fn method_bias(&self) -> f64 {
        self.inner.budget.method_bias.value
    }
    /// λ extrapolated to infinite run length.
    #[getter]
    fn limit(&self) -> f64 {
        self.inner.limit().value
    }
    /// Its standard error.
    #[getter]
    fn limit_sem(&self) -> f64 {
        self.inner.limit().sem
    }
    /// The law the finite-time bias follows.
    #[getter]
    fn bias_law(&self) -> &'static str {
        self.inner.regime().name()
    }
    /// Share of initial conditions chaotic at the shortest run.
    #[getter]
    fn chaotic_fraction(&self) -> f64 {
        self.inner.chaotic_fraction.value
    }
    /// Its standard error.
    #[getter]
    fn chaotic_fraction_sem(&self) -> f64 {
        self.inner.chaotic_fraction.sem
    }
    /// Mean λ of the chaotic initial conditions at the top run length.
    #[getter]
    fn chaotic_mean(&self) -> Option<f64> {
        self.inner.chaotic_mean.map(|m| m.value)
    }
    /// Its standard error.
    #[getter]
    fn chaotic_mean_sem(&self) -> Option<f64> {
        self.inner.chaotic_mean.map(|m| m.sem)
    }
    /// The target relative total error.
    #[getter]
    fn target_error(&self) -> f64 {
        self.inner.target_rel
    }
    /// Whether the total error meets the target.
    #[getter]
    fn target_met(&self) -> bool {
        self.inner.target_met()
    }
    /// Wall-clock seconds over all levels.
    #[getter]
    fn wall_time_s(&self) -> f64 {
        self.inner.wall_time_s()
    }
    /// One dict per level.
    #[getter]
    fn levels(&self, py: Python<'_>) -> PyResult<Vec<Py<pyo3::types::PyDict>>> {
        self.inner
            .levels
            .iter()
            .map(|s| {
                let d = pyo3::types::PyDict::new(py);
                d.set_item("collisions", s.collisions)?;
                d.set_item("n_ics", s.n_ics)?;
                d.set_item("mean", s.mean)?;
                d.set_item("variance", s.variance)?;
                d.set_item("cost", s.cost)?;
                d.set_item("wall_time_s", s.wall_time_s)?;
                Ok(d.unbind())
            })
            .collect()
    }
    fn __repr__(&self) -> String {
        let l = self.inner.lambda();
        format!(
            "MultilevelResult(mean={:.6}, sem={:.6}, total_error={:.6}, limit={:.6}, levels={})",
            l.value,
            l.sem,
            self.inner.budget.total.value,
            self.inner.limit().value,
            self.inner.levels.len()
        )
    }
    fn __str__(&self) -> String {
        self.inner.to_string()
    }
}

/// The multilevel estimator for `target_error`.
///
/// # Errors
/// `ValueError` for a missing or out-of-range target.
pub fn estimator(target_error: Option<f64>) -> PyResult<Multilevel> {
    match target_error {
        Some(t) if t.is_finite() && t > 0.0 && t < 1.0 => Ok(Multilevel::new(t)),
        Some(t) => Err(value_error(format!(
            "target_error must be a relative error in (0, 1), got {t}"
        ))),
        None => Err(value_error(
            "estimator=\"multilevel\" needs target_error (e.g. 1e-3)",
        )),
    }
}

/// Run `options` on the levels of `ensemble` up to its collisions, the GIL
/// released.
///
/// # Errors
/// `ValueError` for levels that cannot be made, `RuntimeError` for a failed
/// run or an unreachable target.
pub fn run<B: Boundary + Clone + Sync + Send>(
    py: Python<'_>,
    ensemble: Ensemble<B>,
    options: Multilevel,
) -> PyResult<PyMultilevelResult> {
    py.detach(|| {
        guarded(
            || {
                let source = EnsembleLevels::up_to(ensemble.clone(), ensemble.collisions)?;
                options.run(&source)
            },
            analysis,
        )
    })
    .map(|inner| PyMultilevelResult { inner })
}
