//! Open and periodic tables from Python: `escape` (how long balls take to
//! leave through a hole) and `diffuse` (how they spread through a Lorentz
//! gas), their result classes, and the `LorentzGas` class.
//!
//! Every number comes from `spinball-analysis`: the run and the document
//! are `EscapeDocument::run` and `DiffusionDocument::run`, the summaries
//! `EscapeSummary` and `DiffusionSummary`, so `to_json()` is the document
//! `spinball escape --json` and `spinball diffuse --json` write (the file
//! holds that text and a newline).

use numpy::ndarray::{Array2, Array3};
use numpy::{IntoPyArray, PyArray1, PyArray2, PyArray3};
use pyo3::exceptions::PyRuntimeError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use spinball_analysis::escape::{ClockSummary, EscapeOptions, RateWindow, TailWindow};
use spinball_analysis::estimators::Fitted;
use spinball_analysis::open::Budget;
use spinball_analysis::report::{DiffusionDocument, Document, EscapeDocument, OpenRun};
use spinball_analysis::run::{DiffusionDefaults, EscapeDefaults, RunDefaults};
use spinball_analysis::transport::{Diffusion, FitWindow, Horizon};
use spinball_analysis::{AnalysisError, escape::EscapeError, transport::TransportError};
use spinball_core::Billiard;
use spinball_geometry::{Built, Lattice, LorentzGas};

use crate::args::{self, count};
use crate::errors::{analysis, geometry, guarded, value_error};
use crate::results::loads;
use crate::tables::{PySegmentTable, segment_table, table_arg};

/// A refused table or option is a `ValueError`; a failed run a
/// `RuntimeError`.
fn open_error(e: AnalysisError) -> PyErr {
    match e {
        AnalysisError::Escape(EscapeError::NoHole | EscapeError::InvalidOption { .. })
        | AnalysisError::Transport(_) => value_error(e.to_string()),
        e => analysis(e),
    }
}

/// The run of `table` at `alpha`.
#[allow(clippy::too_many_arguments)]
fn open_run(
    table: &Bound<'_, PyAny>,
    alpha: f64,
    extended: bool,
    ics: i64,
    min_ics: i64,
    seed: u64,
    sampler: Option<&str>,
    threads: Option<i64>,
) -> PyResult<OpenRun<Built>> {
    let table: Built = table_arg(table)?.into();
    Ok(OpenRun {
        billiard: Billiard::new(table, args::law(alpha, extended)?),
        sampler: args::sampler(sampler)?,
        seed,
        ics: 0..count("ics", ics, min_ics)?,
        threads: args::threads(threads)?,
    })
}

fn document_json(doc: &Document, indent: Option<usize>) -> PyResult<String> {
    match indent {
        None => doc.to_json(),
        Some(n) => doc.to_json_indent(n),
    }
    .map_err(|e| PyRuntimeError::new_err(format!("cannot serialise the result: {e}")))
}

fn floats<'py>(py: Python<'py>, values: Vec<f64>) -> Bound<'py, PyArray1<f64>> {
    values.into_pyarray(py)
}

/// How long balls take to leave `table` through a hole at spin parameter
/// `alpha`; returns an `EscapeResult`.
///
/// `table`: a table with a hole (`SegmentTable.stadium_with_hole`, a
/// `SegmentTable` with `with_hole` / `with_hole_at`, a table file with
/// `exits` or `openings`, or a spec such as `"stadium:a=1,hole=0.2"`).
/// `ics` balls (streams `0..ics` of `seed`, drawn by `sampler`) run until
/// they escape or the budget runs out: `collisions` (default 100 000 when
/// `time` is not given) and/or `time`; a ball still inside then is
/// censored, never dropped. `window` / `collision_window` (`(t0, t1)`)
/// set the escape-rate windows, `tail_from` / `collision_tail_from` the
/// start of the tail (defaults: the documented rules). The GIL is
/// released.
///
/// Raises `ValueError` for a table without a hole (add one), a bad α,
/// budget or option; `RuntimeError` if a trajectory fails.
#[pyfunction]
#[pyo3(signature = (
    table, alpha, *, ics = EscapeDefaults::ICS as i64, collisions = None, time = None,
    seed = RunDefaults::SEED, sampler = None, threads = None, window = None,
    collision_window = None, tail_from = None, collision_tail_from = None, extended = false
))]
#[allow(clippy::too_many_arguments)]
pub fn escape(
    py: Python<'_>,
    table: &Bound<'_, PyAny>,
    alpha: f64,
    ics: i64,
    collisions: Option<i64>,
    time: Option<f64>,
    seed: u64,
    sampler: Option<&str>,
    threads: Option<i64>,
    window: Option<(f64, f64)>,
    collision_window: Option<(f64, f64)>,
    tail_from: Option<f64>,
    collision_tail_from: Option<f64>,
    extended: bool,
) -> PyResult<PyEscapeResult> {
    let run = open_run(table, alpha, extended, ics, 1, seed, sampler, threads)?;
    let collisions = collisions.map(|n| count("collisions", n, 1)).transpose()?;
    let budget = match (collisions, time) {
        (Some(n), Some(t)) => Budget {
            collisions: n,
            time: t,
        },
        (None, Some(t)) => Budget::time(t),
        (n, None) => Budget::collisions(n.unwrap_or(EscapeDefaults::COLLISIONS)),
    };
    let range = |w: Option<(f64, f64)>| {
        w.map_or_else(RateWindow::default, |(t0, t1)| RateWindow::Range { t0, t1 })
    };
    let tail =
        |t: Option<f64>| t.map_or_else(TailWindow::default, |t_min| TailWindow::From { t_min });
    let options = EscapeOptions {
        time_window: range(window),
        collision_window: range(collision_window),
        time_tail: tail(tail_from),
        collision_tail: tail(collision_tail_from),
        ..EscapeOptions::default()
    };
    let doc = py.detach(|| {
        guarded(
            || EscapeDocument::run(&run, budget, options, &mut |_, _| {}),
            open_error,
        )
    })?;
    Ok(PyEscapeResult { doc })
}

/// The result of `escape`: every ball's record as NumPy arrays and the
/// summary (survival curve with its band, escape rate, tail, mean escape
/// time against Kac) in time and in collisions.
#[pyclass(frozen, name = "EscapeResult", module = "spinball")]
pub struct PyEscapeResult {
    doc: EscapeDocument,
}

impl PyEscapeResult {
    fn clock(&self, clock: &str) -> PyResult<&Fitted<ClockSummary>> {
        match clock {
            "time" => Ok(&self.doc.summary.time),
            "collisions" => Ok(&self.doc.summary.collisions),
            other => Err(value_error(format!(
                "unknown clock `{other}` (expected time or collisions)"
            ))),
        }
    }

    fn exits(&self, f: impl Fn(&spinball_core::Exit) -> f64) -> Vec<f64> {
        self.doc
            .records
            .iter()
            .map(|r| r.exit.as_ref().map_or(f64::NAN, &f))
            .collect()
    }
}

#[pymethods]
impl PyEscapeResult {
    /// Index of each ball's initial condition.
    #[getter]
    fn index<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<u64>> {
        let v: Vec<u64> = self.doc.records.iter().map(|r| r.index).collect();
        v.into_pyarray(py)
    }
    /// Escape time of each ball (for a censored ball, the time it was last
    /// seen inside).
    #[getter]
    fn times<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        floats(py, self.doc.records.iter().map(|r| r.time).collect())
    }
    /// Collisions of each ball before the hole (or before the budget ran
    /// out).
    #[getter]
    fn collisions<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<u64>> {
        let v: Vec<u64> = self.doc.records.iter().map(|r| r.collisions).collect();
        v.into_pyarray(py)
    }
    /// Whether each ball was still inside at the budget.
    #[getter]
    fn censored<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<bool>> {
        let v: Vec<bool> = self.doc.records.iter().map(|r| r.censored).collect();
        v.into_pyarray(py)
    }
    /// Where each ball left, `(n, 2)` (NaN for a censored ball).
    #[getter]
    fn exit_point<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let (x, y) = (self.exits(|e| e.point.x), self.exits(|e| e.point.y));
        let flat: Vec<f64> = x.iter().zip(&y).flat_map(|(a, b)| [*a, *b]).collect();
        Array2::from_shape_vec((x.len(), 2), flat)
            .map(|a| a.into_pyarray(py))
            .map_err(|e| PyRuntimeError::new_err(e.to_string()))
    }
    /// Birkhoff `s` of each exit (NaN for a censored ball).
    #[getter]
    fn exit_s<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        floats(py, self.exits(|e| e.s))
    }
    /// Tangential velocity `v∥` of each exit (NaN for a censored ball).
    #[getter]
    fn exit_v_par<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        floats(py, self.exits(|e| e.v_par))
    }
    /// Spin `u` of each exit (NaN for a censored ball).
    #[getter]
    fn exit_spin<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        floats(py, self.exits(|e| e.spin))
    }
    /// Balls that escaped.
    #[getter]
    fn escaped(&self) -> u64 {
        self.doc.summary.escaped
    }
    /// Balls still inside at the budget.
    #[getter]
    fn n_censored(&self) -> u64 {
        self.doc.summary.censored
    }
    /// The survival curve on `clock` (`"time"` or `"collisions"`, the hole
    /// counted): a dict of arrays `t`, `p` (Kaplan–Meier), `sem`
    /// (Greenwood), `lower`, `upper` (the 95 % log–log band), `at_risk`;
    /// `None` if no ball escaped.
    #[pyo3(signature = (clock = "time"))]
    fn survival<'py>(&self, py: Python<'py>, clock: &str) -> PyResult<Option<Bound<'py, PyDict>>> {
        let Some(c) = self.clock(clock)?.fit() else {
            return Ok(None);
        };
        let pts = c.survival.points();
        let out = PyDict::new(py);
        let col = |f: &dyn Fn(&spinball_analysis::escape::SurvivalPoint) -> f64| {
            pts.iter().map(f).collect::<Vec<f64>>()
        };
        out.set_item("t", floats(py, col(&|p| p.t)))?;
        out.set_item("p", floats(py, col(&|p| p.survival)))?;
        out.set_item("sem", floats(py, col(&|p| p.std_error)))?;
        out.set_item("lower", floats(py, col(&|p| p.lower)))?;
        out.set_item("upper", floats(py, col(&|p| p.upper)))?;
        out.set_item("at_risk", floats(py, col(&|p| p.at_risk as f64)))?;
        Ok(Some(out))
    }
    /// The escape rate `(γ, SEM)` on `clock` (per unit time, or per
    /// collision), `None` where it was refused (see `summary`).
    #[pyo3(signature = (clock = "time"))]
    fn escape_rate(&self, clock: &str) -> PyResult<Option<(f64, f64)>> {
        Ok(self
            .clock(clock)?
            .fit()
            .and_then(|c| c.rate.fit())
            .map(|r| (r.gamma, r.sem)))
    }
    /// The mean escape time `(mean, SEM, complete)` on `clock`; with
    /// censored balls it is a lower bound (`complete` False). `None` if no
    /// ball escaped.
    #[pyo3(signature = (clock = "time"))]
    fn mean_escape(&self, clock: &str) -> PyResult<Option<(f64, f64, bool)>> {
        Ok(self
            .clock(clock)?
            .fit()
            .map(|c| (c.mean.mean, c.mean.sem, c.mean.complete)))
    }
    /// The mean escape time over Kac's prediction `(ratio, SEM)` on
    /// `clock`, `None` for a table without one (periodic walls) or no
    /// escape.
    #[pyo3(signature = (clock = "time"))]
    fn kac_ratio(&self, clock: &str) -> PyResult<Option<(f64, f64)>> {
        Ok(self
            .clock(clock)?
            .fit()
            .and_then(|c| c.kac)
            .map(|k| (k.ratio, k.ratio_sem)))
    }
    /// The tail on `clock`: `(law, β, SEM of β)` with law `"algebraic"`,
    /// `"exponential"` or `"undecided"`; `None` where it was refused.
    #[pyo3(signature = (clock = "time"))]
    fn tail(&self, clock: &str) -> PyResult<Option<(String, f64, f64)>> {
        Ok(self
            .clock(clock)?
            .fit()
            .and_then(|c| c.tail.fit())
            .map(|t| (t.law.to_string(), t.beta, t.beta_sem)))
    }
    /// The whole summary as a dict (the `summary` of `to_json()`'s
    /// document; a refused estimate is `{"refused": reason}`).
    #[getter]
    fn summary<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        loads(py, &crate::results::json(&self.doc.summary, None)?)
    }
    /// The `spinball.escape` document `spinball escape --json` writes for
    /// the same run (the file is this text and a newline), compact or
    /// indented by `indent` spaces.
    #[pyo3(signature = (indent = None))]
    fn to_json(&self, indent: Option<usize>) -> PyResult<String> {
        document_json(&Document::Escape(self.doc.clone()), indent)
    }
    fn __repr__(&self) -> String {
        format!(
            "<EscapeResult [{}, α = {}] {} balls, {} escaped, {} censored>",
            self.doc.head.table,
            self.doc.head.alpha,
            self.doc.summary.n,
            self.doc.summary.escaped,
            self.doc.summary.censored
        )
    }
    fn __str__(&self) -> String {
        self.doc.summary.to_string()
    }
}

/// How balls spread through the periodic `table` (a Lorentz gas's cell) at
/// spin parameter `alpha`; returns a `DiffusionResult`.
///
/// `table`: `LorentzGas(...).table()` or a spec such as
/// `"lorentz:lattice=triangular,w=1,R=0.45"`. `ics` initial conditions
/// (at least 2) are followed with exact unwrapped positions and their
/// displacement recorded at `times` (increasing; default `checkpoints`
/// evenly spaced up to `until`). `window` `(t0, t1)` is the Einstein
/// relation's fit window (default the later half). With an infinite
/// horizon the marginal coefficient of `t ln t` growth is reported, never a
/// finite `D`. The GIL is released.
///
/// Raises `ValueError` for a table without periodic walls, of unknown
/// horizon, or with holes, and for bad options; `RuntimeError` if a
/// trajectory fails.
#[pyfunction]
#[pyo3(signature = (
    table, alpha, *, ics = DiffusionDefaults::ICS as i64, times = None,
    until = DiffusionDefaults::UNTIL, checkpoints = DiffusionDefaults::CHECKPOINTS as i64,
    seed = RunDefaults::SEED, sampler = None, threads = None, window = None, extended = false
))]
#[allow(clippy::too_many_arguments)]
pub fn diffuse(
    py: Python<'_>,
    table: &Bound<'_, PyAny>,
    alpha: f64,
    ics: i64,
    times: Option<Vec<f64>>,
    until: f64,
    checkpoints: i64,
    seed: u64,
    sampler: Option<&str>,
    threads: Option<i64>,
    window: Option<(f64, f64)>,
    extended: bool,
) -> PyResult<PyDiffusionResult> {
    let run = open_run(table, alpha, extended, ics, 2, seed, sampler, threads)?;
    let times = match times {
        Some(t) => t,
        None => {
            let n = count("checkpoints", checkpoints, 3)?;
            if !(until.is_finite() && until > 0.0) {
                return Err(value_error(format!(
                    "until = {until}: the last checkpoint must be a finite time > 0"
                )));
            }
            (1..=n).map(|k| until * k as f64 / n as f64).collect()
        }
    };
    let window = window
        .map(|(t0, t1)| FitWindow::new(t0, t1))
        .transpose()
        .map_err(|e: TransportError| value_error(format!("window: {e}")))?;
    let doc = py.detach(|| {
        guarded(
            || DiffusionDocument::run(&run, &times, window, &mut |_, _| {}),
            open_error,
        )
    })?;
    Ok(PyDiffusionResult { doc })
}

/// The result of `diffuse`: every initial condition's displacements, the
/// mean-square displacement with its errors, and `D` (or the marginal
/// coefficient) with its error and window.
#[pyclass(frozen, name = "DiffusionResult", module = "spinball")]
pub struct PyDiffusionResult {
    doc: DiffusionDocument,
}

#[pymethods]
impl PyDiffusionResult {
    /// The checkpoint times.
    #[getter]
    fn times<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        floats(py, self.doc.times.clone())
    }
    /// Unwrapped displacements, `(ICs, checkpoints, 2)`.
    #[getter]
    fn displacements<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray3<f64>>> {
        let (shape, values) = self.doc.array();
        let dims = (shape[0] as usize, shape[1] as usize, 2);
        Array3::from_shape_vec(dims, values)
            .map(|a| a.into_pyarray(py))
            .map_err(|e| PyRuntimeError::new_err(e.to_string()))
    }
    /// `⟨Δr²⟩` at each checkpoint.
    #[getter]
    fn msd<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        floats(
            py,
            self.doc
                .summary
                .msd
                .points()
                .iter()
                .map(|p| p.msd)
                .collect(),
        )
    }
    /// Standard error of `⟨Δr²⟩` at each checkpoint.
    #[getter]
    fn msd_sem<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        floats(
            py,
            self.doc
                .summary
                .msd
                .points()
                .iter()
                .map(|p| p.sem)
                .collect(),
        )
    }
    /// `"finite"` or `"infinite"`.
    #[getter]
    fn horizon(&self) -> String {
        self.doc.summary.horizon.to_string()
    }
    /// `(D, SEM)` for a finite horizon; `None` for an infinite one (there
    /// is no finite `D`) or a refused fit.
    #[getter]
    fn diffusion_coefficient(&self) -> Option<(f64, f64)> {
        match self.doc.summary.estimate.fit()? {
            Diffusion::Normal(f) => Some((f.coefficient, f.sem)),
            Diffusion::Marginal(_) | Diffusion::Ballistic(..) => None,
        }
    }
    /// `(D_m, SEM)`, the coefficient of `⟨Δr²⟩ ≈ 4 D_m t ln t`, for an
    /// infinite horizon; `None` otherwise.
    #[getter]
    fn marginal_coefficient(&self) -> Option<(f64, f64)> {
        match self.doc.summary.estimate.fit()? {
            Diffusion::Marginal(f) => Some((f.coefficient, f.sem)),
            Diffusion::Normal(_) | Diffusion::Ballistic(..) => None,
        }
    }
    /// The fit window `(t0, t1)` of the estimate, `None` if refused.
    #[getter]
    fn window(&self) -> Option<(f64, f64)> {
        let w = self.doc.summary.estimate.fit()?.fit().window;
        Some((w.t0, w.t1))
    }
    /// The whole summary as a dict (the `summary` of `to_json()`'s
    /// document, with the window scan).
    #[getter]
    fn summary<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        loads(py, &crate::results::json(&self.doc.summary, None)?)
    }
    /// The `spinball.diffusion` document `spinball diffuse --json` writes
    /// for the same run (the file is this text and a newline).
    #[pyo3(signature = (indent = None))]
    fn to_json(&self, indent: Option<usize>) -> PyResult<String> {
        document_json(&Document::Diffusion(self.doc.clone()), indent)
    }
    fn __repr__(&self) -> String {
        format!(
            "<DiffusionResult [{}, α = {}] {} ICs, {} horizon>",
            self.doc.head.table,
            self.doc.head.alpha,
            self.doc.records.len(),
            self.doc.summary.horizon
        )
    }
    fn __str__(&self) -> String {
        self.doc.summary.to_string()
    }
}

/// A periodic Lorentz gas: disks of radius `R` on a `lattice`
/// (`"square"` or `"triangular"`) of spacing `w`, run as one cell with
/// periodic sides. Raises `ValueError` unless `0 < R < w/2`.
#[pyclass(frozen, name = "LorentzGas", module = "spinball")]
pub struct PyLorentzGas {
    inner: LorentzGas,
}

#[pymethods]
impl PyLorentzGas {
    #[new]
    #[pyo3(signature = (lattice = "triangular", w = 1.0, R = 0.4))]
    #[allow(non_snake_case)]
    fn new(lattice: &str, w: f64, R: f64) -> PyResult<Self> {
        let inner = match lattice.trim().to_ascii_lowercase().as_str() {
            "square" => LorentzGas::square(w, R),
            "triangular" => LorentzGas::triangular(w, R),
            other => {
                return Err(value_error(format!(
                    "unknown lattice `{other}` (expected square or triangular)"
                )));
            }
        }
        .map_err(geometry)?;
        Ok(PyLorentzGas { inner })
    }
    /// The unit cell as a `SegmentTable` with periodic sides.
    fn table(&self, py: Python<'_>) -> PyResult<Py<PySegmentTable>> {
        Py::new(py, segment_table(self.inner.table().map_err(geometry)?))
    }
    /// `"finite"` (every free flight bounded) or `"infinite"` (corridors).
    #[getter]
    fn horizon(&self) -> String {
        Horizon::from(self.inner.horizon()).to_string()
    }
    /// `"square"` or `"triangular"`.
    #[getter]
    fn lattice(&self) -> &'static str {
        match self.inner.lattice() {
            Lattice::Square => "square",
            Lattice::Triangular => "triangular",
        }
    }
    /// Lattice spacing.
    #[getter]
    fn w(&self) -> f64 {
        self.inner.w()
    }
    /// Disk radius.
    #[getter]
    #[allow(non_snake_case)]
    fn R(&self) -> f64 {
        self.inner.r()
    }
    /// The spec string, `lorentz:lattice=…,w=…,R=…`.
    #[getter]
    fn spec(&self) -> String {
        format!(
            "lorentz:lattice={},w={},R={}",
            self.lattice(),
            self.inner.w(),
            self.inner.r()
        )
    }
    fn __repr__(&self) -> String {
        format!(
            "LorentzGas(lattice={:?}, w={:?}, R={:?})",
            self.lattice(),
            self.inner.w(),
            self.inner.r()
        )
    }
}

/// Add the open-table functions and classes to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(escape, m)?)?;
    m.add_function(wrap_pyfunction!(diffuse, m)?)?;
    m.add_class::<PyEscapeResult>()?;
    m.add_class::<PyDiffusionResult>()?;
    m.add_class::<PyLorentzGas>()?;
    Ok(())
}
