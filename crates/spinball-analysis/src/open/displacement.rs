//! Displacements: per initial condition, how far the ball has moved through
//! a periodic table at given times (for the mean-square displacement).

use glam::DVec2;
use spinball_core::Event;
use spinball_geometry::Boundary;

use super::scene::OpenEnsemble;
use crate::error::AnalysisError;
use crate::run::map_indices;

/// One trajectory of a displacement run.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct DisplacementRecord {
    /// Index of the initial condition.
    pub index: u64,
    /// Unwrapped displacement from the start at each checkpoint time, in
    /// the order of the times given.
    pub displacement: Vec<DVec2>,
    /// Collisions up to the last checkpoint.
    pub collisions: u64,
    /// Periodic-wall crossings up to the last checkpoint.
    pub crossings: u64,
}

impl DisplacementRecord {
    /// The records' displacements as the IC-major `[Δx, Δy]` rows
    /// [`Displacements`](crate::transport::Displacements) takes (all
    /// records at the same checkpoints).
    #[must_use]
    pub fn rows(records: &[DisplacementRecord]) -> Vec<[f64; 2]> {
        records
            .iter()
            .flat_map(|r| r.displacement.iter().map(|d| [d.x, d.y]))
            .collect()
    }
}

impl<B: Boundary + Sync> OpenEnsemble<B> {
    /// Run each initial condition to the last of `times` and record its
    /// unwrapped displacement ([`Billiard::unwrapped`](spinball_core::Billiard::unwrapped):
    /// integer cell count plus position in the cell) at each time, the
    /// ball's free flight interpolated between events. On a table without
    /// periodic walls the displacement is the plain one (bounded by the
    /// table).
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] for an empty index range, no
    /// times, times that are not finite, positive and increasing, or a
    /// table with holes (a ball that escapes has no displacement);
    /// [`AnalysisError::Launch`] and [`AnalysisError::Step`] (lowest
    /// failing index).
    pub fn displacements(&self, times: &[f64]) -> Result<Vec<DisplacementRecord>, AnalysisError> {
        if self.indices().is_empty() {
            return Err(AnalysisError::invalid(
                "indices",
                "the index range is empty: give at least one initial condition",
            ));
        }
        let increasing = times.windows(2).all(|w| w[0] < w[1]);
        if times.is_empty() || !increasing || !times.iter().all(|t| t.is_finite() && *t > 0.0) {
            return Err(AnalysisError::invalid(
                "times",
                "checkpoint times must be finite, positive and strictly increasing (at least one)",
            ));
        }
        let billiard = self.billiard();
        if billiard.table().has_holes() {
            return Err(AnalysisError::invalid(
                "table",
                "the table has holes: a ball that escapes has no displacement (close the holes, or run escape_times)",
            ));
        }
        map_indices(self.indices(), self.threads(), |index| {
            let mut ball = self.launch(index)?;
            let origin = billiard.unwrapped(&ball);
            let mut record = DisplacementRecord {
                index,
                displacement: Vec::with_capacity(times.len()),
                collisions: 0,
                crossings: 0,
            };
            let mut now = 0.0;
            let mut next = 0;
            while next < times.len() {
                let before = ball;
                let event = billiard
                    .advance(&mut ball)
                    .map_err(|source| AnalysisError::Step { index, source })?;
                if let Event::Escape(_) = event {
                    return Err(AnalysisError::invalid(
                        "table",
                        format!(
                            "initial condition {index} escaped through a hole that the table's Boundary::has_holes does not report (forward has_holes in the wrapper)"
                        ),
                    ));
                }
                let then = now + event.time();
                // Checkpoints inside this flight: the ball flies straight
                // from where it was.
                while next < times.len() && times[next] <= then {
                    let at = billiard.unwrapped(&before) + before.velocity() * (times[next] - now);
                    record.displacement.push(at - origin);
                    next += 1;
                }
                if next < times.len() {
                    match event {
                        Event::Crossing(_) => record.crossings += 1,
                        _ => record.collisions += 1,
                    }
                }
                now = then;
            }
            Ok(record)
        })
    }
}
