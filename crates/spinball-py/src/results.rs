//! Result classes: `LyapunovResult` (an ensemble estimate of the largest
//! exponent) and `SpectrumResult` (the ensemble spectrum), each with its
//! fields as attributes, per-trajectory values as NumPy arrays, and
//! `to_dict()` / `to_json()` equal to the Rust result's serde JSON; and
//! `read_results` / `write_results`, the result documents of the command
//! line (one schema, `spinball_analysis::report::Document`).

use numpy::ndarray::Array2;
use numpy::{IntoPyArray, PyArray1, PyArray2};
use pyo3::exceptions::PyRuntimeError;
use pyo3::prelude::*;
use spinball_analysis::report::{Document, LyapunovDocument, SpectrumDocument};
use spinball_analysis::run::{LyapunovEstimate, Provenance, SpectrumEstimate, TableRecord};

use crate::errors::{analysis, value_error};
use crate::ftle::PyFtleDistribution;

/// `value ± error` as text, the error to two significant digits and the
/// value to the same decimal place (`plus_minus(0.0003124, 0.0000412)` is
/// `'0.000312 ± 0.000041'`): how results print their error.
#[pyfunction]
#[must_use]
pub fn plus_minus(value: f64, error: f64) -> String {
    spinball_analysis::estimators::PlusMinus::new(value, error).to_string()
}

/// `value` as its serde JSON text (`indent` spaces, or compact).
pub(crate) fn json<T: serde::Serialize>(value: &T, indent: Option<usize>) -> PyResult<String> {
    let out = match indent {
        None => serde_json::to_string(value),
        Some(n) => {
            let pad = vec![b' '; n];
            let mut buf = Vec::new();
            let fmt = serde_json::ser::PrettyFormatter::with_indent(&pad);
            let mut ser = serde_json::Serializer::with_formatter(&mut buf, fmt);
            value
                .serialize(&mut ser)
                .map(|()| String::from_utf8(buf).unwrap_or_default())
        }
    };
    out.map_err(|e| PyRuntimeError::new_err(format!("cannot serialise the result: {e}")))
}

/// JSON text to Python objects (`json.loads`).
pub(crate) fn loads<'py>(py: Python<'py>, text: &str) -> PyResult<Bound<'py, PyAny>> {
    py.import("json")?.call_method1("loads", (text,))
}

/// The ensemble estimate of the largest Lyapunov exponent (per unit time),
/// returned by `lyapunov` and `alpha_sweep`.
///
/// Statistics: `mean` (the estimate λ), `sem` (its standard error),
/// `median`, `std`, `min`, `max`, `conditional_mean` (mean over FTLE >
/// `threshold`, or `None`), `chaotic_fraction` and `chaotic_fraction_sem`,
/// `per_collision_mean` (mean exponent per collision), `collision_rate`
/// (collisions per unit time over the ensemble), `total_time`.
/// Cost: `n_ics`, `first_index`, `collisions_per_ic`, `wall_time_s`.
/// Parameters: `table` (spec), `alpha`, `method` (`"fd"` / `"tangent"`),
/// `delta0`, `sampler` (`None` for explicit states), `seed`, `threshold`,
/// `engine`, `version`, `stop` (why the run stopped). Per trajectory, in
/// index order: `exponents`, `per_collision`, `times`, `collisions`,
/// `indices` (NumPy arrays).
#[pyclass(frozen, name = "LyapunovResult", module = "spinball")]
pub struct PyLyapunovResult {
    pub(crate) inner: LyapunovEstimate,
}

impl PyLyapunovResult {
    fn column<T: numpy::Element>(
        &self,
        py: Python<'_>,
        f: impl Fn(&spinball_analysis::run::TrajectoryStats) -> T,
    ) -> Py<PyArray1<T>> {
        self.inner
            .trajectories()
            .iter()
            .map(f)
            .collect::<Vec<T>>()
            .into_pyarray(py)
            .unbind()
    }
}

#[pymethods]
impl PyLyapunovResult {
    /// Mean FTLE λ (per unit time): the estimate.
    #[getter]
    fn mean(&self) -> f64 {
        self.inner.mean()
    }
    /// Standard error of the mean, std/√n_ics.
    #[getter]
    fn sem(&self) -> f64 {
        self.inner.sem()
    }
    /// Median FTLE.
    #[getter]
    fn median(&self) -> f64 {
        self.inner.median()
    }
    /// Sample standard deviation of the FTLEs.
    #[getter]
    fn std(&self) -> f64 {
        self.inner.std()
    }
    /// Smallest FTLE.
    #[getter]
    fn min(&self) -> f64 {
        self.inner.min()
    }
    /// Largest FTLE.
    #[getter]
    fn max(&self) -> f64 {
        self.inner.max()
    }
    /// FTLE above which a trajectory counts as chaotic.
    #[getter]
    fn threshold(&self) -> f64 {
        self.inner.threshold()
    }
    /// Mean FTLE of the chaotic trajectories (`None` if there are none).
    #[getter]
    fn conditional_mean(&self) -> Option<f64> {
        self.inner.conditional_mean()
    }
    /// Share of trajectories with FTLE > threshold.
    #[getter]
    fn chaotic_fraction(&self) -> f64 {
        self.inner.chaotic_fraction()
    }
    /// Binomial standard error of the chaotic fraction.
    #[getter]
    fn chaotic_fraction_sem(&self) -> f64 {
        self.inner.chaotic_fraction_sem()
    }
    /// Mean exponent per collision.
    #[getter]
    fn per_collision_mean(&self) -> f64 {
        self.inner.per_collision_mean()
    }
    /// Collisions per unit time, Σ collisions / Σ time.
    #[getter]
    fn collision_rate(&self) -> f64 {
        self.inner.collision_rate()
    }
    /// Total flight time of all trajectories.
    #[getter]
    fn total_time(&self) -> f64 {
        self.inner.total_time()
    }
    /// Number of initial conditions.
    #[getter]
    fn n_ics(&self) -> u64 {
        self.inner.n_ics()
    }
    /// Index of the first initial condition.
    #[getter]
    fn first_index(&self) -> u64 {
        self.inner.first_index()
    }
    /// Collisions per initial condition.
    #[getter]
    fn collisions_per_ic(&self) -> u64 {
        self.inner.collisions_per_ic()
    }
    /// Wall-clock seconds spent computing.
    #[getter]
    fn wall_time_s(&self) -> f64 {
        self.inner.wall_time_s()
    }
    /// Seed of the initial conditions.
    #[getter]
    fn seed(&self) -> u64 {
        self.inner.seed()
    }
    /// Spec string of the table (`stadium:a=1`, `segments(6 walls)`).
    #[getter]
    fn table(&self) -> String {
        self.inner.table().name.clone()
    }
    /// Spin parameter α.
    #[getter]
    fn alpha(&self) -> f64 {
        self.inner.alpha()
    }
    /// `"fd"` or `"tangent"`.
    #[getter]
    fn method(&self) -> &'static str {
        self.inner.method().name()
    }
    /// Initial separation of the finite-difference method (`None` for tangent).
    #[getter]
    fn delta0(&self) -> Option<f64> {
        self.inner.delta0()
    }
    /// `"paper"`, `"microcanonical"`, or `None` for explicit initial states.
    #[getter]
    fn sampler(&self) -> Option<&'static str> {
        self.inner.sampler().map(|s| s.name())
    }
    /// `"lanes"` or `"scalar"`: the engine that ran the trajectories.
    #[getter]
    fn engine(&self) -> &'static str {
        self.inner.engine().name()
    }
    /// Version of the Rust analysis crate that computed the result.
    #[getter]
    fn version(&self) -> String {
        self.inner.version().to_string()
    }
    /// Why the run stopped: `completed`, `target_reached`, `time_budget` or
    /// `range_exhausted`.
    #[getter]
    fn stop(&self) -> &'static str {
        self.inner.stop().name()
    }
    /// Relative standard error sem/|mean|.
    #[getter]
    fn rel_sem(&self) -> f64 {
        self.inner.rel_sem()
    }
    /// Per-trajectory FTLEs (per unit time), float64, in index order.
    #[getter]
    fn exponents(&self, py: Python<'_>) -> Py<PyArray1<f64>> {
        self.column(py, |t| t.exponent)
    }
    /// Per-trajectory exponents per collision, float64.
    #[getter]
    fn per_collision(&self, py: Python<'_>) -> Py<PyArray1<f64>> {
        self.column(py, |t| t.per_collision)
    }
    /// Per-trajectory total flight time, float64.
    #[getter]
    fn times(&self, py: Python<'_>) -> Py<PyArray1<f64>> {
        self.column(py, |t| t.time)
    }
    /// Per-trajectory collision counts, int64.
    #[getter]
    fn collisions(&self, py: Python<'_>) -> Py<PyArray1<i64>> {
        self.column(py, |t| t.collisions as i64)
    }
    /// Initial-condition indices, int64.
    #[getter]
    fn indices(&self, py: Python<'_>) -> Py<PyArray1<i64>> {
        self.column(py, |t| t.index as i64)
    }
    /// What the result was computed from (table with its shape, alpha,
    /// method, sampler, seed, collisions_per_ic, threshold, engine) and the
    /// crate version, as a dict: enough to rerun it.
    #[getter]
    fn provenance<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let e = &self.inner;
        let p = Provenance::new(
            e.table().clone(),
            e.alpha(),
            e.method(),
            e.sampler(),
            e.seed(),
            e.collisions_per_ic(),
            e.threshold(),
            e.engine(),
        );
        let d = loads(py, &json(&p, None)?)?;
        d.set_item("version", e.version())?;
        Ok(d)
    }
    /// The per-trajectory exponents as an `FtleDistribution`.
    fn ftle(&self) -> PyResult<PyFtleDistribution> {
        Ok(PyFtleDistribution {
            inner: self.inner.ftle().map_err(analysis)?,
        })
    }
    /// The result over both index ranges of two adjacent runs with the same
    /// parameters (bitwise equal to one run over both). Raises `ValueError`
    /// if the ranges are not adjacent or a parameter differs.
    fn merge(&self, other: &PyLyapunovResult) -> PyResult<PyLyapunovResult> {
        Ok(PyLyapunovResult {
            inner: self.inner.merge(&other.inner).map_err(analysis)?,
        })
    }
    /// The result document the command line writes for the same run
    /// (`spinball lyapunov --json`: kind `spinball.lyapunov`, one point),
    /// compact or indented by `indent` spaces per level; `read_results`
    /// and `from_json` read it.
    #[pyo3(signature = (indent = None))]
    fn to_json(&self, indent: Option<usize>) -> PyResult<String> {
        let doc = Document::Lyapunov(LyapunovDocument::new(vec![self.inner.clone()]));
        match indent {
            None => doc.to_json(),
            Some(n) => doc.to_json_indent(n),
        }
        .map_err(|e| PyRuntimeError::new_err(format!("cannot serialise the result: {e}")))
    }
    /// The result's fields as a dict (the one point of `to_json()`'s
    /// document): every statistic and parameter, the per-trajectory values
    /// under `trajectories`.
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        loads(py, &json(&self.inner, None)?)
    }
    /// A result read back from `to_json()` text or a one-point result file
    /// of the command line (a bare result written by spinball 0.2's
    /// `to_json` too). Raises `ValueError` for text that is not such a
    /// result, or a document of several (read those with `read_results`).
    #[staticmethod]
    fn from_json(text: &str) -> PyResult<PyLyapunovResult> {
        let mut doc = LyapunovDocument::from_json(text)
            .map_err(|e| value_error(format!("not a spinball LyapunovResult: {e}")))?;
        match doc.points.len() {
            1 => Ok(PyLyapunovResult {
                inner: doc.points.remove(0),
            }),
            n => Err(value_error(format!(
                "the document holds {n} results, not one: read it with read_results"
            ))),
        }
    }
    fn __eq__(&self, other: &Bound<'_, PyAny>) -> bool {
        other
            .cast::<PyLyapunovResult>()
            .is_ok_and(|o| o.get().inner == self.inner)
    }
    fn __repr__(&self) -> String {
        format!("<LyapunovResult {}>", self.inner)
    }
}

/// The Lyapunov spectrum averaged over an ensemble, returned by `spectrum`.
///
/// `mean`, `sem`, `per_collision_mean`: arrays of the five exponents (per
/// unit time, descending within each trajectory) and their standard
/// errors; `sum_mean` (zero to rounding for the tangent method),
/// `sum_max_abs`, `floored` (finite differences: separations floored at
/// ε·δ0); `exponents` and `per_collision`: `(n_ics, 5)` arrays; `times`;
/// `alpha`, `table`, `method`, `delta0`, `qr_interval`, `collisions_per_ic`,
/// `sampler`, `seed`, `n_ics`, `first_index`, `wall_time_s`.
#[pyclass(frozen, name = "SpectrumResult", module = "spinball")]
pub struct PySpectrumResult {
    pub(crate) inner: SpectrumEstimate,
    pub(crate) alpha: f64,
    pub(crate) table: String,
    /// The table as results record it (for `to_json`'s document).
    pub(crate) record: TableRecord,
}

impl PySpectrumResult {
    fn matrix(
        &self,
        py: Python<'_>,
        f: impl Fn(&spinball_analysis::estimators::Spectrum) -> [f64; 5],
    ) -> PyResult<Py<PyArray2<f64>>> {
        let flat: Vec<f64> = self.inner.spectra.iter().flat_map(f).collect();
        let a = Array2::from_shape_vec((self.inner.spectra.len(), 5), flat)
            .map_err(|e| PyRuntimeError::new_err(e.to_string()))?;
        Ok(a.into_pyarray(py).unbind())
    }
}

#[pymethods]
impl PySpectrumResult {
    /// Mean of each of the five exponents (per unit time).
    #[getter]
    fn mean(&self, py: Python<'_>) -> Py<PyArray1<f64>> {
        self.inner.mean.to_vec().into_pyarray(py).unbind()
    }
    /// Standard error of each mean.
    #[getter]
    fn sem(&self, py: Python<'_>) -> Py<PyArray1<f64>> {
        self.inner.sem.to_vec().into_pyarray(py).unbind()
    }
    /// Mean of each exponent per collision.
    #[getter]
    fn per_collision_mean(&self, py: Python<'_>) -> Py<PyArray1<f64>> {
        self.inner
            .per_collision_mean
            .to_vec()
            .into_pyarray(py)
            .unbind()
    }
    /// Mean of the per-trajectory sums of the exponents.
    #[getter]
    fn sum_mean(&self) -> f64 {
        self.inner.sum_mean
    }
    /// Largest |sum| over the trajectories.
    #[getter]
    fn sum_max_abs(&self) -> f64 {
        self.inner.sum_max_abs
    }
    /// Finite differences: separations floored at ε·δ0 (0 for tangent).
    #[getter]
    fn floored(&self) -> u64 {
        self.inner.floored
    }
    /// Per-trajectory spectra, shape `(n_ics, 5)`, per unit time.
    #[getter]
    fn exponents(&self, py: Python<'_>) -> PyResult<Py<PyArray2<f64>>> {
        self.matrix(py, |s| s.exponents)
    }
    /// Per-trajectory spectra per collision, shape `(n_ics, 5)`.
    #[getter]
    fn per_collision(&self, py: Python<'_>) -> PyResult<Py<PyArray2<f64>>> {
        self.matrix(py, |s| s.per_collision)
    }
    /// Per-trajectory flight time.
    #[getter]
    fn times(&self, py: Python<'_>) -> Py<PyArray1<f64>> {
        let t: Vec<f64> = self.inner.spectra.iter().map(|s| s.time).collect();
        t.into_pyarray(py).unbind()
    }
    /// Spin parameter α.
    #[getter]
    fn alpha(&self) -> f64 {
        self.alpha
    }
    /// Spec string of the table.
    #[getter]
    fn table(&self) -> String {
        self.table.clone()
    }
    /// `"fd"` or `"tangent"`.
    #[getter]
    fn method(&self) -> &'static str {
        self.inner.options.method.name()
    }
    /// δ0 of finite differences (`None` for tangent).
    #[getter]
    fn delta0(&self) -> Option<f64> {
        match self.inner.options.method {
            spinball_analysis::estimators::Method::FiniteDifference { delta0 } => Some(delta0),
            spinball_analysis::estimators::Method::Tangent => None,
        }
    }
    /// Collisions between re-orthonormalisations.
    #[getter]
    fn qr_interval(&self) -> u32 {
        self.inner.options.qr_interval
    }
    /// Collisions per initial condition.
    #[getter]
    fn collisions_per_ic(&self) -> u64 {
        self.inner.options.collisions
    }
    /// `"paper"` or `"microcanonical"`.
    #[getter]
    fn sampler(&self) -> &'static str {
        self.inner.sampler.name()
    }
    /// Seed of the initial conditions.
    #[getter]
    fn seed(&self) -> u64 {
        self.inner.seed
    }
    /// Number of initial conditions.
    #[getter]
    fn n_ics(&self) -> u64 {
        self.inner.n_ics
    }
    /// First initial-condition index.
    #[getter]
    fn first_index(&self) -> u64 {
        self.inner.first_index
    }
    /// Wall-clock seconds.
    #[getter]
    fn wall_time_s(&self) -> f64 {
        self.inner.wall_time_s
    }
    /// The result document the command line writes for the same run
    /// (`spinball spectrum --json`: kind `spinball.spectrum`, one point),
    /// compact or indented by `indent` spaces per level.
    #[pyo3(signature = (indent = None))]
    fn to_json(&self, indent: Option<usize>) -> PyResult<String> {
        let first = self.inner.first_index;
        let doc = Document::Spectrum(SpectrumDocument::new(
            self.record.clone(),
            vec![self.alpha],
            None,
            first..first + self.inner.n_ics,
            vec![self.inner.clone()],
        ));
        match indent {
            None => doc.to_json(),
            Some(n) => doc.to_json_indent(n),
        }
        .map_err(|e| PyRuntimeError::new_err(format!("cannot serialise the result: {e}")))
    }
    /// The result's fields as a dict (the one point of `to_json()`'s
    /// document).
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        loads(py, &json(&self.inner, None)?)
    }
    fn __repr__(&self) -> String {
        let m = self.inner.mean;
        format!(
            "<SpectrumResult [{}, α = {}, {}, {} ICs × {} collisions] λ = [{:.4}, {:.4}, {:.4}, {:.4}, {:.4}]>",
            self.table,
            self.alpha,
            self.inner.options.method.name(),
            self.inner.n_ics,
            self.inner.options.collisions,
            m[0],
            m[1],
            m[2],
            m[3],
            m[4]
        )
    }
}

/// The Lyapunov results of a result document (the `--json` file of
/// `spinball lyapunov`, `ftle` or `merge`, `write_results` or `to_json`
/// text, or a bare result of spinball 0.2's `to_json`), one per α. Raises
/// `ValueError` naming the schema found and the schema this version reads
/// for a file of another version (spinball 0.1 results load), and for
/// text that is not such a document.
#[pyfunction]
pub fn read_results(text: &str) -> PyResult<Vec<PyLyapunovResult>> {
    let doc = LyapunovDocument::from_json(text).map_err(|e| value_error(e.to_string()))?;
    Ok(doc
        .points
        .into_iter()
        .map(|inner| PyLyapunovResult { inner })
        .collect())
}

/// `results` as a result document (kind `spinball.lyapunov`, the format
/// of `spinball lyapunov --json`): one line, or indented if `pretty`.
#[pyfunction]
#[pyo3(signature = (results, pretty = false))]
pub fn write_results(results: Vec<PyRef<'_, PyLyapunovResult>>, pretty: bool) -> PyResult<String> {
    let doc = Document::Lyapunov(LyapunovDocument::new(
        results.iter().map(|r| r.inner.clone()).collect(),
    ));
    let text = if pretty {
        doc.to_json_pretty()
    } else {
        doc.to_json()
    };
    text.map_err(|e| PyRuntimeError::new_err(format!("cannot serialise the results: {e}")))
}
