//! `Billiard(table, alpha, extended=False)`: single trajectories as NumPy
//! arrays, and the initial conditions of an ensemble.
//!
//! A trajectory of `n` collisions is computed in Rust with the GIL released
//! and comes back as one array per quantity (no Python loop per collision).

use numpy::ndarray::Array2;
use numpy::{IntoPyArray, PyArray1, PyArray2};
use pyo3::exceptions::PyRuntimeError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use spinball_analysis::AnalysisError;
use spinball_analysis::diagnostics::collision_log;
use spinball_core::{Billiard, Sampler, SpinLaw, State};
use spinball_geometry::{Boundary, DVec2};

use crate::args::{count, law, pair};
use crate::errors::{guarded, value_error};
use crate::tables::{AnyTable, table_arg};
use crate::with_table;

/// A spinning billiard: a table and the spin law of
/// `alpha = I/(m r²)` (0 specular, 0.4 solid sphere, 0.5 disk, 1 thin
/// ring). `alpha` must lie in `[0, 1]` unless `extended=True` (any finite
/// `alpha >= 0`, the mathematical extension). `table` is a table object or
/// a spec string (`"stadium:a=1"`). Raises `ValueError` for an invalid
/// `alpha` or spec, `TypeError` for something that is not a table.
#[pyclass(frozen, name = "Billiard", module = "spinball")]
pub struct PyBilliard {
    table: AnyTable,
    law: SpinLaw,
    extended: bool,
}

#[pymethods]
impl PyBilliard {
    #[new]
    #[pyo3(signature = (table, alpha, extended = false))]
    fn new(table: &Bound<'_, PyAny>, alpha: f64, extended: bool) -> PyResult<Self> {
        Ok(PyBilliard {
            table: table_arg(table)?,
            law: law(alpha, extended)?,
            extended,
        })
    }

    /// Spin parameter α.
    #[getter]
    fn alpha(&self) -> f64 {
        self.law.alpha()
    }
    /// Whether α may exceed 1.
    #[getter]
    fn extended(&self) -> bool {
        self.extended
    }
    /// The table's spec string.
    #[getter]
    fn table(&self) -> String {
        self.table.spec()
    }
    /// Energy `E = ½|v|² + ½ α u²` of the state `(vx, vy, u)` (mass 1).
    fn energy(&self, vx: f64, vy: f64, u: f64) -> f64 {
        self.law.energy(DVec2::new(vx, vy), u)
    }

    /// Follow one ball for `collisions` collisions from `position = (x, y)`
    /// with `velocity = (vx, vy)` and spin `u = rω` (default 0).
    ///
    /// Returns a `Trajectory` with one entry per collision: `time`
    /// (cumulative time of the collision), `x`, `y` (contact point), `vx`,
    /// `vy`, `u` (velocity and spin just after it), `wall` (wall id, int64),
    /// `s` (Birkhoff arc length of the contact), `v_par` (tangential
    /// velocity `v·t` just before it) and `q` (`Q = v∥ − αu`, conserved by
    /// each collision). `start` holds the launch state `(x, y, vx, vy, u)`.
    ///
    /// Raises `ValueError` for `collisions < 1`, a non-finite state, a ball
    /// at rest or outside the table; `RuntimeError` if a step fails.
    #[pyo3(signature = (collisions, position, velocity, spin = 0.0))]
    fn trajectory(
        &self,
        py: Python<'_>,
        collisions: i64,
        position: &Bound<'_, PyAny>,
        velocity: &Bound<'_, PyAny>,
        spin: f64,
    ) -> PyResult<PyTrajectory> {
        let n = count("collisions", collisions, 1)?;
        let (p, v) = (pair(position, "position")?, pair(velocity, "velocity")?);
        let start = State::new(DVec2::new(p.0, p.1), DVec2::new(v.0, v.1), spin);
        let law = self.law;
        let columns = py.detach(|| {
            guarded(
                || with_table!(&self.table, |t| follow(&Billiard::new(t, law), start, n)),
                |e| e,
            )
        })?;
        columns.into_python(py, start)
    }

    /// The initial conditions `first_index .. first_index + n` that an
    /// ensemble with `seed` and `sampler` (`"paper"` or `"microcanonical"`)
    /// runs, as an `(n, 5)` array of `(x, y, vx, vy, u)` (energy ½).
    /// Raises `ValueError` if the sampler finds no room in the table (the
    /// paper sampler in a ring or corridor narrower than 1% of its size).
    #[pyo3(signature = (n, seed = 0, sampler = None, first_index = 0))]
    fn initial_states<'py>(
        &self,
        py: Python<'py>,
        n: i64,
        seed: u64,
        sampler: Option<&str>,
        first_index: i64,
    ) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let n = count("n", n, 0)?;
        let first = count("first_index", first_index, 0)?;
        let draw: Sampler = crate::args::sampler(sampler)?;
        let law = self.law;
        let flat = py
            .detach(|| {
                with_table!(&self.table, |t| {
                    (first..first + n)
                        .map(|i| {
                            draw.try_initial_state(t, &law, seed, i)
                                .map(|s| s.to_array())
                        })
                        .collect::<Result<Vec<[f64; 5]>, _>>()
                })
            })
            .map_err(|e| value_error(e.to_string()))?
            .concat();
        let array = Array2::from_shape_vec((n as usize, 5), flat)
            .map_err(|e| PyRuntimeError::new_err(e.to_string()))?;
        Ok(array.into_pyarray(py))
    }

    fn __repr__(&self) -> String {
        let ext = if self.extended { ", extended=True" } else { "" };
        format!(
            "Billiard({}, alpha={:?}{ext})",
            self.table.repr(),
            self.law.alpha()
        )
    }
}

/// One column per quantity of a trajectory.
struct Columns {
    time: Vec<f64>,
    x: Vec<f64>,
    y: Vec<f64>,
    vx: Vec<f64>,
    vy: Vec<f64>,
    u: Vec<f64>,
    wall: Vec<i64>,
    s: Vec<f64>,
    v_par: Vec<f64>,
    q: Vec<f64>,
}

/// Step a ball from `start` for `n` collisions, keeping every collision
/// ([`collision_log`], whose columns these are).
fn follow<B: Boundary>(billiard: &Billiard<B>, start: State, n: u64) -> PyResult<Columns> {
    let log = collision_log(billiard, start, n).map_err(|e| match e {
        AnalysisError::Launch { source, .. } => value_error(format!("initial state: {source}")),
        other => PyRuntimeError::new_err(other.to_string()),
    })?;
    let [time, x, y, vx, vy, u, wall, s, v_par, q] = std::array::from_fn(|k| log.column(k));
    Ok(Columns {
        time,
        x,
        y,
        vx,
        vy,
        u,
        // Wall indices are small integers, stored exactly in the f64 row.
        wall: wall.into_iter().map(|w| w as i64).collect(),
        s,
        v_par,
        q,
    })
}

impl Columns {
    fn into_python(self, py: Python<'_>, start: State) -> PyResult<PyTrajectory> {
        let a = |v: Vec<f64>| v.into_pyarray(py).unbind();
        Ok(PyTrajectory {
            time: a(self.time),
            x: a(self.x),
            y: a(self.y),
            vx: a(self.vx),
            vy: a(self.vy),
            u: a(self.u),
            wall: self.wall.into_pyarray(py).unbind(),
            s: a(self.s),
            v_par: a(self.v_par),
            q: a(self.q),
            start: start.to_array(),
        })
    }
}

/// One trajectory, one NumPy array per quantity (see
/// `Billiard.trajectory`): `time`, `x`, `y`, `vx`, `vy`, `u`, `wall`,
/// `s`, `v_par`, `q`, each of length `collisions`; `start` is the launch
/// state `(x, y, vx, vy, u)`.
#[pyclass(frozen, name = "Trajectory", module = "spinball")]
pub struct PyTrajectory {
    time: Py<PyArray1<f64>>,
    x: Py<PyArray1<f64>>,
    y: Py<PyArray1<f64>>,
    vx: Py<PyArray1<f64>>,
    vy: Py<PyArray1<f64>>,
    u: Py<PyArray1<f64>>,
    wall: Py<PyArray1<i64>>,
    s: Py<PyArray1<f64>>,
    v_par: Py<PyArray1<f64>>,
    q: Py<PyArray1<f64>>,
    start: [f64; 5],
}

#[pymethods]
impl PyTrajectory {
    /// Cumulative time of each collision (float64).
    #[getter]
    fn time(&self, py: Python<'_>) -> Py<PyArray1<f64>> {
        self.time.clone_ref(py)
    }
    /// x of each contact point.
    #[getter]
    fn x(&self, py: Python<'_>) -> Py<PyArray1<f64>> {
        self.x.clone_ref(py)
    }
    /// y of each contact point.
    #[getter]
    fn y(&self, py: Python<'_>) -> Py<PyArray1<f64>> {
        self.y.clone_ref(py)
    }
    /// vx just after each collision.
    #[getter]
    fn vx(&self, py: Python<'_>) -> Py<PyArray1<f64>> {
        self.vx.clone_ref(py)
    }
    /// vy just after each collision.
    #[getter]
    fn vy(&self, py: Python<'_>) -> Py<PyArray1<f64>> {
        self.vy.clone_ref(py)
    }
    /// Spin u = rω just after each collision.
    #[getter]
    fn u(&self, py: Python<'_>) -> Py<PyArray1<f64>> {
        self.u.clone_ref(py)
    }
    /// Wall id of each collision (int64; each table's docs number its walls).
    #[getter]
    fn wall(&self, py: Python<'_>) -> Py<PyArray1<i64>> {
        self.wall.clone_ref(py)
    }
    /// Birkhoff arc length of each contact point.
    #[getter]
    fn s(&self, py: Python<'_>) -> Py<PyArray1<f64>> {
        self.s.clone_ref(py)
    }
    /// Tangential velocity v·t just before each collision.
    #[getter]
    fn v_par(&self, py: Python<'_>) -> Py<PyArray1<f64>> {
        self.v_par.clone_ref(py)
    }
    /// Q = v∥ − αu at each collision (conserved through it).
    #[getter]
    fn q(&self, py: Python<'_>) -> Py<PyArray1<f64>> {
        self.q.clone_ref(py)
    }
    /// The launch state (x, y, vx, vy, u).
    #[getter]
    fn start(&self) -> (f64, f64, f64, f64, f64) {
        let s = self.start;
        (s[0], s[1], s[2], s[3], s[4])
    }
    /// The arrays as a dict (e.g. for `numpy.savez(path, **t.to_dict())`).
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        for (k, v) in [
            ("time", &self.time),
            ("x", &self.x),
            ("y", &self.y),
            ("vx", &self.vx),
            ("vy", &self.vy),
            ("u", &self.u),
            ("s", &self.s),
            ("v_par", &self.v_par),
            ("q", &self.q),
        ] {
            d.set_item(k, v.clone_ref(py))?;
        }
        d.set_item("wall", self.wall.clone_ref(py))?;
        Ok(d)
    }
    fn __len__(&self, py: Python<'_>) -> usize {
        numpy::PyUntypedArrayMethods::len(self.time.bind(py))
    }
    fn __repr__(&self, py: Python<'_>) -> String {
        format!("Trajectory(<{} collisions>)", self.__len__(py))
    }
}
