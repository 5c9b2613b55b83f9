//! The levels of a multilevel run on a billiard: an [`Ensemble`] read at
//! geometric run lengths, each level with its own stream of initial
//! conditions.
//!
//! Documented in the group docs (`precision/mod.rs`), section "Multilevel
//! ensembles".

use std::ops::Range;

use spinball_core::Billiard;
use spinball_geometry::Boundary;

use super::convergence::start_checkpoints;
use super::multilevel::{LevelDraw, LevelSamples, LevelSource};
use crate::error::AnalysisError;
use crate::estimators::Method;
use crate::run::{Engine, Ensemble, Starts, map_indices};

/// An [`Ensemble`] (table, law, sampler, seed, method, engine, threads) as
/// a [`LevelSource`]: level `l` runs to `T_l` collisions and reads each
/// trajectory at `T_0`, `T_l−1` and `T_l`.
///
/// Level `l`'s initial condition `i` is drawn from
/// `ic_rng(level_seed(seed, l), i)`: the level is part of the seed path, so
/// the levels are independent samples, and a level's draws depend only on
/// the seed, the level and the index (any thread count, any split into
/// shards). Both engines read the three run lengths off one run of `T_l`
/// collisions (the lane engine stops each trajectory at every read and
/// resumes it, bitwise as if it had never stopped), so a draw costs `T_l`.
#[derive(Debug, Clone, PartialEq)]
pub struct EnsembleLevels<B> {
    ensemble: Ensemble<B>,
    levels: Vec<u64>,
}

impl<B: Boundary + Clone + Sync> EnsembleLevels<B> {
    /// The levels `levels` (collisions, increasing) of `ensemble`; its
    /// index range and collisions are not used.
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] for explicit initial states (every
    /// level needs its own draws), run lengths not positive and increasing,
    /// or what [`Ensemble::validate_settings`] refuses.
    pub fn new(ensemble: Ensemble<B>, levels: Vec<u64>) -> Result<Self, AnalysisError> {
        if let Starts::States(_) = ensemble.starts {
            return Err(AnalysisError::invalid(
                "starts",
                "a multilevel run draws independent initial conditions per level: use a sampler, not a list of states",
            ));
        }
        if levels.first() == Some(&0) || levels.windows(2).any(|w| w[1] <= w[0]) {
            return Err(AnalysisError::invalid(
                "levels",
                format!("run lengths must be positive and increasing, got {levels:?}"),
            ));
        }
        ensemble.validate_settings()?;
        Ok(EnsembleLevels { ensemble, levels })
    }

    /// `count` levels `T_0, r·T_0, r²·T_0, …` (`r = ratio ≥ 2`).
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] for `shortest = 0`, `ratio < 2`,
    /// a top level past `u64`; then as [`new`](Self::new).
    pub fn geometric(
        ensemble: Ensemble<B>,
        shortest: u64,
        ratio: u64,
        count: usize,
    ) -> Result<Self, AnalysisError> {
        if shortest == 0 || ratio < 2 {
            return Err(AnalysisError::invalid(
                "levels",
                format!("need shortest >= 1 and ratio >= 2, got {shortest} and {ratio}"),
            ));
        }
        let mut levels = Vec::with_capacity(count);
        let mut next = Some(shortest);
        for _ in 0..count {
            let Some(t) = next else {
                return Err(AnalysisError::invalid(
                    "levels",
                    "the top level's run length overflows",
                ));
            };
            levels.push(t);
            next = t.checked_mul(ratio);
        }
        Self::new(ensemble, levels)
    }

    /// [`default_levels`] up to `top` collisions.
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] if `top` is too short for four
    /// levels of at least [`SHORTEST_LEVEL`] collisions; then as
    /// [`new`](Self::new).
    pub fn up_to(ensemble: Ensemble<B>, top: u64) -> Result<Self, AnalysisError> {
        let levels = default_levels(top).ok_or_else(|| {
            AnalysisError::invalid(
                "levels",
                format!(
                    "a multilevel run needs four levels of at least {SHORTEST_LEVEL} collisions: the top run length must be at least {}, got {top}",
                    8 * SHORTEST_LEVEL
                ),
            )
        })?;
        Self::new(ensemble, levels)
    }

    /// The ensemble the levels run.
    #[must_use]
    pub fn ensemble(&self) -> &Ensemble<B> {
        &self.ensemble
    }

    /// The seed of level `level`'s initial conditions.
    #[must_use]
    pub fn level_seed(&self, level: usize) -> u64 {
        level_seed(self.ensemble.seed, level)
    }

    /// The run lengths level `level` reads: `T_l` on level 0, else
    /// `T_0, T_l−1, T_l` without repeats.
    fn reads(&self, level: usize) -> Vec<u64> {
        let mut reads = vec![self.levels[0]];
        if level >= 2 {
            reads.push(self.levels[level - 1]);
        }
        if level >= 1 {
            reads.push(self.levels[level]);
        }
        reads
    }
}

/// Shortest level [`levels_below`] makes (collisions): shorter runs are
/// mostly the transient, which neither classifies nor saves work.
pub const SHORTEST_LEVEL: u64 = 200;

/// Levels `T/r^k, …, T/r, T` (integer division) down to at least
/// [`SHORTEST_LEVEL`] collisions, at most 12; `None` for `ratio < 2` or if
/// `top` is too short for four levels.
///
/// ```
/// use spinball_analysis::precision::levels_below;
/// assert_eq!(levels_below(1600, 2), Some(vec![200, 400, 800, 1600]));
/// assert_eq!(levels_below(1000, 2), None);
/// assert_eq!(levels_below(25_000, 4), Some(vec![390, 1562, 6250, 25_000]));
/// ```
#[must_use]
pub fn levels_below(top: u64, ratio: u64) -> Option<Vec<u64>> {
    if ratio < 2 {
        return None;
    }
    let mut levels = vec![top];
    while levels[0] / ratio >= SHORTEST_LEVEL && levels.len() < 12 {
        levels.insert(0, levels[0] / ratio);
    }
    (levels.len() >= 4).then_some(levels)
}

/// The levels a multilevel run up to `top` collisions uses by default:
/// ratio 4 where that leaves four levels of at least [`SHORTEST_LEVEL`]
/// (`top ≥ 12 800`), else ratio 2 (`top ≥ 1600`). The corrections'
/// variance falls about like `1/T` while their cost grows like `T`, so
/// fewer, wider levels cost less than many halvings.
///
/// ```
/// use spinball_analysis::precision::default_levels;
/// assert_eq!(default_levels(2_000), Some(vec![250, 500, 1_000, 2_000]));
/// assert_eq!(default_levels(25_000), Some(vec![390, 1_562, 6_250, 25_000]));
/// assert_eq!(default_levels(1_000), None);
/// ```
#[must_use]
pub fn default_levels(top: u64) -> Option<Vec<u64>> {
    levels_below(top, 4).or_else(|| levels_below(top, 2))
}

/// The seed of level `level` of a multilevel run with seed `seed`: a
/// bijective mix of the pair, so no two levels (and no level and a plain
/// run with a nearby seed) share a stream by accident.
#[must_use]
pub fn level_seed(seed: u64, level: usize) -> u64 {
    let mut z = seed ^ (level as u64 + 1).wrapping_mul(0xd6e8_feb8_6659_fd93);
    z = (z ^ (z >> 32)).wrapping_mul(0xd6e8_feb8_6659_fd93);
    z = (z ^ (z >> 32)).wrapping_mul(0xd6e8_feb8_6659_fd93);
    z ^ (z >> 32)
}

impl<B: Boundary + Clone + Sync> LevelSource for EnsembleLevels<B> {
    fn levels(&self) -> &[u64] {
        &self.levels
    }

    fn cost(&self, level: usize) -> f64 {
        self.levels[level] as f64
    }

    fn draw(&self, level: usize, indices: Range<u64>) -> Result<Vec<LevelDraw>, AnalysisError> {
        let reads = self.reads(level);
        let seed = self.level_seed(level);
        // Per initial condition, its exponent at each read, in order.
        let rows: Vec<Vec<f64>> = match self.ensemble.engine_used() {
            Engine::Scalar => {
                let billiard = Billiard::new(&self.ensemble.table, self.ensemble.law);
                let e = &self.ensemble;
                map_indices(indices.clone(), e.threads, |i| {
                    let at = start_checkpoints(&billiard, &e.starts, seed, i, &reads, e.method)?;
                    Ok(at.iter().map(|t| t.exponent).collect())
                })?
            }
            Engine::Lanes => {
                let e = self.ensemble.clone().with_seed(seed);
                let billiard = Billiard::new(&e.table, e.law);
                e.lane_reads(&billiard, indices.clone(), &reads)?
                    .into_iter()
                    .map(|row| row.iter().map(|t| t.exponent).collect())
                    .collect()
            }
        };
        Ok(indices
            .zip(rows)
            .map(|(index, r)| LevelDraw {
                index,
                short: r[0],
                coarse: if level == 0 { 0.0 } else { r[r.len() - 2] },
                fine: r[r.len() - 1],
            })
            .collect())
    }

    /// Finite differences: the paired difference `λ_fd − λ_tangent` on
    /// the draws of `top` at `T_L` (same starts and directions). None for
    /// the tangent method.
    fn method_differences(&self, top: &LevelSamples) -> Result<Vec<f64>, AnalysisError> {
        if matches!(self.ensemble.method, Method::Tangent) || top.draws.is_empty() {
            return Ok(Vec::new());
        }
        let tangent = self
            .ensemble
            .clone()
            .with_method(Method::Tangent)
            .with_seed(self.level_seed(top.level))
            .with_collisions(top.collisions)
            .trajectories(top.first_index..top.end())?;
        Ok(top
            .draws
            .iter()
            .zip(&tangent)
            .map(|(fd, t)| fd.fine - t.exponent)
            .collect())
    }
}
