//! Phase space from Python: Birkhoff sections, FTLE maps (fixed spin or
//! fixed `Q`), the bouncing-ball prediction, Kac return times and the
//! invariant-measure sampler, each a function returning NumPy arrays (in a
//! dict where there are several), computed by `spinball_analysis::phase_space`.

use numpy::ndarray::Array2;
use numpy::{IntoPyArray, PyArray1, PyArray2};
use pyo3::exceptions::PyRuntimeError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use spinball_analysis::AnalysisError;
use spinball_analysis::phase_space::{
    FacingFlats, FtleMapOptions, SECTION_COLUMNS, SectionBox, Slice, ftle_map as map_of,
    invariant_starts, kac_comparison, pair_rotation as rotation, sampled_sections, section_rows,
    sections,
};
use spinball_analysis::run::{FtleMapDefaults, KacDefaults, RunDefaults, SectionDefaults};
use spinball_core::Billiard;

use crate::args::{self, count};
use crate::errors::{analysis, guarded, value_error};
use crate::tables::{AnyTable, table_arg};
use crate::with_table;

// The signatures below write the defaults as literals so that `help()`
// shows them; they are the library's, checked here when the package is
// compiled.
const _: () = {
    assert!(RunDefaults::SEED == 0);
    assert!(RunDefaults::THRESHOLD == 0.01);
    assert!(SectionDefaults::ORBITS == 8);
    assert!(SectionDefaults::COLLISIONS == 1000);
    assert!(KacDefaults::ORBITS == 16);
    assert!(KacDefaults::COLLISIONS == 10_000);
    assert!(FtleMapDefaults::COLUMNS == 64);
    assert!(FtleMapDefaults::ROWS == 64);
    assert!(FtleMapDefaults::COLLISIONS == 2000);
};

/// A float64 NumPy array of `values`.
fn floats<'py>(py: Python<'py>, values: Vec<f64>) -> Bound<'py, PyArray1<f64>> {
    values.into_pyarray(py)
}

/// `(n, columns)` rows as a float64 NumPy array.
fn matrix<'py, const N: usize>(
    py: Python<'py>,
    rows: &[[f64; N]],
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let flat: Vec<f64> = rows.iter().flatten().copied().collect();
    Array2::from_shape_vec((rows.len(), N), flat)
        .map(|a| a.into_pyarray(py))
        .map_err(|e| PyRuntimeError::new_err(e.to_string()))
}

/// The Birkhoff section of `orbits` orbits of `table` at spin `alpha`:
/// every collision as a point, just before it; returns a dict of NumPy
/// arrays, one entry per point, orbit by orbit in collision order:
/// `orbit` and `wall` (int64), `s` (arc length), `sin_theta` (`v∥/|v|`),
/// `v_par`, `speed` (`|v|`), `u` (spin), `q` (`Q = v∥ − αu`).
///
/// Arguments: `orbits` (default 8) starts `0 .. orbits` of `seed`'s
/// streams, drawn by `sampler`: `"paper"` (default), `"microcanonical"`,
/// or `"invariant"` (the invariant measure of the collision map, as
/// `invariant_states`); `collisions` per orbit (default 1000);
/// `spin_slice`: keep only the points with `|√α u| < spin_slice` (> 0);
/// `threads` (`None`: all cores; results do not depend on it);
/// `extended` allows α > 1. The CLI's `spinball section` writes the same
/// columns.
///
/// Raises `ValueError` for invalid input (α, counts, sampler, slice, a
/// table that cannot place points by arc length for `"invariant"`) and
/// `RuntimeError` if an orbit fails.
#[pyfunction]
#[pyo3(signature = (
    table, alpha, *, orbits = 8, collisions = 1000, seed = 0, sampler = None,
    spin_slice = None, threads = None, extended = false
))]
#[allow(clippy::too_many_arguments)]
pub fn section<'py>(
    py: Python<'py>,
    table: &Bound<'_, PyAny>,
    alpha: f64,
    orbits: i64,
    collisions: i64,
    seed: u64,
    sampler: Option<&str>,
    spin_slice: Option<f64>,
    threads: Option<i64>,
    extended: bool,
) -> PyResult<Bound<'py, PyDict>> {
    let table = table_arg(table)?;
    let law = args::law(alpha, extended)?;
    let orbits = count("orbits", orbits, 1)?;
    let collisions = count("collisions", collisions, 1)?;
    let threads = args::threads(threads)?;
    if let Some(w) = spin_slice
        && !(w.is_finite() && w > 0.0)
    {
        return Err(value_error(format!(
            "spin_slice must be a finite number > 0 (|√α u| ≤ 1 on the shell), got {w}"
        )));
    }
    let draw = match sampler {
        Some(s) if s.trim().eq_ignore_ascii_case("invariant") => None,
        other => Some(args::sampler(other)?),
    };
    let rows = py.detach(|| {
        guarded(
            || {
                with_table!(table.clone(), |t| {
                    let billiard = Billiard::new(t, law);
                    let found = match draw {
                        Some(s) => {
                            sampled_sections(&billiard, s, seed, 0..orbits, collisions, threads)
                        }
                        None => invariant_starts(billiard.table(), &law, seed, 0..orbits)
                            .and_then(|st| sections(&billiard, &st, collisions, threads)),
                    }?;
                    let alpha = law.alpha();
                    Ok::<_, AnalysisError>(section_rows(&found, 0, |p| {
                        spin_slice.is_none_or(|w| p.w(alpha).abs() < w)
                    }))
                })
            },
            analysis,
        )
    })?;
    let out = PyDict::new(py);
    for (k, name) in SECTION_COLUMNS.iter().enumerate() {
        let column: Vec<f64> = rows.iter().map(|r| r[k]).collect();
        if *name == "orbit" || *name == "wall" {
            let ints: Vec<i64> = column.iter().map(|&x| x as i64).collect();
            out.set_item(*name, ints.into_pyarray(py))?;
        } else {
            out.set_item(*name, floats(py, column))?;
        }
    }
    Ok(out)
}

/// The facing flats of a table, if it has them (the stadium's).
fn flats_of(table: &AnyTable) -> Option<FacingFlats> {
    match table {
        AnyTable::Builtin(t) => FacingFlats::of_table(t),
        AnyTable::Segments(_) => None,
    }
}

/// The FTLE map of `table` at spin `alpha`: the finite-time Lyapunov
/// exponent (per unit time, exact tangent method) of every start on a
/// `rows × columns` grid of the section; returns a dict.
///
/// The grid covers the arc length `s` (columns, cell centres) and a row
/// coordinate in `(−1, 1)`; the third coordinate is fixed: `spin=u` (the
/// default, `u = 0`; rows are `sin θ`) or `q=Q` (fixed `Q = v∥ − αu`,
/// needs α > 0; rows are `v∥/|V|`, and cells off the energy shell are
/// NaN). Starts are on the shell E = ½, each run for `collisions`
/// (default 2000) with tangent directions from `seed`.
///
/// Keys: `exponents` (`rows × columns` float64, row 0 at the bottom, NaN
/// off the shell), `s` (the columns' arc lengths), `row` (the rows'
/// coordinate), `row_label`, `slice` (`"spin"` or `"q"`), `slice_value`,
/// `alpha`, `perimeter`, `collisions`, `seed`, `threshold`, `regular` and
/// `on_shell` (cell counts; regular is FTLE ≤ `threshold`),
/// `regular_fraction`, `chaotic_fraction` and `chaotic_fraction_sem`, and
/// the bouncing-ball prediction: `predicted` (`rows × columns` bool, the
/// starts the rotation `4·arctan √α` traps between two facing flats;
/// `None` for a table without them), `predicted_cells`,
/// `predicted_regular`. The CLI's `spinball ftle-map` computes the same map
/// (and in shards).
///
/// Raises `ValueError` for invalid input (grid, collisions, both `spin`
/// and `q`, `αu² ≥ 1`, `q` at α = 0, fewer than two cells on the shell, a
/// table that cannot place points by arc length), `RuntimeError` if a
/// start fails.
#[pyfunction]
#[pyo3(signature = (
    table, alpha, *, columns = 64, rows = 64, spin = None, q = None, collisions = 2000,
    seed = 0, threshold = 0.01, threads = None, extended = false
))]
#[allow(clippy::too_many_arguments)]
pub fn ftle_map<'py>(
    py: Python<'py>,
    table: &Bound<'_, PyAny>,
    alpha: f64,
    columns: i64,
    rows: i64,
    spin: Option<f64>,
    q: Option<f64>,
    collisions: i64,
    seed: u64,
    threshold: f64,
    threads: Option<i64>,
    extended: bool,
) -> PyResult<Bound<'py, PyDict>> {
    let table = table_arg(table)?;
    let law = args::law(alpha, extended)?;
    let slice = match (spin, q) {
        (Some(_), Some(_)) => {
            return Err(value_error(
                "give spin or q, not both: a map is a slice at one of them",
            ));
        }
        (_, Some(q)) => Slice::Q(q),
        (spin, None) => Slice::Spin(spin.unwrap_or(0.0)),
    };
    let options = FtleMapOptions::new(
        count("columns", columns, 1)? as usize,
        count("rows", rows, 1)? as usize,
        slice,
    )
    .with_collisions(count("collisions", collisions, 1)?)
    .with_seed(seed)
    .with_threshold(threshold)
    .with_threads(args::threads(threads)?);
    let map = py.detach(|| {
        guarded(
            || with_table!(table.clone(), |t| map_of(t, law, &options)),
            analysis,
        )
    })?;
    let predicted = flats_of(&table).map(|f| f.trapped_cells(&law, &map));
    let (predicted_cells, predicted_regular) =
        predicted.as_ref().map_or((0, 0), |m| map.regular_among(m));
    let (nc, nr) = (options.columns, options.rows);
    let (regular, on_shell) = map.counts();
    let fraction = map.chaotic_fraction();
    let out = PyDict::new(py);
    let grid = Array2::from_shape_vec((nr, nc), map.to_array())
        .map_err(|e| PyRuntimeError::new_err(e.to_string()))?;
    out.set_item("exponents", grid.into_pyarray(py))?;
    out.set_item("s", floats(py, (0..nc).map(|i| map.s(i)).collect()))?;
    out.set_item("row", floats(py, (0..nr).map(|j| map.row(j)).collect()))?;
    out.set_item("row_label", slice.row_label())?;
    let (name, value) = match slice {
        Slice::Spin(u) => ("spin", u),
        Slice::Q(q) => ("q", q),
    };
    out.set_item("slice", name)?;
    out.set_item("slice_value", value)?;
    out.set_item("alpha", map.alpha)?;
    out.set_item("perimeter", map.perimeter)?;
    out.set_item("collisions", options.collisions)?;
    out.set_item("seed", seed)?;
    out.set_item("threshold", threshold)?;
    out.set_item("regular", regular)?;
    out.set_item("on_shell", on_shell)?;
    out.set_item("regular_fraction", map.regular_fraction())?;
    out.set_item("chaotic_fraction", fraction.fraction)?;
    out.set_item("chaotic_fraction_sem", fraction.sem)?;
    match predicted {
        Some(mask) => {
            let mask = Array2::from_shape_vec((nr, nc), mask)
                .map_err(|e| PyRuntimeError::new_err(e.to_string()))?;
            out.set_item("predicted", mask.into_pyarray(py))?;
        }
        None => out.set_item("predicted", py.None())?,
    }
    out.set_item("predicted_cells", predicted_cells)?;
    out.set_item("predicted_regular", predicted_regular)?;
    out.set_item("table", table.spec())?;
    Ok(out)
}

/// `(lo, hi)` with finite `lo < hi`, for the region's ranges.
fn range(value: (f64, f64), what: &str) -> PyResult<std::ops::Range<f64>> {
    let (lo, hi) = value;
    if lo.is_finite() && hi.is_finite() && lo < hi {
        Ok(lo..hi)
    } else {
        Err(value_error(format!(
            "{what}: expected (lo, hi) with finite lo < hi, got ({lo}, {hi})"
        )))
    }
}

/// Mean return times to a region of the section against Kac's lemma:
/// `orbits` orbits started from the invariant measure (streams
/// `0 .. orbits` of `seed`, as `invariant_states`), `collisions` each; on
/// an ergodic table every orbit's mean return time is near `1/μ(A)`.
///
/// The region is `s` (arc lengths `(lo, hi)`, required), `v_par`
/// (`v∥/|V|`, default `(-1, 1)`) and `w` (`√α u/|V|`, default every spin;
/// at α = 0 it must contain 0). Returns a dict: `probability` (μ(A)),
/// `expected` (Kac's `1/μ(A)`, collisions), `mean_return` and
/// `mean_return_sem` (over the returning orbits; `None` if fewer than two
/// returned), `ratio` and `ratio_sem` (the mean over Kac's, 1 on an
/// ergodic table), `never_returned`, and per orbit in index order `index`
/// and `visits` (int64) and `orbit_mean_return`, `orbit_ratio` (float64,
/// NaN for an orbit with fewer than two visits); `alpha`, `table`. The
/// CLI's `spinball kac` computes the same.
///
/// Raises `ValueError` for invalid input (fewer than 2 orbits, zero
/// collisions, a region of zero measure or with a bad range, a table that
/// cannot place points by arc length), `RuntimeError` if an orbit fails.
#[pyfunction]
#[pyo3(signature = (
    table, alpha, *, s, v_par = (-1.0, 1.0), w = None, orbits = 16, collisions = 10_000,
    seed = 0, threads = None, extended = false
))]
#[allow(clippy::too_many_arguments)]
pub fn kac<'py>(
    py: Python<'py>,
    table: &Bound<'_, PyAny>,
    alpha: f64,
    s: (f64, f64),
    v_par: (f64, f64),
    w: Option<(f64, f64)>,
    orbits: i64,
    collisions: i64,
    seed: u64,
    threads: Option<i64>,
    extended: bool,
) -> PyResult<Bound<'py, PyDict>> {
    let table = table_arg(table)?;
    let law = args::law(alpha, extended)?;
    let mut region = SectionBox::new(range(s, "s")?, range(v_par, "v_par")?);
    if let Some(w) = w {
        region = region.with_w(range(w, "w")?);
    }
    let orbits = count("orbits", orbits, 2)?;
    let collisions = count("collisions", collisions, 1)?;
    let threads = args::threads(threads)?;
    let kac = py.detach(|| {
        guarded(
            || {
                with_table!(table.clone(), |t| kac_comparison(
                    &Billiard::new(t, law),
                    &region,
                    orbits,
                    collisions,
                    seed,
                    threads
                ))
            },
            analysis,
        )
    })?;
    let out = PyDict::new(py);
    out.set_item("probability", kac.probability)?;
    out.set_item("expected", kac.expected)?;
    out.set_item("mean_return", kac.mean_return.map(|m| m.value))?;
    out.set_item("mean_return_sem", kac.mean_return.map(|m| m.sem))?;
    out.set_item("ratio", kac.ratio().map(|m| m.value))?;
    out.set_item("ratio_sem", kac.ratio().map(|m| m.sem))?;
    out.set_item("never_returned", kac.never_returned)?;
    let per = |f: &dyn Fn(&spinball_analysis::phase_space::OrbitReturns) -> f64| {
        kac.orbits.iter().map(f).collect::<Vec<f64>>()
    };
    let ints = |f: &dyn Fn(&spinball_analysis::phase_space::OrbitReturns) -> u64| {
        kac.orbits.iter().map(|o| f(o) as i64).collect::<Vec<i64>>()
    };
    out.set_item("index", ints(&|o| o.index).into_pyarray(py))?;
    out.set_item("visits", ints(&|o| o.visits).into_pyarray(py))?;
    let mean = |o: &spinball_analysis::phase_space::OrbitReturns| o.mean_return.unwrap_or(f64::NAN);
    out.set_item("orbit_mean_return", floats(py, per(&mean)))?;
    out.set_item("orbit_ratio", floats(py, per(&|o| mean(o) / kac.expected)))?;
    out.set_item("alpha", kac.alpha)?;
    out.set_item("table", table.spec())?;
    Ok(out)
}

/// Starts `first_index .. first_index + n` drawn from the invariant measure
/// of the collision map of `table` at spin `alpha` (uniform in arc length
/// and in the disk of `(v∥, √α u)`, on the shell E = ½), start `i` from
/// stream `i` of `seed`: each is a ball just leaving the wall, as an
/// `(n, 5)` array of `(x, y, vx, vy, u)`. These are the starts of `kac`
/// and of `section(..., sampler="invariant")`; pass them to `lyapunov`'s
/// `initial_states` to run an ensemble over the invariant measure.
///
/// Raises `ValueError` for a negative count or a table that cannot place
/// points by arc length.
#[pyfunction]
#[pyo3(signature = (table, alpha, n, *, seed = 0, first_index = 0, extended = false))]
pub fn invariant_states<'py>(
    py: Python<'py>,
    table: &Bound<'_, PyAny>,
    alpha: f64,
    n: i64,
    seed: u64,
    first_index: i64,
    extended: bool,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let table = table_arg(table)?;
    let law = args::law(alpha, extended)?;
    let n = count("n", n, 0)?;
    let first = count("first_index", first_index, 0)?;
    let end = first
        .checked_add(n)
        .ok_or_else(|| value_error("first_index + n overflows a 64-bit index"))?;
    let states = py.detach(|| {
        guarded(
            || with_table!(&table, |t| invariant_starts(t, &law, seed, first..end)),
            analysis,
        )
    })?;
    let rows: Vec<[f64; 5]> = states.iter().map(|s| s.to_array()).collect();
    matrix(py, &rows)
}

/// The bouncing-ball prediction on a stadium: for each state of `states`
/// (an `(n, 5)` array of `(x, y, vx, vy, u)`, or one row), whether the
/// rotation `4·arctan √α` of `(vx, √α u)` per pair of flat-wall collisions
/// keeps the ball between the two flat walls for ever (its band of contact
/// points fits on the flats; exact when the rotation is an irrational
/// fraction of a turn). Returns a bool array of length n.
///
/// Raises `ValueError` for a table without two facing flats (anything but
/// a stadium) or a malformed array.
#[pyfunction]
#[pyo3(signature = (table, alpha, states, *, extended = false))]
pub fn bouncing_ball<'py>(
    py: Python<'py>,
    table: &Bound<'_, PyAny>,
    alpha: f64,
    states: &Bound<'_, PyAny>,
    extended: bool,
) -> PyResult<Bound<'py, PyArray1<bool>>> {
    let table = table_arg(table)?;
    let law = args::law(alpha, extended)?;
    let flats = flats_of(&table).ok_or_else(|| {
        value_error(format!(
            "the bouncing-ball prediction needs two facing flat walls with unit caps (a stadium), not {}",
            table.spec()
        ))
    })?;
    let rows = args::rows(states, 5, "states")?;
    let trapped: Vec<bool> = rows
        .iter()
        .map(|r| {
            let s = spinball_core::State::from_array([r[0], r[1], r[2], r[3], r[4]]);
            flats.trapped(&law, &s)
        })
        .collect();
    Ok(trapped.into_pyarray(py))
}

/// The rotation of `(v_x, √α u)` by a bottom–top pair of collisions on two
/// facing flat walls, `4·arctan √α` radians (0 at α = 0, π at α = 1).
///
/// Raises `ValueError` unless `alpha` is finite and ≥ 0.
#[pyfunction]
pub fn pair_rotation(alpha: f64) -> PyResult<f64> {
    if alpha.is_finite() && alpha >= 0.0 {
        Ok(rotation(alpha))
    } else {
        Err(value_error(format!(
            "alpha must be finite and >= 0, got {alpha}"
        )))
    }
}

/// Add this module's functions to the native module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(section, m)?)?;
    m.add_function(wrap_pyfunction!(ftle_map, m)?)?;
    m.add_function(wrap_pyfunction!(kac, m)?)?;
    m.add_function(wrap_pyfunction!(invariant_states, m)?)?;
    m.add_function(wrap_pyfunction!(bouncing_ball, m)?)?;
    m.add_function(wrap_pyfunction!(pair_rotation, m)?)?;
    Ok(())
}
