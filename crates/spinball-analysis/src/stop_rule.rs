//! When a batched ensemble run stops: at a target relative standard error,
//! on a wall-time budget, or when its initial conditions run out.

use std::time::Duration;

use crate::error::AnalysisError;

/// A batch schedule for [`Ensemble::run_until`](crate::Ensemble::run_until).
///
/// After every batch of `batch` initial conditions the run stops if
/// `SEM ≤ target_rel_sem · |mean|` (with at least `min_ics` done), else if
/// the wall time since the start is at least `time_budget`, else if the
/// ensemble's index range is used up. The budget is checked between batches,
/// so a run can overshoot it by up to one batch.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct StopRule {
    /// Initial conditions per batch (≥ 2).
    pub batch: u64,
    /// Target relative standard error `SEM/|mean|` (e.g. `0.01` for 1%).
    pub target_rel_sem: f64,
    /// Wall-time budget (`None`: no budget).
    pub time_budget: Option<Duration>,
    /// Do not stop on the target before this many initial conditions (the
    /// SEM of a small sample is itself uncertain). Defaults to `batch`.
    pub min_ics: u64,
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
    /// [`AnalysisError::InvalidOption`] for `batch < 2` or a target that is
    /// not finite and ≥ 0.
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
        Ok(())
    }

    /// Whether a run with `count` initial conditions done, mean `mean` and
    /// standard error `sem` has reached the target.
    #[must_use]
    pub fn target_met(&self, count: u64, mean: f64, sem: f64) -> bool {
        count >= self.min_ics.max(2) && sem <= self.target_rel_sem * mean.abs()
    }
}
