//! When a batched ensemble run stops: at a target relative standard error,
//! at a target relative **total** error (the SEM and a known bias
//! together), on a wall-time budget, or when its initial conditions run out.
//!
//! Documented in the group docs (`run/mod.rs`), section "Stop rules".

use std::time::Duration;

use super::result::StopReason;
use crate::error::AnalysisError;

/// A batch schedule for [`Ensemble::run_until`](crate::run::Ensemble::run_until).
///
/// After every batch of `batch` initial conditions the run stops if
/// `SEM ≤ target_rel_sem · |mean|` (with at least `min_ics` done), else if
/// the wall time since the start is at least `time_budget`, else if the
/// ensemble's index range is used up. The budget is checked between batches,
/// so a run can overshoot it by up to one batch.
///
/// With a bias ([`StopRule::total_error`]) the target applies to the total
/// error `√(SEM² + bias²) ≤ target · |mean|` instead (the bias from a pilot:
/// finite-time and method bias, see [`ErrorBudget`](crate::precision::ErrorBudget) and
/// [`Planner`](crate::precision::Planner)); such a run stops with
/// [`StopReason::TotalErrorReached`].
/// A bias of `target · |mean|` or more can never be reached: the run then
/// ends on its budget or its range.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct StopRule {
    /// Initial conditions per batch (≥ 2). With the lane engine a multiple
    /// of [`CHUNK`](spinball_lanes::CHUNK) (96) per thread runs fastest: a
    /// batch is cut into chunks from its start, and the lanes of a partial
    /// register group idle at full cost. The batch size changes no number,
    /// only where a stop rule may stop.
    pub batch: u64,
    /// Target relative standard error `SEM/|mean|` (e.g. `0.01` for 1%);
    /// with a `bias`, the target relative total error.
    pub target_rel_sem: f64,
    /// Wall-time budget (`None`: no budget).
    pub time_budget: Option<Duration>,
    /// Do not stop on the target before this many initial conditions (the
    /// SEM of a small sample is itself uncertain). Defaults to `batch`.
    pub min_ics: u64,
    /// A known bias magnitude (absolute, ≥ 0) that the SEM is added to in
    /// quadrature before comparing with the target (`None`: SEM only).
    pub bias: Option<f64>,
}

impl StopRule {
    /// Batches of `batch` ICs until `SEM/|mean| ≤ target_rel_sem`.
    #[must_use]
    pub fn new(batch: u64, target_rel_sem: f64) -> Self {
        StopRule {
            batch,
            target_rel_sem,
            time_budget: None,
            min_ics: batch,
            bias: None,
        }
    }

    /// Batches of `batch` ICs until the total error `√(SEM² + bias²)` is at
    /// most `target_rel_total · |mean|`; `bias` is the magnitude of the
    /// bias of the run's method and length, from a pilot.
    ///
    /// ```
    /// use spinball_analysis::estimators::Method;
    /// use spinball_analysis::run::{Ensemble, StopReason, StopRule};
    /// use spinball_core::SpinLaw;
    /// use spinball_geometry::Stadium;
    ///
    /// let ensemble = Ensemble::new(Stadium::new(1.0)?, SpinLaw::new(0.0)?)
    ///     .with_ics(2_000)
    ///     .with_collisions(1_000)
    ///     .with_method(Method::Tangent);
    /// let rule = StopRule::total_error(16, 0.02, 0.004);
    /// let estimate = ensemble.run_until(&rule)?;
    /// assert_eq!(estimate.stop(), StopReason::TotalErrorReached);
    /// assert!(estimate.sem().hypot(0.004) <= 0.02 * estimate.mean());
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    #[must_use]
    pub fn total_error(batch: u64, target_rel_total: f64, bias: f64) -> Self {
        StopRule {
            bias: Some(bias),
            ..Self::new(batch, target_rel_total)
        }
    }

    /// Also stop once `budget` of wall time is spent.
    #[must_use]
    pub fn with_time_budget(mut self, budget: Duration) -> Self {
        self.time_budget = Some(budget);
        self
    }

    /// Do not stop on the target before `min_ics` initial conditions.
    #[must_use]
    pub fn with_min_ics(mut self, min_ics: u64) -> Self {
        self.min_ics = min_ics;
        self
    }

    /// Check the rule.
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] for `batch < 2`, a target that is
    /// not finite and ≥ 0, or a bias that is not finite and ≥ 0.
    pub fn validate(&self) -> Result<(), AnalysisError> {
        if self.batch < 2 {
            return Err(AnalysisError::invalid(
                "batch",
                format!("must be at least 2, got {}", self.batch),
            ));
        }
        if !(self.target_rel_sem.is_finite() && self.target_rel_sem >= 0.0) {
            return Err(AnalysisError::invalid(
                "target_rel_sem",
                format!("must be finite and >= 0, got {}", self.target_rel_sem),
            ));
        }
        if let Some(b) = self.bias
            && !(b.is_finite() && b >= 0.0)
        {
            return Err(AnalysisError::invalid(
                "bias",
                format!("must be finite and >= 0, got {b}"),
            ));
        }
        Ok(())
    }

    /// The total error this rule compares with its target: the SEM, or
    /// `√(SEM² + bias²)` with a bias.
    #[must_use]
    pub fn error(&self, sem: f64) -> f64 {
        self.bias.map_or(sem, |b| sem.hypot(b))
    }

    /// Why a run that met this rule's target stopped.
    #[must_use]
    pub fn reached(&self) -> StopReason {
        if self.bias.is_some() {
            StopReason::TotalErrorReached
        } else {
            StopReason::TargetReached
        }
    }

    /// Whether a run with `count` initial conditions done, mean `mean` and
    /// standard error `sem` has reached the target (on the SEM, or on the
    /// total error with a bias).
    #[must_use]
    pub fn target_met(&self, count: u64, mean: f64, sem: f64) -> bool {
        count >= self.min_ics.max(2) && self.error(sem) <= self.target_rel_sem * mean.abs()
    }
}
