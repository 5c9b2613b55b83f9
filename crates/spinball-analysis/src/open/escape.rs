//! Escape times: per initial condition, when and how the ball left through
//! a hole, or that it was still inside when the budget ran out.

use spinball_core::{Event, Exit};
use spinball_geometry::Boundary;

use super::budget::Budget;
use super::scene::OpenEnsemble;
use crate::error::AnalysisError;
use crate::run::map_indices;

/// One trajectory of an escape run.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct EscapeRecord {
    /// Index of the initial condition.
    pub index: u64,
    /// Escape time, or for a censored ball the time it was last seen
    /// inside (the time budget, or the time of its last collision when
    /// the collision budget ran out).
    pub time: f64,
    /// Collisions before the escape (or before the run stopped).
    pub collisions: u64,
    /// Whether the ball was still inside when the budget ran out: its true
    /// escape time is longer than `time`.
    pub censored: bool,
    /// Where and how it left (`None` for a censored ball). `exit.time` is
    /// the last flight only; the escape time is `time`.
    pub exit: Option<Exit>,
}

impl<B: Boundary + Sync> OpenEnsemble<B> {
    /// Run each initial condition until it escapes or the `budget` runs
    /// out. One record per index, in index order: a ball still inside at
    /// the budget is censored, never dropped; on a table without holes
    /// every record is censored.
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] for an empty index range or a
    /// budget [`Budget::validate`] refuses; [`AnalysisError::Launch`] and
    /// [`AnalysisError::Step`] (with the lowest failing index) for a start
    /// that cannot launch or a step that fails.
    pub fn escape_times(&self, budget: Budget) -> Result<Vec<EscapeRecord>, AnalysisError> {
        budget.validate()?;
        if self.indices().is_empty() {
            return Err(AnalysisError::invalid(
                "indices",
                "the index range is empty: give at least one initial condition",
            ));
        }
        let billiard = self.billiard();
        map_indices(self.indices(), self.threads(), |index| {
            let mut ball = self.launch(index)?;
            let mut record = EscapeRecord {
                index,
                time: 0.0,
                collisions: 0,
                censored: true,
                exit: None,
            };
            while record.collisions < budget.collisions {
                let event = billiard
                    .advance(&mut ball)
                    .map_err(|source| AnalysisError::Step { index, source })?;
                let t = record.time + event.time();
                if t > budget.time {
                    // Still inside at the time budget.
                    record.time = budget.time;
                    break;
                }
                record.time = t;
                match event {
                    Event::Collision(_) => record.collisions += 1,
                    Event::Crossing(_) => {}
                    Event::Escape(exit) => {
                        record.censored = false;
                        record.exit = Some(exit);
                        break;
                    }
                }
            }
            Ok(record)
        })
    }
}
