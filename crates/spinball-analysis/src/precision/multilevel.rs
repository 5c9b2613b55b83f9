//! Multilevel ensembles over trajectory length (Giles' multilevel Monte
//! Carlo): `E[λ_TL] = E[λ_T0] + Σ E[λ_Tl − λ_Tl−1]`, each level with its
//! own number of initial conditions, so that the long runs are spent only
//! on the small correction between a short and a long run.
//!
//! Documented in the group docs (`precision/mod.rs`), section "Multilevel
//! ensembles".

use std::ops::Range;
use std::time::Instant;

use super::finite_time_bias::MIN_CHECKPOINTS;
use super::measurement::Measurement;
use super::multilevel_estimate::MultilevelEstimate;
use crate::error::AnalysisError;
use crate::estimators::{Accumulator, CHAOS_THRESHOLD};

/// One initial condition's contribution to one level: its exponent after
/// the shortest run (which classifies it), after the level's coarser run
/// and after the level's own run, all on the **same** trajectory.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct LevelDraw {
    /// Initial-condition index within the level's own stream.
    pub index: u64,
    /// `λ_T0`, the exponent after the shortest level's run.
    pub short: f64,
    /// `λ_Tl−1`; exactly `0.0` on level 0 (which has no coarser run).
    pub coarse: f64,
    /// `λ_Tl`.
    pub fine: f64,
}

impl LevelDraw {
    /// `λ_Tl − λ_Tl−1` (on level 0, `λ_T0`): what this draw adds to the
    /// telescoping sum.
    #[must_use]
    pub fn correction(&self) -> f64 {
        self.fine - self.coarse
    }
}

/// Where the draws of each level come from: a billiard ensemble
/// ([`EnsembleLevels`](crate::precision::EnsembleLevels)) or any model of
/// one (the estimator is tested on a synthetic bimodal source with a known
/// mean).
pub trait LevelSource {
    /// The run lengths `T_0 < T_1 < … < T_L` of the levels.
    fn levels(&self) -> &[u64];

    /// The work of one draw of `level` in IC-steps. The allocation of
    /// initial conditions depends on it, so it is a count, not a clock
    /// reading: the result must not depend on how busy the machine is.
    fn cost(&self, level: usize) -> f64;

    /// The draws of `level` for initial conditions `indices`, in index
    /// order; the same for any split of the range.
    ///
    /// # Errors
    /// The first failing initial condition's error.
    fn draw(&self, level: usize, indices: Range<u64>) -> Result<Vec<LevelDraw>, AnalysisError>;

    /// Per draw of `top` (a piece of the top level), in order, the paired
    /// difference between this source's exponent and a method without bias
    /// (finite differences against exact tangent dynamics on the same
    /// start); empty (no method bias) unless the source overrides it.
    ///
    /// # Errors
    /// As the run that measures it.
    fn method_differences(&self, top: &LevelSamples) -> Result<Vec<f64>, AnalysisError> {
        let _ = top;
        Ok(Vec::new())
    }

    /// The method bias at the top level: the mean of
    /// [`method_differences`](Self::method_differences) over `top` with its
    /// standard error.
    ///
    /// # Errors
    /// As [`method_differences`](Self::method_differences).
    fn method_bias(&self, top: &LevelSamples) -> Result<Measurement, AnalysisError> {
        Ok(method_bias_of(&self.method_differences(top)?))
    }
}

/// Mean and standard error of paired method differences (zero for none).
pub(crate) fn method_bias_of(differences: &[f64]) -> Measurement {
    let d: Accumulator = differences.iter().copied().collect();
    Measurement::new(d.mean().unwrap_or(0.0), d.sem().unwrap_or(0.0))
}

/// The draws of one level over a contiguous range of its initial
/// conditions: a pilot, a top-up, or a shard of a campaign. Pieces of the
/// same level [merge](Self::merge) into exactly the draws of one run.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct LevelSamples {
    /// The level, `0..=L`.
    pub level: usize,
    /// `T_l`, collisions of the level's own run.
    pub collisions: u64,
    /// IC-steps of one draw.
    pub cost: f64,
    /// First initial-condition index.
    pub first_index: u64,
    /// The draws, in index order.
    pub draws: Vec<LevelDraw>,
    /// Wall-clock seconds spent on them.
    pub wall_time_s: f64,
}

impl LevelSamples {
    /// Draw `indices` of `level` from `source`, timed.
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] for a level past the top; then as
    /// [`LevelSource::draw`].
    pub fn run<S: LevelSource + ?Sized>(
        source: &S,
        level: usize,
        indices: Range<u64>,
    ) -> Result<Self, AnalysisError> {
        let levels = source.levels();
        let Some(&collisions) = levels.get(level) else {
            return Err(AnalysisError::invalid(
                "level",
                format!(
                    "must be in 0..={}, got {level}",
                    levels.len().saturating_sub(1)
                ),
            ));
        };
        let start = Instant::now();
        let first_index = indices.start;
        let draws = source.draw(level, indices)?;
        Ok(LevelSamples {
            level,
            collisions,
            cost: source.cost(level),
            first_index,
            draws,
            wall_time_s: start.elapsed().as_secs_f64(),
        })
    }

    /// One past the last initial-condition index.
    #[must_use]
    pub fn end(&self) -> u64 {
        self.first_index + self.draws.len() as u64
    }

    /// Append `next`, the draws of the same level that follow these.
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] if `next` is another level or does
    /// not start where these end.
    pub fn merge(&mut self, next: LevelSamples) -> Result<(), AnalysisError> {
        if next.level != self.level || next.collisions != self.collisions {
            return Err(AnalysisError::invalid(
                "level samples",
                format!(
                    "cannot merge level {} into level {}",
                    next.level, self.level
                ),
            ));
        }
        if next.first_index != self.end() {
            return Err(AnalysisError::invalid(
                "level samples",
                format!(
                    "the next piece must start at index {}, it starts at {}",
                    self.end(),
                    next.first_index
                ),
            ));
        }
        self.draws.extend(next.draws);
        self.wall_time_s += next.wall_time_s;
        Ok(())
    }

    /// Mean and variance of the level's corrections, and its cost.
    #[must_use]
    pub fn stats(&self) -> LevelStats {
        let acc: Accumulator = self.draws.iter().map(LevelDraw::correction).collect();
        LevelStats {
            level: self.level,
            collisions: self.collisions,
            n_ics: acc.count(),
            mean: acc.mean().unwrap_or(0.0),
            variance: acc.variance().unwrap_or(0.0),
            cost: self.cost,
            wall_time_s: self.wall_time_s,
        }
    }
}

/// What one level measured.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct LevelStats {
    /// The level.
    pub level: usize,
    /// `T_l`.
    pub collisions: u64,
    /// Initial conditions drawn.
    pub n_ics: u64,
    /// Mean correction `E[λ_Tl − λ_Tl−1]` (level 0: `E[λ_T0]`).
    pub mean: f64,
    /// Variance of one correction, `V_l`.
    pub variance: f64,
    /// IC-steps of one draw, `C_l`.
    pub cost: f64,
    /// Wall-clock seconds spent on the level.
    pub wall_time_s: f64,
}

impl LevelStats {
    /// `V_l / N_l`, the level's share of the squared standard error.
    #[must_use]
    pub fn sem2(&self) -> f64 {
        self.variance / self.n_ics.max(1) as f64
    }
}

/// Giles' allocation: the initial conditions per level that reach a
/// statistical error `√eps2` at the least work, `N_l = √(V_l/C_l) ·
/// Σ_k √(V_k C_k) / eps2` (real numbers; round up).
///
/// ```
/// use spinball_analysis::precision::giles_allocation;
/// // A wide cheap level and a narrow expensive one.
/// let n = giles_allocation(&[1.0, 0.01], &[1.0, 100.0], 1e-4);
/// assert!((n[0] - 20_000.0).abs() < 1e-6 && (n[1] - 200.0).abs() < 1e-6);
/// // Σ V_l/N_l meets the target exactly.
/// assert!((1.0 / n[0] + 0.01 / n[1] - 1e-4).abs() < 1e-15);
/// ```
#[must_use]
pub fn giles_allocation(variances: &[f64], costs: &[f64], eps2: f64) -> Vec<f64> {
    let sum: f64 = variances
        .iter()
        .zip(costs)
        .map(|(v, c)| (v.max(0.0) * c).sqrt())
        .sum();
    variances
        .iter()
        .zip(costs)
        .map(|(v, c)| (v.max(0.0) / c).sqrt() * sum / eps2)
        .collect()
}

/// The adaptive multilevel estimator: a pilot on every level, then
/// top-ups to Giles' allocation (from the measured variances and costs)
/// until the total error meets the target.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct Multilevel {
    /// Target relative total error (of `|λ_TL|`).
    pub target_rel: f64,
    /// Initial conditions of each level's pilot, and the fewest any level
    /// keeps. Default 64.
    pub pilot_ics: u64,
    /// Most initial conditions of any level; a target that needs more is
    /// refused. Default 10⁷.
    pub max_ics: u64,
    /// Most rounds of top-ups. Default 8.
    pub max_rounds: u32,
    /// FTLE at `T_0` above which an initial condition counts as chaotic.
    pub threshold: f64,
}

impl Multilevel {
    /// Aim at relative total error `target_rel`, with the defaults above.
    #[must_use]
    pub fn new(target_rel: f64) -> Self {
        Multilevel {
            target_rel,
            pilot_ics: 64,
            max_ics: 10_000_000,
            max_rounds: 8,
            threshold: CHAOS_THRESHOLD,
        }
    }

    /// Pilots of `n` initial conditions per level.
    #[must_use]
    pub fn with_pilot_ics(mut self, n: u64) -> Self {
        self.pilot_ics = n;
        self
    }

    /// At most `n` initial conditions per level.
    #[must_use]
    pub fn with_max_ics(mut self, n: u64) -> Self {
        self.max_ics = n;
        self
    }

    /// At most `n` rounds of top-ups.
    #[must_use]
    pub fn with_max_rounds(mut self, n: u32) -> Self {
        self.max_rounds = n;
        self
    }

    /// Chaotic above `threshold` at `T_0`.
    #[must_use]
    pub fn with_threshold(mut self, threshold: f64) -> Self {
        self.threshold = threshold;
        self
    }

    /// Check the options against `levels`.
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] for a target not finite and
    /// positive, fewer than 4 pilot initial conditions, `max_ics` below
    /// the pilot, a non-finite threshold, fewer than
    /// [`MIN_CHECKPOINTS`] levels or run lengths not positive and
    /// increasing.
    pub fn validate(&self, levels: &[u64]) -> Result<(), AnalysisError> {
        if !(self.target_rel.is_finite() && self.target_rel > 0.0) {
            return Err(AnalysisError::invalid(
                "target",
                format!(
                    "the relative total error must be finite and > 0, got {}",
                    self.target_rel
                ),
            ));
        }
        if self.pilot_ics < 4 || self.max_ics < self.pilot_ics {
            return Err(AnalysisError::invalid(
                "pilot",
                format!(
                    "need at least 4 pilot initial conditions and max_ics >= pilot, got {} and {}",
                    self.pilot_ics, self.max_ics
                ),
            ));
        }
        if !self.threshold.is_finite() {
            return Err(AnalysisError::invalid(
                "threshold",
                format!("must be finite, got {}", self.threshold),
            ));
        }
        check_levels(levels)
    }

    /// Run the estimator on `source`: pilots of every level, then rounds
    /// of top-ups to the allocation for the statistical error left once the
    /// biases are counted, until no level needs more (or `max_rounds`).
    /// Initial condition `i` of level `l` is the source's, so the result is
    /// the same on any number of threads; it depends only on the source,
    /// these options and the seed behind them.
    ///
    /// # Errors
    /// As [`validate`](Self::validate); [`AnalysisError::TargetUnreachable`]
    /// if the bias at the top level alone exceeds the target by more than
    /// two of its standard errors (run longer top levels); then as the
    /// source. A bias that is above the target but not significantly so is
    /// not an error: the result says whether the target was met
    /// ([`MultilevelEstimate::target_met`]).
    pub fn run<S: LevelSource + ?Sized>(
        &self,
        source: &S,
    ) -> Result<MultilevelEstimate, AnalysisError> {
        self.validate(source.levels())?;
        let n_levels = source.levels().len();
        let mut samples = (0..n_levels)
            .map(|l| LevelSamples::run(source, l, 0..self.pilot_ics))
            .collect::<Result<Vec<_>, _>>()?;
        let mut method_bias = source.method_bias(samples.last().expect("levels"))?;
        let mut rounds = 0;
        for round in 1..=self.max_rounds {
            let want = self.allocation(&samples, method_bias)?;
            let mut topped = false;
            for (s, target) in samples.iter_mut().zip(want) {
                if target > s.end() {
                    s.merge(LevelSamples::run(source, s.level, s.end()..target)?)?;
                    topped = true;
                }
            }
            if !topped {
                break;
            }
            rounds = round;
        }
        method_bias = source.method_bias(samples.last().expect("levels"))?;
        let mut estimate = MultilevelEstimate::from_levels(&samples, method_bias, self)?;
        estimate.rounds = rounds;
        Ok(estimate)
    }
}

impl Multilevel {
    /// Initial conditions per level (Giles' allocation, between the pilot
    /// size and `max_ics`) for the statistical error the target leaves once
    /// the biases measured on `samples` are counted.
    ///
    /// # Errors
    /// [`AnalysisError::TargetUnreachable`] if the bias at the top level
    /// exceeds the target by more than two of its standard errors;
    /// [`AnalysisError::InvalidOption`] if a level would need more than
    /// `max_ics`; as [`MultilevelEstimate::from_levels`].
    pub(crate) fn allocation(
        &self,
        samples: &[LevelSamples],
        method_bias: Measurement,
    ) -> Result<Vec<u64>, AnalysisError> {
        let estimate = MultilevelEstimate::from_levels(samples, method_bias, self)?;
        let eps = self.target_rel * estimate.lambda().value.abs();
        let b = estimate.budget;
        // Unreachable only if the bias is above the target beyond two of
        // its standard errors (more draws only shrink its uncertainty).
        let bias_floor = b.finite_time_bias.value.hypot(b.method_bias.value);
        let bias_sem = b.finite_time_bias.sem.hypot(b.method_bias.sem);
        if bias_floor - 2.0 * bias_sem >= eps {
            return Err(AnalysisError::TargetUnreachable {
                target: eps,
                floor: bias_floor,
            });
        }
        let sq = |m: Measurement| m.value * m.value + m.sem * m.sem;
        let eps_s2 = (eps * eps - sq(b.finite_time_bias) - sq(b.method_bias)).max(0.25 * eps * eps);
        let stats: Vec<LevelStats> = samples.iter().map(LevelSamples::stats).collect();
        let variances: Vec<f64> = stats.iter().map(|s| s.variance).collect();
        let costs: Vec<f64> = stats.iter().map(|s| s.cost).collect();
        let want = giles_allocation(&variances, &costs, eps_s2);
        if let Some((l, w)) = want
            .iter()
            .enumerate()
            .find(|(_, w)| **w > self.max_ics as f64)
        {
            return Err(AnalysisError::invalid(
                "target",
                format!(
                    "level {l} would need {w:.3e} initial conditions, more than max_ics = {}: aim at a larger target or raise max_ics",
                    self.max_ics
                ),
            ));
        }
        Ok(want
            .iter()
            .map(|w| (w.ceil() as u64).clamp(self.pilot_ics, self.max_ics))
            .collect())
    }
}

fn check_levels(levels: &[u64]) -> Result<(), AnalysisError> {
    if levels.len() < MIN_CHECKPOINTS {
        return Err(AnalysisError::invalid(
            "levels",
            format!(
                "need at least {MIN_CHECKPOINTS} levels for the bias fit, got {}",
                levels.len()
            ),
        ));
    }
    if levels[0] == 0 || levels.windows(2).any(|w| w[1] <= w[0]) {
        return Err(AnalysisError::invalid(
            "levels",
            format!("run lengths must be positive and increasing, got {levels:?}"),
        ));
    }
    Ok(())
}
