//! The per-trajectory table: one row per initial condition, the same
//! columns wherever it is written (`spinball ftle --per-ic`, the figures).
//!
//! Documented in the group docs (`report/mod.rs`), section "CSV".

use crate::run::LyapunovEstimate;

/// One initial condition of an estimate: α, its index, its finite-time
/// exponent and what it cost. The column `exponent` is the per-unit-time
/// FTLE, named as in the JSON's `trajectories`.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct TrajectoryRow {
    /// Spin parameter of the estimate.
    pub alpha: f64,
    /// Index of the initial condition.
    pub index: u64,
    /// Finite-time exponent per unit time.
    pub exponent: f64,
    /// Finite-time exponent per collision.
    pub per_collision: f64,
    /// Flight time of the reference trajectory.
    pub time: f64,
    /// Collisions taken.
    pub collisions: u64,
}

/// Every trajectory of `estimates`, estimate by estimate, in index order.
#[must_use]
pub fn trajectory_rows(estimates: &[LyapunovEstimate]) -> Vec<TrajectoryRow> {
    estimates
        .iter()
        .flat_map(|e| {
            e.trajectories().iter().map(|t| TrajectoryRow {
                alpha: e.alpha(),
                index: t.index,
                exponent: t.exponent,
                per_collision: t.per_collision,
                time: t.time,
                collisions: t.collisions,
            })
        })
        .collect()
}
