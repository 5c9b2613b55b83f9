//! The ensemble functions: `lyapunov`, `alpha_sweep`, `spectrum`.
//!
//! Each parses its arguments into the Rust description of the run
//! (a plan → [`Ensemble`], [`AlphaSweep`], `spectrum_ensemble`), releases
//! the GIL, and runs it through the analysis crate's driver with a [`Watch`]
//! between batches.

use std::time::Instant;

use pyo3::prelude::*;
use pyo3::types::PyDict;
use spinball_analysis::AnalysisError;
use spinball_analysis::estimators::{Method, PAPER_DELTA0, SpectrumOptions};
use spinball_analysis::run::{
    AlphaSweep, Control, Engine, Ensemble, RunDefaults, SpectrumDefaults, SpectrumEstimate,
    TableRecord, Threads, spectrum_ensemble,
};
use spinball_core::{Billiard, Sampler, SpinLaw, State};
use spinball_geometry::Boundary;

use crate::args::{self, count};
use crate::errors::{analysis, guarded, value_error};
use crate::results::{PyLyapunovResult, PySpectrumResult};
use crate::tables::table_arg;
use crate::watch::Watch;
use crate::with_table;

// The signatures below write the defaults as literals so that `help()`
// shows them; they are the library's (`RunDefaults`, `SpectrumDefaults`),
// checked here when the package is compiled.
const _: () = {
    assert!(RunDefaults::SEED == 0);
    assert!(RunDefaults::ICS == 1000);
    assert!(RunDefaults::COLLISIONS == 10_000);
    assert!(
        matches!(RunDefaults::METHOD, Method::FiniteDifference { delta0 } if delta0 == PAPER_DELTA0)
    );
    assert!(matches!(RunDefaults::SAMPLER, Sampler::Paper));
    assert!(RunDefaults::THRESHOLD == 0.01);
    assert!(matches!(RunDefaults::ENGINE, Engine::Lanes));
    assert!(matches!(RunDefaults::THREADS, Threads::All));
    assert!(SpectrumDefaults::ICS == 50);
    assert!(SpectrumDefaults::COLLISIONS == 50_000);
    assert!(matches!(SpectrumDefaults::METHOD, Method::Tangent));
    assert!(SpectrumDefaults::QR_INTERVAL == 1);
};

/// Everything of an ensemble but its table and spin law.
struct Plan {
    states: Option<Vec<State>>,
    sampler: Sampler,
    seed: u64,
    first: u64,
    ics: u64,
    collisions: u64,
    method: Method,
    threads: Threads,
    threshold: f64,
    engine: Engine,
}

impl Plan {
    #[allow(clippy::too_many_arguments)]
    fn parse(
        ics: Option<i64>,
        collisions: i64,
        method: &str,
        delta0: Option<f64>,
        seed: u64,
        sampler: Option<&str>,
        threads: Option<i64>,
        initial_states: Option<&Bound<'_, PyAny>>,
        first_index: i64,
        threshold: f64,
        engine: &str,
    ) -> PyResult<Self> {
        let states = initial_states.map(args::states).transpose()?;
        if states.is_some() && sampler.is_some() {
            return Err(value_error(
                "give either initial_states or sampler: explicit states are not drawn",
            ));
        }
        let first = count("first_index", first_index, 0)?;
        let ics = match (ics, &states) {
            (Some(n), _) => count("ics", n, 2)?,
            (None, Some(s)) => (s.len() as u64).saturating_sub(first),
            (None, None) => RunDefaults::ICS,
        };
        if first.checked_add(ics).is_none() {
            return Err(value_error("first_index + ics overflows a 64-bit index"));
        }
        if !threshold.is_finite() {
            return Err(value_error(format!(
                "threshold must be finite, got {threshold}"
            )));
        }
        Ok(Plan {
            states,
            sampler: args::sampler(sampler)?,
            seed,
            first,
            ics,
            collisions: count("collisions", collisions, 1)?,
            method: args::method(method, delta0)?,
            threads: args::threads(threads)?,
            threshold,
            engine: args::engine(engine)?,
        })
    }

    fn ensemble<B: Boundary>(&self, table: B, law: SpinLaw) -> Ensemble<B> {
        let e = match &self.states {
            Some(s) => Ensemble::from_states(table, law, s.clone()),
            None => Ensemble::new(table, law).with_sampler(self.sampler),
        };
        e.with_seed(self.seed)
            .with_indices(self.first..self.first + self.ics)
            .with_collisions(self.collisions)
            .with_method(self.method)
            .with_threads(self.threads)
            .with_threshold(self.threshold)
            .with_engine(self.engine)
    }
}

/// Largest Lyapunov exponent of `table` at spin `alpha`, over an ensemble
/// of initial conditions; returns a `LyapunovResult`.
///
/// Exponents are per unit time at energy ½ (the paper's units). Initial
/// condition `i` (indices `first_index .. first_index + ics`) is drawn by
/// `sampler` from its own random stream of `seed`, so the result is
/// bitwise the same for any `threads` and equals the Rust `Ensemble` (and
/// the `sweep` example) with the same arguments.
///
/// Arguments:
/// - `table`: a table object or a spec string (`"stadium:a=1"`);
/// - `alpha`: spin parameter in `[0, 1]` (any finite `>= 0` with
///   `extended=True`);
/// - `ics`: number of initial conditions (default 1000; with
///   `initial_states`, all of them), at least 2;
/// - `collisions`: collisions per trajectory (default 10 000);
/// - `method`: `"fd"` (the paper's finite-difference Benettin method,
///   separation `delta0`, default 1e-7) or `"tangent"` (exact tangent
///   dynamics);
/// - `seed`: seed of the initial conditions and perturbation directions
///   (default 0);
/// - `sampler`: `"paper"` (default) or `"microcanonical"`;
/// - `threads`: `None` (all cores) or the number of threads;
/// - `initial_states`: `None`, or an `(n, 5)` array of `(x, y, vx, vy, u)`
///   to run instead of drawing (not with `sampler`);
/// - `first_index`: first initial-condition index (shards of a big run
///   merge with `LyapunovResult.merge`);
/// - `threshold`: FTLE above which a trajectory counts as chaotic (0.01);
/// - `engine`: `"lanes"` (vector kernels, default) or `"scalar"`;
/// - `target_rel_sem`, `batch`, `time_budget`: stop early, after a batch of
///   `batch` initial conditions, once `sem/|mean| <= target_rel_sem` or
///   `time_budget` seconds have passed (`ics` caps the count); a batch of
///   a multiple of 96 per thread (the default, 96) keeps every register
///   group of the lane kernels full;
/// - `progress`: `True` (a line on stderr), a callable receiving one dict
///   per event (`event`, `point`, `points`, `alpha`, `ics_done`, `ics_max`,
///   `mean`, `sem`, `elapsed_s`), or `None`.
///
/// The GIL is released while Rust computes; Ctrl-C is checked between
/// batches and raises `KeyboardInterrupt`.
///
/// Raises `ValueError` for invalid input (the Rust message: α out of range,
/// fewer than 2 ICs, zero collisions, bad δ0, unknown method/sampler/engine,
/// an initial state outside the table or at rest), `TypeError` for a
/// non-table, `RuntimeError` if a trajectory fails, and whatever the
/// progress callback raises.
#[pyfunction]
#[pyo3(signature = (
    table, alpha, *, ics = None, collisions = 10_000, method = "fd", delta0 = None, seed = 0,
    sampler = None, threads = None, initial_states = None, first_index = 0,
    threshold = 0.01, engine = "lanes", extended = false, target_rel_sem = None,
    batch = 96, time_budget = None, progress = None, estimator = "plain", target_error = None
))]
#[allow(clippy::too_many_arguments)]
pub fn lyapunov(
    py: Python<'_>,
    table: &Bound<'_, PyAny>,
    alpha: f64,
    ics: Option<i64>,
    collisions: i64,
    method: &str,
    delta0: Option<f64>,
    seed: u64,
    sampler: Option<&str>,
    threads: Option<i64>,
    initial_states: Option<&Bound<'_, PyAny>>,
    first_index: i64,
    threshold: f64,
    engine: &str,
    extended: bool,
    target_rel_sem: Option<f64>,
    batch: i64,
    time_budget: Option<f64>,
    progress: Option<&Bound<'_, PyAny>>,
    estimator: &str,
    target_error: Option<f64>,
) -> PyResult<Py<PyAny>> {
    let table = table_arg(table)?;
    let law = args::law(alpha, extended)?;
    let multilevel = match estimator {
        "plain" if target_error.is_none() => None,
        "plain" => {
            return Err(value_error(
                "target_error applies to estimator=\"multilevel\"",
            ));
        }
        "multilevel" => {
            if initial_states.is_some()
                || target_rel_sem.is_some()
                || time_budget.is_some()
                || progress.is_some()
            {
                return Err(value_error(
                    "estimator=\"multilevel\" draws its own initial conditions per level and stops at target_error: it takes no initial_states, target_rel_sem, time_budget or progress",
                ));
            }
            Some(crate::multilevel::estimator(target_error)?)
        }
        other => {
            return Err(value_error(format!(
                "estimator must be \"plain\" or \"multilevel\", got {other:?}"
            )));
        }
    };
    let plan = Plan::parse(
        ics,
        collisions,
        method,
        delta0,
        seed,
        sampler,
        threads,
        initial_states,
        first_index,
        threshold,
        engine,
    )?;
    if let Some(options) = multilevel {
        let result = with_table!(table, |t| crate::multilevel::run(
            py,
            plan.ensemble(t, law),
            options
        ))?;
        return Ok(Py::new(py, result)?.into_any());
    }
    let stop = args::stop_rule(target_rel_sem, batch, time_budget)?;
    let mut watch = Watch::new(progress)?;
    let out = py.detach(|| {
        guarded(
            || {
                with_table!(table.clone(), |t| plan
                    .ensemble(t, law)
                    .run_observed(stop.as_ref(), &mut watch))
            },
            analysis,
        )
    });
    let result = watch.finish(out).map(|inner| PyLyapunovResult { inner })?;
    Ok(Py::new(py, result)?.into_any())
}

/// λ(α): `lyapunov` at each α of `alphas` (same table, initial conditions,
/// seed and options at every point); returns a list of `LyapunovResult`
/// in the order of `alphas`. Arguments as `lyapunov`; `progress` events
/// carry the point index `point` of `points`.
///
/// Raises `ValueError` for an empty `alphas`, an α outside `[0, 1]`
/// without `extended=True`, and every invalid argument `lyapunov` rejects;
/// `RuntimeError` if a trajectory fails; `KeyboardInterrupt` on Ctrl-C
/// (checked between batches; the points already finished are not
/// returned, so run long sweeps point by point to keep them).
#[pyfunction]
#[pyo3(signature = (
    table, alphas, *, ics = None, collisions = 10_000, method = "fd", delta0 = None, seed = 0,
    sampler = None, threads = None, initial_states = None, first_index = 0,
    threshold = 0.01, engine = "lanes", extended = false, target_rel_sem = None,
    batch = 96, time_budget = None, progress = None
))]
#[allow(clippy::too_many_arguments)]
pub fn alpha_sweep(
    py: Python<'_>,
    table: &Bound<'_, PyAny>,
    alphas: Vec<f64>,
    ics: Option<i64>,
    collisions: i64,
    method: &str,
    delta0: Option<f64>,
    seed: u64,
    sampler: Option<&str>,
    threads: Option<i64>,
    initial_states: Option<&Bound<'_, PyAny>>,
    first_index: i64,
    threshold: f64,
    engine: &str,
    extended: bool,
    target_rel_sem: Option<f64>,
    batch: i64,
    time_budget: Option<f64>,
    progress: Option<&Bound<'_, PyAny>>,
) -> PyResult<Vec<PyLyapunovResult>> {
    let table = table_arg(table)?;
    let laws = alphas
        .iter()
        .map(|&a| args::law(a, extended))
        .collect::<PyResult<Vec<_>>>()?;
    if laws.is_empty() {
        return Err(value_error("alphas: the sweep has no points"));
    }
    let plan = Plan::parse(
        ics,
        collisions,
        method,
        delta0,
        seed,
        sampler,
        threads,
        initial_states,
        first_index,
        threshold,
        engine,
    )?;
    let stop = args::stop_rule(target_rel_sem, batch, time_budget)?;
    let mut watch = Watch::new(progress)?;
    let out = py.detach(|| {
        guarded(
            || {
                with_table!(table.clone(), |t| AlphaSweep::from_laws(
                    plan.ensemble(t, laws[0]),
                    laws.clone()
                )
                .with_stop(stop)
                .run_observed(&mut watch))
            },
            analysis,
        )
    });
    let estimates = watch.finish(out)?;
    Ok(estimates
        .into_iter()
        .map(|inner| PyLyapunovResult { inner })
        .collect())
}

/// The Lyapunov spectrum (all five exponents) of `table` at `alpha`,
/// averaged over `ics` initial conditions (default 50, the paper's
/// appendix) of `collisions` collisions each (default 50 000); returns a
/// `SpectrumResult`.
///
/// `method`: `"tangent"` (exact tangent dynamics, default; `qr_interval`
/// collisions between re-orthonormalisations, 1–`MAX_QR_INTERVAL`) or
/// `"fd"` (the paper's five shadow trajectories with separation `delta0`,
/// QR every collision; its fifth exponent is an artefact of the method).
/// `seed`, `sampler`, `threads`, `first_index`, `extended`, `progress` as
/// in `lyapunov`. The GIL is released; Ctrl-C is checked between batches.
///
/// Raises `ValueError` for invalid input, `RuntimeError` if a trajectory
/// fails.
#[pyfunction]
#[pyo3(signature = (
    table, alpha, *, ics = 50, collisions = 50_000, method = "tangent", delta0 = None, seed = 0,
    sampler = None, threads = None, first_index = 0, qr_interval = 1, extended = false,
    progress = None
))]
#[allow(clippy::too_many_arguments)]
pub fn spectrum(
    py: Python<'_>,
    table: &Bound<'_, PyAny>,
    alpha: f64,
    ics: i64,
    collisions: i64,
    method: &str,
    delta0: Option<f64>,
    seed: u64,
    sampler: Option<&str>,
    threads: Option<i64>,
    first_index: i64,
    qr_interval: i64,
    extended: bool,
    progress: Option<&Bound<'_, PyAny>>,
) -> PyResult<PySpectrumResult> {
    let table = table_arg(table)?;
    let law = args::law(alpha, extended)?;
    let ics = count("ics", ics, 2)?;
    let first = count("first_index", first_index, 0)?;
    let end = first
        .checked_add(ics)
        .ok_or_else(|| value_error("first_index + ics overflows a 64-bit index"))?;
    let qr = u32::try_from(count("qr_interval", qr_interval, 1)?)
        .map_err(|_| value_error(format!("qr_interval too large: {qr_interval}")))?;
    let options = SpectrumOptions::new(
        count("collisions", collisions, 1)?,
        args::method(method, delta0)?,
    )
    .with_qr_interval(qr);
    options.validate().map_err(analysis)?;
    let sampler = args::sampler(sampler)?;
    let threads = args::threads(threads)?;
    let mut watch = Watch::new(progress)?;
    // Batches of about a tenth of the run (each a whole number of
    // trajectories, none of one alone): Ctrl-C is checked between them.
    // Every trajectory depends only on its index, so batching does not
    // change a number.
    let batch = ics.div_ceil(10).max(16);
    let out = py.detach(|| {
        guarded(
            || {
                with_table!(table.clone(), |t| {
                    let billiard = Billiard::new(t, law);
                    let clock = Instant::now();
                    let mut spectra = Vec::with_capacity(ics as usize);
                    let mut next = first;
                    while next < end {
                        let mut hi = next.saturating_add(batch).min(end);
                        if end - hi < 2 {
                            hi = end;
                        }
                        let part = spectrum_ensemble(
                            &billiard,
                            sampler,
                            seed,
                            next..hi,
                            &options,
                            threads,
                        )?;
                        spectra.extend(part.spectra);
                        next = hi;
                        let elapsed = clock.elapsed().as_secs_f64();
                        let done = spectra.len() as u64;
                        let alpha = law.alpha();
                        let answer = watch.report(|py| {
                            let d = PyDict::new(py);
                            d.set_item("event", "batch")?;
                            d.set_item("point", 0)?;
                            d.set_item("points", 1)?;
                            d.set_item("alpha", alpha)?;
                            d.set_item("ics_done", done)?;
                            d.set_item("ics_max", ics)?;
                            d.set_item("elapsed_s", elapsed)?;
                            Ok(d)
                        });
                        if answer == Control::Stop {
                            return Err(AnalysisError::Cancelled);
                        }
                    }
                    SpectrumEstimate::from_spectra(
                        spectra,
                        first,
                        options,
                        sampler,
                        seed,
                        clock.elapsed().as_secs_f64(),
                    )
                })
            },
            analysis,
        )
    });
    let inner = watch.finish(out)?;
    Ok(PySpectrumResult {
        inner,
        alpha: law.alpha(),
        table: table.spec(),
        record: with_table!(&table, |t| TableRecord::of(t)),
    })
}
