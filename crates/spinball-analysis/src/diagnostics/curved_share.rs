//! The share of collisions on curved walls: where the chaos of a billiard
//! comes from, measured over an ensemble and set against the α = 0 theory
//! (each wall's share of the perimeter).
//!
//! Documented in the group docs (`diagnostics/mod.rs`), section "Curved share".

use std::{ops::Range, time::Instant};

use spinball_core::{Billiard, Sampler, SpinLaw};
use spinball_geometry::Boundary;

use super::wall_statistics::{WallStatistics, wall_statistics};
use crate::error::AnalysisError;
use crate::estimators::Accumulator;
use crate::precision::Measurement;
use crate::run::{TableRecord, Threads, map_indices};

/// Share of the boundary length on curved walls,
/// [`Boundary::curved_length`] over [`Boundary::perimeter`]: the share of
/// collisions on curved walls at α = 0 under the invariant measure (the
/// billiard map's measure `cos θ ds dθ` gives each wall its share of the
/// perimeter). Stadium `2π/(4a + 2π)` (0.611 at `a = 1`); Sinai
/// `2πR/(8L + 2πR)` (0.282 at `L = 2, R = 1`); circle 1; rectangle 0.
#[must_use]
pub fn perimeter_curved_share<B: Boundary + ?Sized>(table: &B) -> f64 {
    table.curved_length() / table.perimeter()
}

/// The share of collisions on curved walls over an ensemble.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct CurvedShare {
    /// The table.
    pub table: TableRecord,
    /// Spin parameter.
    pub alpha: f64,
    /// Pooled share: curved collisions over all collisions.
    pub pooled: f64,
    /// Mean over initial conditions of each trajectory's share, with its
    /// SEM (the honest error: collisions of one trajectory are correlated).
    pub per_ic: Measurement,
    /// The α = 0 theory, [`perimeter_curved_share`].
    pub perimeter_share: f64,
    /// Initial conditions.
    pub n_ics: u64,
    /// Collisions per initial condition.
    pub collisions_per_ic: u64,
    /// Wall-clock seconds.
    pub wall_time_s: f64,
    /// All wall statistics, pooled in index order.
    pub stats: WallStatistics,
}

/// [`CurvedShare`] of `table` under `law`: initial conditions `ics` of
/// `seed` drawn with `sampler`, `collisions` each, per-trajectory
/// [`WallStatistics`] merged in index order (the same numbers for any
/// thread count).
///
/// # Errors
/// [`AnalysisError::InvalidOption`] for fewer than two initial conditions or
/// zero collisions; dynamics errors with the failing index.
pub fn curved_share<B: Boundary + Sync>(
    table: &B,
    law: SpinLaw,
    sampler: Sampler,
    seed: u64,
    ics: Range<u64>,
    collisions: u64,
    threads: Threads,
) -> Result<CurvedShare, AnalysisError> {
    if ics.end.saturating_sub(ics.start) < 2 {
        return Err(AnalysisError::invalid(
            "ics",
            format!("need at least 2 initial conditions, got {ics:?}"),
        ));
    }
    if collisions == 0 {
        return Err(AnalysisError::invalid("collisions", "must be > 0"));
    }
    let clock = Instant::now();
    let billiard = Billiard::new(table, law);
    let parts = map_indices(ics, threads, |i| {
        let start = sampler.try_initial_state(billiard.table(), billiard.law(), seed, i)?;
        wall_statistics(&billiard, start, collisions).map_err(|e| e.at_index(i))
    })?;
    let mut pooled = WallStatistics::new(&law);
    let mut per_ic = Accumulator::new();
    for p in &parts {
        pooled.merge(p)?;
        per_ic.push(p.curved_fraction().unwrap_or(0.0));
    }
    Ok(CurvedShare {
        table: TableRecord::of(table),
        alpha: law.alpha(),
        pooled: pooled.curved_fraction().unwrap_or(0.0),
        per_ic: Measurement::new(
            per_ic.mean().unwrap_or(f64::NAN),
            per_ic.sem().unwrap_or(f64::NAN),
        ),
        perimeter_share: perimeter_curved_share(table),
        n_ics: parts.len() as u64,
        collisions_per_ic: collisions,
        wall_time_s: clock.elapsed().as_secs_f64(),
        stats: pooled,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use spinball_geometry::{Sinai, Stadium};
    #[test]
    fn curved_share_of_tables() {
        let stadium = Stadium::new(1.0).unwrap();
        let theory = perimeter_curved_share(&stadium);
        assert!((theory - 0.6110).abs() < 1e-4);
        let sinai = Sinai::new(2.0, 1.0).unwrap();
        assert!((perimeter_curved_share(&sinai) - 0.2820).abs() < 1e-4);
        let share = curved_share(
            &stadium,
            SpinLaw::specular(),
            Sampler::Paper,
            3,
            0..40,
            2_000,
            Threads::Fixed(2),
        )
        .unwrap();
        assert_eq!((share.n_ics, share.collisions_per_ic), (40, 2_000));
        assert_eq!(share.stats.collisions, 80_000);
        assert!((share.pooled - theory).abs() < 0.03, "{}", share.pooled);
        assert!((share.per_ic.value - share.pooled).abs() < 1e-12); // equal lengths
        assert!(share.per_ic.sem > 0.0 && share.per_ic.sem < 0.02);
        let again = curved_share(
            &stadium,
            SpinLaw::specular(),
            Sampler::Paper,
            3,
            0..40,
            2_000,
            Threads::Fixed(1),
        )
        .unwrap();
        assert_eq!(again.stats, share.stats);
        assert!(
            curved_share(
                &stadium,
                SpinLaw::specular(),
                Sampler::Paper,
                3,
                0..1,
                10,
                Threads::All
            )
            .is_err()
        );
    }
}
