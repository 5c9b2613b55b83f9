//! A multilevel allocation fixed before the run, so that a campaign can
//! cut every level into shards and merge them back exactly.
//!
//! The adaptive [`Multilevel::run`] decides its top-ups from what it has
//! measured so far, which a job array cannot do: its tasks run at the same
//! time and never see each other. So a campaign decides once, when it is
//! written: a pilot of every level, then Giles' allocation for the target
//! ([`Multilevel::allocate`]). Each task then runs its block of every
//! level's initial-condition indices ([`LevelAllocation::run_shard`]), and
//! [`LevelShard::merge`] joins the blocks level by level, in index order,
//! into the same draws — and so bitwise the same estimate — as one process
//! running the allocation whole ([`LevelAllocation::run`]).
//!
//! Documented in the group docs (`precision/mod.rs`), section "Multilevel
//! ensembles".

use super::multilevel::{LevelSamples, LevelSource, Multilevel, method_bias_of};
use super::multilevel_estimate::MultilevelEstimate;
use crate::error::AnalysisError;
use crate::run::Shard;

/// The levels of a multilevel run and how many initial conditions each
/// gets, fixed in advance (from a pilot: [`Multilevel::allocate`]).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct LevelAllocation {
    /// Run lengths `T_0 < … < T_L`.
    pub levels: Vec<u64>,
    /// Initial conditions of each level, `N_l`.
    pub ics: Vec<u64>,
    /// The options the estimate is read with (target, threshold).
    pub options: Multilevel,
}

impl Multilevel {
    /// A pilot of [`pilot_ics`](Multilevel::pilot_ics) on every level of
    /// `source`, then the initial conditions per level that reach the
    /// target by Giles' allocation from the pilot's variances, costs and
    /// biases (one round of [`run`](Self::run)'s top-ups, decided at once).
    ///
    /// # Errors
    /// As [`run`](Self::run).
    pub fn allocate<S: LevelSource + ?Sized>(
        &self,
        source: &S,
    ) -> Result<LevelAllocation, AnalysisError> {
        self.validate(source.levels())?;
        let samples = (0..source.levels().len())
            .map(|l| LevelSamples::run(source, l, 0..self.pilot_ics))
            .collect::<Result<Vec<_>, _>>()?;
        let method_bias = source.method_bias(samples.last().expect("levels"))?;
        Ok(LevelAllocation {
            levels: source.levels().to_vec(),
            ics: self.allocation(&samples, method_bias)?,
            options: *self,
        })
    }
}

impl LevelAllocation {
    /// Check the allocation against `source` (same levels, at least two
    /// initial conditions per level).
    fn check<S: LevelSource + ?Sized>(&self, source: &S) -> Result<(), AnalysisError> {
        if source.levels() != self.levels.as_slice() {
            return Err(AnalysisError::invalid(
                "allocation",
                format!(
                    "planned for levels {:?}, the source has {:?}",
                    self.levels,
                    source.levels()
                ),
            ));
        }
        if self.ics.len() != self.levels.len() || self.ics.iter().any(|&n| n < 2) {
            return Err(AnalysisError::invalid(
                "allocation",
                format!(
                    "need at least 2 initial conditions on each of the {} levels, got {:?}",
                    self.levels.len(),
                    self.ics
                ),
            ));
        }
        Ok(())
    }

    /// Shard `shard`'s block of every level: level `l`'s indices `0..N_l`
    /// cut as [`Shard::range`] cuts them (a level with fewer initial
    /// conditions than shards leaves some blocks empty).
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] for a source with other levels;
    /// then as [`LevelSource::draw`] and
    /// [`LevelSource::method_differences`].
    pub fn run_shard<S: LevelSource + ?Sized>(
        &self,
        source: &S,
        shard: Shard,
    ) -> Result<LevelShard, AnalysisError> {
        self.check(source)?;
        let samples = self
            .ics
            .iter()
            .enumerate()
            .map(|(l, &n)| LevelSamples::run(source, l, shard.range(0..n)))
            .collect::<Result<Vec<_>, _>>()?;
        let method_differences = source.method_differences(samples.last().expect("levels"))?;
        Ok(LevelShard {
            allocation: self.clone(),
            shard,
            samples,
            method_differences,
        })
    }

    /// The whole allocation in one process: the estimate every complete set
    /// of shards merges into.
    ///
    /// # Errors
    /// As [`run_shard`](Self::run_shard) and [`LevelShard::merge`].
    pub fn run<S: LevelSource + ?Sized>(
        &self,
        source: &S,
    ) -> Result<MultilevelEstimate, AnalysisError> {
        LevelShard::merge(&[self.run_shard(source, Shard::WHOLE)?])
    }
}

/// One shard's draws of every level of a [`LevelAllocation`], with the
/// paired method differences of its block of the top level.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct LevelShard {
    /// The allocation the shard belongs to.
    pub allocation: LevelAllocation,
    /// Which shard.
    pub shard: Shard,
    /// Its block of each level, in level order.
    pub samples: Vec<LevelSamples>,
    /// [`LevelSource::method_differences`] of its block of the top level.
    pub method_differences: Vec<f64>,
}

impl LevelShard {
    /// The estimate of all shards of one allocation (any order): each
    /// level's blocks joined in index order, the method differences
    /// likewise, read as one run of the allocation reads them, so the
    /// numbers are bitwise those of [`LevelAllocation::run`] (only the
    /// levels' wall times, summed over the shards, differ).
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] for no shards, shards of different
    /// allocations or shard counts, a shard missing or given twice; then as
    /// [`MultilevelEstimate::from_levels`].
    pub fn merge(shards: &[LevelShard]) -> Result<MultilevelEstimate, AnalysisError> {
        let Some(first) = shards.first() else {
            return Err(AnalysisError::invalid("shards", "nothing to merge"));
        };
        let count = first.shard.count;
        if let Some(other) = shards
            .iter()
            .find(|s| s.allocation != first.allocation || s.shard.count != count)
        {
            return Err(AnalysisError::invalid(
                "shards",
                format!(
                    "shard {} and shard {} are of different multilevel allocations or shard counts",
                    first.shard, other.shard
                ),
            ));
        }
        let mut ordered: Vec<&LevelShard> = shards.iter().collect();
        ordered.sort_by_key(|s| s.shard.index);
        for (k, s) in ordered.iter().enumerate() {
            if s.shard.index != k as u64 {
                return Err(AnalysisError::invalid(
                    "shards",
                    format!(
                        "expected shards 0..{count} once each; shard {k}/{count} is missing or shard {} given twice",
                        s.shard
                    ),
                ));
            }
        }
        if ordered.len() as u64 != count {
            return Err(AnalysisError::invalid(
                "shards",
                format!("got {} of {count} shards", ordered.len()),
            ));
        }
        let mut samples = ordered[0].samples.clone();
        let mut differences = ordered[0].method_differences.clone();
        for s in &ordered[1..] {
            for (joined, piece) in samples.iter_mut().zip(&s.samples) {
                joined.merge(piece.clone())?;
            }
            differences.extend_from_slice(&s.method_differences);
        }
        if let Some((l, s)) = samples
            .iter()
            .enumerate()
            .find(|(l, s)| s.first_index != 0 || s.end() != first.allocation.ics[*l])
        {
            return Err(AnalysisError::invalid(
                "shards",
                format!(
                    "level {l} covers indices {}..{}, the allocation {}..{}",
                    s.first_index,
                    s.end(),
                    0,
                    first.allocation.ics[l]
                ),
            ));
        }
        MultilevelEstimate::from_levels(
            &samples,
            method_bias_of(&differences),
            &first.allocation.options,
        )
    }
}
