//! `periodic_orbits`: the periodic orbits of a table, their stability
//! through a list of α and the α where it changes, as NumPy arrays.

use numpy::IntoPyArray;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use spinball_analysis::orbits::{SearchOptions, StabilityClass, stability_diagram};

use crate::errors::{analysis, guarded, value_error};
use crate::tables::table_arg;
use crate::with_table;

/// The periodic orbits of `period` collisions of `table` (a table object
/// or a spec string), found at `alphas[0]` by Newton's method with the
/// exact tangent map (from `normal_samples` normal-incidence seeds and a
/// `grid` `(ns, nv, nw)` of starts) and followed through `alphas`
/// (default 0 to 1 in 20 steps); each change of stability is located to
/// `precision` in α.
///
/// Returns a dict: `period`, `alphas`, `orbits` (one dict per orbit:
/// `walls` of its first α, float64 arrays over `alphas` of `s`, `v_par`,
/// `spin` (its first point), `pair_trace` (T), `residue` ((2 − T)/4),
/// `rotation` (NaN where not elliptic), `residual`; `classes`, a list of
/// names; `changes`, a list of dicts `alpha`, `error`, `crossing` (±2),
/// `before`, `after`), `seeds_failed` and `lost` (orbits lost on the way,
/// with why).
///
/// Raises `ValueError` for an empty `alphas`, a negative α, a `precision`
/// outside (0, 1), a period of 0 or a table that cannot place points by arc
/// length.
#[pyfunction]
#[pyo3(signature = (table, period = 2, alphas = None, *, precision = 1e-8, normal_samples = 4096, grid = (0, 0, 0)))]
pub fn periodic_orbits<'py>(
    py: Python<'py>,
    table: &Bound<'py, PyAny>,
    period: u32,
    alphas: Option<Vec<f64>>,
    precision: f64,
    normal_samples: u32,
    grid: (u32, u32, u32),
) -> PyResult<Bound<'py, PyDict>> {
    let table = table_arg(table)?;
    let alphas = alphas.unwrap_or_else(|| (0..=20).map(|i| f64::from(i) / 20.0).collect());
    if alphas.is_empty() {
        return Err(value_error("alphas: need at least one α"));
    }
    let search = SearchOptions {
        normal_samples,
        grid: [grid.0, grid.1, grid.2],
        ..SearchOptions::default()
    };
    let diagram = py.detach(|| {
        guarded(
            || {
                with_table!(table.clone(), |t| stability_diagram(
                    &t, period, &alphas, precision, &search
                ))
            },
            analysis,
        )
    })?;
    let orbits = PyList::empty(py);
    for b in &diagram.branches {
        let o = PyDict::new(py);
        let column = |f: &dyn Fn(&spinball_analysis::orbits::PeriodicOrbit) -> f64| {
            b.orbits.iter().map(f).collect::<Vec<f64>>()
        };
        o.set_item("walls", b.orbits[0].walls.clone())?;
        o.set_item("s", column(&|x| x.points[0].s).into_pyarray(py))?;
        o.set_item("v_par", column(&|x| x.points[0].v_par).into_pyarray(py))?;
        o.set_item("spin", column(&|x| x.points[0].spin).into_pyarray(py))?;
        o.set_item(
            "pair_trace",
            column(&|x| x.stability.pair_trace).into_pyarray(py),
        )?;
        o.set_item("residue", column(&|x| x.stability.residue).into_pyarray(py))?;
        o.set_item(
            "rotation",
            column(&|x| match x.stability.class {
                StabilityClass::Elliptic { rotation } => rotation,
                _ => f64::NAN,
            })
            .into_pyarray(py),
        )?;
        o.set_item("residual", column(&|x| x.residual).into_pyarray(py))?;
        let classes: Vec<&str> = b.orbits.iter().map(|x| x.stability.class.name()).collect();
        o.set_item("classes", classes)?;
        let changes = PyList::empty(py);
        for c in &b.changes {
            let d = PyDict::new(py);
            d.set_item("alpha", c.alpha)?;
            d.set_item("error", c.error)?;
            d.set_item("crossing", c.crossing)?;
            d.set_item("before", c.before.name())?;
            d.set_item("after", c.after.name())?;
            changes.append(d)?;
        }
        o.set_item("changes", changes)?;
        orbits.append(o)?;
    }
    let out = PyDict::new(py);
    out.set_item("period", diagram.period)?;
    out.set_item("alphas", diagram.alphas.clone().into_pyarray(py))?;
    out.set_item("orbits", orbits)?;
    out.set_item("seeds_failed", diagram.seeds_failed)?;
    out.set_item(
        "lost",
        diagram
            .lost
            .iter()
            .map(|(_, why)| why.clone())
            .collect::<Vec<_>>(),
    )?;
    Ok(out)
}
