//! Work–precision sets: for one scene, what each method and engine buys
//! for each budget of `N` initial conditions × `T` collisions, measured as
//! wall time against the error from a [`Reference`] value.
//!
//! Documented in the group docs (`precision/mod.rs`), section "Work–precision".

use std::ops::Range;

use spinball_geometry::Boundary;

use super::error_budget::Reference;
use super::measurement::Measurement;
use crate::error::AnalysisError;
use crate::estimators::Method;
use crate::run::{Engine, Ensemble};

/// A budget: `ics` initial conditions × `collisions` collisions each.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Budget {
    /// Initial conditions.
    pub ics: u64,
    /// Collisions per initial condition.
    pub collisions: u64,
}

impl Budget {
    /// `ics × collisions`.
    #[must_use]
    pub fn new(ics: u64, collisions: u64) -> Self {
        Budget { ics, collisions }
    }

    /// The work, in collisions of one trajectory (IC-steps).
    #[must_use]
    pub fn ic_steps(&self) -> u64 {
        self.ics.saturating_mul(self.collisions)
    }
}

/// One point of a work–precision set.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct WorkPoint {
    /// How the exponent was measured.
    pub method: Method,
    /// Which implementation ran it.
    pub engine: Engine,
    /// What was run.
    pub budget: Budget,
    /// Measured wall-clock seconds.
    pub wall_time_s: f64,
    /// Nanoseconds per IC-step (wall time over `N·T`).
    pub ns_per_step: f64,
    /// The estimate `λ ± SEM`.
    pub estimate: Measurement,
    /// `λ − λ_ref` with its standard error.
    pub error: Measurement,
    /// `√(Δ² + SEM²) / |λ_ref|`: the relative error the chart plots.
    pub rel_error: f64,
}

/// The work–precision set of `ensemble`'s scene (table, law, sampler,
/// seed, threads): one point per method, engine and budget, in that nesting
/// order, each against `reference`. Every budget runs initial conditions
/// `0..ics` of the ensemble's seed (so budgets of the same `T` share their
/// first initial conditions); give the reference another seed.
///
/// # Errors
/// [`AnalysisError::InvalidOption`] for an empty list of methods, engines
/// or budgets, a budget of fewer than two initial conditions or zero
/// collisions, a reference of zero value; then the first run's error.
pub fn work_precision<B: Boundary + Clone + Sync>(
    ensemble: &Ensemble<B>,
    reference: &Reference,
    methods: &[Method],
    engines: &[Engine],
    budgets: &[Budget],
) -> Result<Vec<WorkPoint>, AnalysisError> {
    for (name, empty) in [
        ("methods", methods.is_empty()),
        ("engines", engines.is_empty()),
        ("budgets", budgets.is_empty()),
    ] {
        if empty {
            return Err(AnalysisError::invalid(name, "need at least one"));
        }
    }
    if let Some(b) = budgets.iter().find(|b| b.ics < 2 || b.collisions == 0) {
        return Err(AnalysisError::invalid(
            "budgets",
            format!(
                "need at least 2 initial conditions and 1 collision, got {} x {}",
                b.ics, b.collisions
            ),
        ));
    }
    let scale = reference.value.value.abs();
    if !(scale > 0.0 && scale.is_finite()) {
        return Err(AnalysisError::invalid(
            "reference",
            format!(
                "a relative error needs a finite non-zero reference, got {}",
                reference.value.value
            ),
        ));
    }
    let mut points = Vec::new();
    for &method in methods {
        for &engine in engines {
            for &budget in budgets {
                let run = ensemble
                    .clone()
                    .with_method(method)
                    .with_engine(engine)
                    .with_indices(Range {
                        start: 0,
                        end: budget.ics,
                    })
                    .with_collisions(budget.collisions)
                    .run()?;
                let estimate = Measurement::lambda(&run);
                let error = reference.error_of(estimate);
                points.push(WorkPoint {
                    method,
                    engine: run.engine,
                    budget,
                    wall_time_s: run.wall_time_s,
                    ns_per_step: 1e9 * run.wall_time_s / budget.ic_steps() as f64,
                    estimate,
                    error,
                    rel_error: error.value.hypot(estimate.sem) / scale,
                });
            }
        }
    }
    Ok(points)
}
