//! The Python front of spinball: the native module `spinball._spinball`,
//! which the pure-Python package `spinball` (`python/spinball/`) re-exports.
//!
//! Physicists who study spinning billiards work in Python (NumPy arrays,
//! matplotlib figures, scripts that drive cluster runs). This crate gives them
//! the Rust engine in Python's idioms and nothing else: every number comes
//! from `spinball-analysis`, `spinball-core` and `spinball-geometry`; this
//! crate only converts arguments (validated by the Rust constructors, whose
//! messages become `ValueError`s), releases the GIL while Rust computes,
//! watches for Ctrl-C between batches, and hands results back as NumPy arrays
//! and objects with the Rust results' fields and JSON.
//!
//! Layers, without circles: [`errors`] (Rust errors and panics to Python
//! exceptions) and [`args`] (argument parsing); [`tables`] (the table
//! classes); [`billiard`] (single trajectories); [`ftle`] and [`results`]
//! (result classes); [`watch`] (progress and Ctrl-C between batches);
//! [`runs`] (the ensemble functions).
//!
//! Built with maturin (`pyproject.toml`); the tests are the pytest suite in
//! `tests/`. Plain `cargo build` also works (the library links against
//! libpython unless `PYO3_BUILD_EXTENSION_MODULE` is set, as maturin does).

use pyo3::prelude::*;

pub mod animation;
pub mod args;
pub mod billiard;
pub mod errors;
pub mod ftle;
pub mod multilevel;
pub mod open_tables;
pub mod orbits;
pub mod phase_space;
pub mod results;
pub mod runs;
pub mod tables;
pub mod watch;

/// The native module. Its members are documented in `spinball/_spinball.pyi`.
#[pymodule]
fn _spinball(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add(
        "CHAOS_THRESHOLD",
        spinball_analysis::estimators::CHAOS_THRESHOLD,
    )?;
    m.add("PAPER_DELTA0", spinball_analysis::estimators::PAPER_DELTA0)?;
    m.add(
        "THRESHOLD_BAND",
        spinball_analysis::estimators::THRESHOLD_BAND.to_vec(),
    )?;
    m.add_class::<tables::PyTable>()?;
    m.add_class::<tables::PyCircle>()?;
    m.add_class::<tables::PyRectangle>()?;
    m.add_class::<tables::PyStadium>()?;
    m.add_class::<tables::PySinai>()?;
    m.add_class::<tables::PySegmentTable>()?;
    m.add_class::<tables::PyLine>()?;
    m.add_class::<tables::PyArc>()?;
    m.add_function(wrap_pyfunction!(tables::table, m)?)?;
    m.add_function(wrap_pyfunction!(tables::table_file, m)?)?;
    m.add_class::<billiard::PyBilliard>()?;
    m.add_class::<billiard::PyTrajectory>()?;
    m.add_class::<ftle::PyFtleDistribution>()?;
    m.add_class::<results::PyLyapunovResult>()?;
    m.add_class::<results::PySpectrumResult>()?;
    m.add_function(wrap_pyfunction!(results::plus_minus, m)?)?;
    m.add_function(wrap_pyfunction!(results::read_results, m)?)?;
    m.add_function(wrap_pyfunction!(results::write_results, m)?)?;
    m.add_class::<multilevel::PyMultilevelResult>()?;
    m.add_function(wrap_pyfunction!(runs::lyapunov, m)?)?;
    m.add_function(wrap_pyfunction!(runs::alpha_sweep, m)?)?;
    m.add_function(wrap_pyfunction!(runs::spectrum, m)?)?;
    m.add_function(wrap_pyfunction!(orbits::periodic_orbits, m)?)?;
    m.add_function(wrap_pyfunction!(orbits::island_sizes, m)?)?;
    m.add_function(wrap_pyfunction!(animation::animate, m)?)?;
    phase_space::register(m)?;
    open_tables::register(m)?;
    Ok(())
}
