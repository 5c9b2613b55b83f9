//! `periodic_orbits`: the periodic orbits of a table, their stability
//! through a list of α and the α where it changes, as NumPy arrays;
//! `island_sizes`: the island around one orbit against α.

use numpy::IntoPyArray;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use spinball_analysis::orbits::{
    BirkhoffPoint, IslandOptions, IslandPoint, NewtonOptions, SearchOptions, StabilityChange,
    StabilityClass, find_orbit, island_sizes as follow_islands, stability_diagram,
};
use spinball_core::{Billiard, SpinLaw};

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
        o.set_item("changes", changes_list(py, &b.changes)?)?;
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

/// The regular island around the periodic orbit of `period` collisions
/// nearest the start `(s, v_par, spin)` (found by Newton's method at
/// `alphas[0]`), followed through `alphas`: at each α where the orbit is
/// elliptic the island is measured on the slice of the section at the
/// orbit's spin, in `(s, sin θ)`, from an FTLE map of a `cells × cells`
/// window centred on the orbit's point `point` (`collisions` per cell,
/// regular at FTLE ≤ 0.01, flood fill from the orbit's cell, window
/// refitted to the island).
///
/// Returns a dict of float64 arrays over `alphas`: `alphas`, `area` (0
/// where the orbit is hyperbolic, NaN where it is parabolic or the
/// measurement failed), `error` (the island's boundary cells times a
/// cell's area), `pair_trace`, `s_min`, `s_max`, `sin_theta_min`,
/// `sin_theta_max` (the island's extent, NaN where not measured), and
/// `classes` (names), `failures` (why, or `None`), `changes` (dicts
/// `alpha`, `error`, `crossing`, `before`, `after`).
///
/// Raises `ValueError` for an empty `alphas`, bad options or a table that
/// cannot place points by arc length; `RuntimeError` if no orbit closes
/// from the start or it is lost on the way.
#[pyfunction]
#[pyo3(signature = (table, s, alphas, *, period = 2, v_par = 0.0, spin = 0.0, precision = 1e-8, cells = 41, collisions = 2000, seed = 0, point = 0))]
#[allow(clippy::too_many_arguments)]
pub fn island_sizes<'py>(
    py: Python<'py>,
    table: &Bound<'py, PyAny>,
    s: f64,
    alphas: Vec<f64>,
    period: u32,
    v_par: f64,
    spin: f64,
    precision: f64,
    cells: usize,
    collisions: u64,
    seed: u64,
    point: usize,
) -> PyResult<Bound<'py, PyDict>> {
    let table = table_arg(table)?;
    let first = *alphas
        .first()
        .ok_or_else(|| value_error("alphas: need at least one α"))?;
    let options = IslandOptions {
        point,
        ..IslandOptions::default()
            .with_cells(cells)
            .with_collisions(collisions)
            .with_seed(seed)
    };
    let newton = NewtonOptions::default();
    let curve = py.detach(|| {
        guarded(
            || {
                with_table!(table.clone(), |t| {
                    let billiard = Billiard::new(&t, SpinLaw::extended(first)?);
                    let start = BirkhoffPoint::new(s, v_par, spin);
                    let orbit = find_orbit(&billiard, start, period, &newton)?;
                    follow_islands(&t, &orbit, &alphas, precision, &newton, &options)
                })
            },
            analysis,
        )
    })?;
    let column = |f: &dyn Fn(&IslandPoint) -> Option<f64>| {
        curve
            .points
            .iter()
            .map(|p| f(p).unwrap_or(f64::NAN))
            .collect::<Vec<f64>>()
            .into_pyarray(py)
    };
    let out = PyDict::new(py);
    out.set_item("alphas", column(&|p| Some(p.alpha)))?;
    out.set_item("area", column(&|p| p.area))?;
    out.set_item("error", column(&|p| p.error))?;
    out.set_item("pair_trace", column(&|p| Some(p.pair_trace)))?;
    out.set_item("s_min", column(&|p| Some(p.size?.s_extent[0])))?;
    out.set_item("s_max", column(&|p| Some(p.size?.s_extent[1])))?;
    out.set_item(
        "sin_theta_min",
        column(&|p| Some(p.size?.sin_theta_extent[0])),
    )?;
    out.set_item(
        "sin_theta_max",
        column(&|p| Some(p.size?.sin_theta_extent[1])),
    )?;
    let classes: Vec<&str> = curve.points.iter().map(|p| p.class.name()).collect();
    out.set_item("classes", classes)?;
    let failures: Vec<Option<String>> = curve.points.iter().map(|p| p.failure.clone()).collect();
    out.set_item("failures", failures)?;
    out.set_item("changes", changes_list(py, &curve.changes)?)?;
    Ok(out)
}

/// Stability changes as a list of dicts `alpha`, `error`, `crossing`,
/// `before`, `after`.
fn changes_list<'py>(py: Python<'py>, changes: &[StabilityChange]) -> PyResult<Bound<'py, PyList>> {
    let list = PyList::empty(py);
    for c in changes {
        let d = PyDict::new(py);
        d.set_item("alpha", c.alpha)?;
        d.set_item("error", c.error)?;
        d.set_item("crossing", c.crossing)?;
        d.set_item("before", c.before.name())?;
        d.set_item("after", c.after.name())?;
        list.append(d)?;
    }
    Ok(list)
}
