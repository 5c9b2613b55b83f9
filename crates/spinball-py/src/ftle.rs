//! `FtleDistribution`: the per-trajectory finite-time exponents of an
//! ensemble, with the statistics the paper reads from them.

use numpy::{IntoPyArray, PyArray1};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use spinball_analysis::estimators::{FtleDistribution, THRESHOLD_BAND};

use crate::args::count;
use crate::errors::analysis;

/// `(counts, edges)` of a histogram.
type Histogram<'py> = (Bound<'py, PyArray1<i64>>, Bound<'py, PyArray1<f64>>);

/// The distribution of finite-time Lyapunov exponents (per unit time) over
/// an ensemble: `LyapunovResult.ftle()`, or built from any sequence of
/// exponents. Raises `ValueError` for an empty sequence or a non-finite
/// exponent.
#[pyclass(frozen, name = "FtleDistribution", module = "spinball")]
pub struct PyFtleDistribution {
    pub(crate) inner: FtleDistribution,
}

#[pymethods]
impl PyFtleDistribution {
    #[new]
    fn new(exponents: Vec<f64>) -> PyResult<Self> {
        Ok(PyFtleDistribution {
            inner: FtleDistribution::new(exponents).map_err(analysis)?,
        })
    }
    /// The exponents, in index order (float64 array).
    #[getter]
    fn exponents<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        self.inner.exponents().to_vec().into_pyarray(py)
    }
    /// Mean exponent.
    #[getter]
    fn mean(&self) -> f64 {
        self.inner.mean()
    }
    /// Median exponent.
    #[getter]
    fn median(&self) -> f64 {
        self.inner.median()
    }
    /// Sample standard deviation (`None` for one exponent).
    #[getter]
    fn std(&self) -> Option<f64> {
        self.inner.std()
    }
    /// Standard error of the mean (`None` for one exponent).
    #[getter]
    fn sem(&self) -> Option<f64> {
        self.inner.sem()
    }
    /// Smallest exponent.
    #[getter]
    fn min(&self) -> f64 {
        self.inner.min()
    }
    /// Largest exponent.
    #[getter]
    fn max(&self) -> f64 {
        self.inner.max()
    }
    /// The `q`-quantile, `0 <= q <= 1` (NumPy's default "linear" method).
    /// Raises `ValueError` for `q` outside `[0, 1]`.
    fn quantile(&self, q: f64) -> PyResult<f64> {
        self.inner.quantile(q).map_err(analysis)
    }
    /// Mean over the chaotic trajectories (FTLE > `threshold`); `None` if
    /// there are none.
    #[pyo3(signature = (threshold = 0.01))]
    fn conditional_mean(&self, threshold: f64) -> Option<f64> {
        self.inner.conditional_mean(threshold)
    }
    /// `(fraction, sem)`: the share of trajectories with FTLE > `threshold`
    /// (default 0.01, the paper's) and its binomial standard error.
    #[pyo3(signature = (threshold = 0.01))]
    fn chaotic_fraction(&self, threshold: f64) -> (f64, f64) {
        let f = self.inner.chaotic_fraction_at(threshold);
        (f.fraction, f.sem)
    }
    /// The chaotic fraction over a band of thresholds (default the paper's
    /// 0.001–0.05): a dict with arrays `thresholds`, `fractions`, `sems` and
    /// floats `min`, `max`, `spread` (max − min).
    #[pyo3(signature = (thresholds = None))]
    fn chaotic_fraction_band<'py>(
        &self,
        py: Python<'py>,
        thresholds: Option<Vec<f64>>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let t = thresholds.unwrap_or_else(|| THRESHOLD_BAND.to_vec());
        let band = self.inner.chaotic_fraction_band(&t);
        let d = PyDict::new(py);
        d.set_item("thresholds", t.into_pyarray(py))?;
        let fr: Vec<f64> = band.points.iter().map(|p| p.fraction).collect();
        let se: Vec<f64> = band.points.iter().map(|p| p.sem).collect();
        d.set_item("fractions", fr.into_pyarray(py))?;
        d.set_item("sems", se.into_pyarray(py))?;
        d.set_item("min", band.min)?;
        d.set_item("max", band.max)?;
        d.set_item("spread", band.spread())?;
        Ok(d)
    }
    /// The Datseris–Hupe–Fleischmann product `mean · chaotic fraction`.
    #[pyo3(signature = (threshold = 0.01))]
    fn dhf_product(&self, threshold: f64) -> f64 {
        self.inner.dhf_product(threshold)
    }
    /// `(counts, edges)` like `numpy.histogram`: `bins` equal bins over
    /// `range = (lo, hi)` (default: the data's range); counts int64, edges
    /// float64 of length `bins + 1`. Bins are half-open `[lo, hi)`; values
    /// outside `[lo, hi)` are not counted. Raises `ValueError` for `bins < 1` or a range without
    /// finite `lo < hi`.
    #[pyo3(signature = (bins = 50, range = None))]
    fn histogram<'py>(
        &self,
        py: Python<'py>,
        bins: i64,
        range: Option<(f64, f64)>,
    ) -> PyResult<Histogram<'py>> {
        let bins = count("bins", bins, 1)? as usize;
        let h = match range {
            Some((lo, hi)) => self.inner.histogram(lo, hi, bins),
            None => self.inner.auto_histogram(bins),
        }
        .map_err(analysis)?;
        let counts: Vec<i64> = h.counts().iter().map(|&c| c as i64).collect();
        Ok((counts.into_pyarray(py), h.edges().into_pyarray(py)))
    }
    fn __len__(&self) -> usize {
        self.inner.len()
    }
    fn __repr__(&self) -> String {
        format!(
            "FtleDistribution(<{} exponents, mean {:.4}, median {:.4}>)",
            self.inner.len(),
            self.inner.mean(),
            self.inner.median()
        )
    }
}
