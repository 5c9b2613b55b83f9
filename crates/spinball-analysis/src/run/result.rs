//! What an ensemble run returns: the estimate, how sure it is, what it cost
//! and everything needed to reproduce it.
//!
//! Documented in the group docs (`run/mod.rs`), section "Results".

use std::{fmt, ops::Range};

use spinball_core::Sampler;

use super::engine::Engine;
use super::provenance::{Provenance, TableRecord};
use super::trajectory::TrajectoryStats;
use crate::error::AnalysisError;
use crate::estimators::{Accumulator, FtleDistribution, Method, PlusMinus};

/// Why an ensemble run stopped.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum StopReason {
    /// A plain run ([`Ensemble::run`](crate::run::Ensemble::run)) over its whole index range.
    Completed,
    /// The stop rule's target `SEM/|mean|` was reached (deterministic for a
    /// given batch schedule).
    TargetReached,
    /// The stop rule's target total error `√(SEM² + bias²)/|mean|` was
    /// reached ([`StopRule::total_error`](crate::run::StopRule::total_error)).
    TotalErrorReached,
    /// The stop rule's wall-time budget was spent before the target was
    /// reached (how many ICs that allows depends on the machine).
    TimeBudget,
    /// The stop rule ran out of initial conditions (the ensemble's index
    /// range) before reaching its target.
    RangeExhausted,
    /// An observer asked the run to stop; the estimate covers the batches
    /// finished before that.
    Cancelled,
}

impl StopReason {
    /// `completed`, `target_reached`, `total_error_reached`, `time_budget`,
    /// `range_exhausted` or `cancelled`.
    pub fn name(&self) -> &'static str {
        match self {
            StopReason::Completed => "completed",
            StopReason::TargetReached => "target_reached",
            StopReason::TotalErrorReached => "total_error_reached",
            StopReason::TimeBudget => "time_budget",
            StopReason::RangeExhausted => "range_exhausted",
            StopReason::Cancelled => "cancelled",
        }
    }
}

impl fmt::Display for StopReason {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// The ensemble estimate of the largest Lyapunov exponent, with its errors,
/// cost and parameters. Built by [`Ensemble::run`](crate::run::Ensemble::run)
/// and [`Ensemble::run_until`](crate::run::Ensemble::run_until).
///
/// All exponents are **per unit time** (paper §II.C); `per_collision_mean`
/// and `collision_rate` give the per-collision view (paper appendix on the
/// collision rate).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct LyapunovEstimate {
    /// The estimate: mean of the per-trajectory FTLEs.
    pub(crate) mean: f64,
    /// Standard error of the mean, `std / √n_ics`.
    pub(crate) sem: f64,
    /// Median FTLE (robust against the regular islands near zero).
    pub(crate) median: f64,
    /// Sample standard deviation of the FTLEs (`n − 1`).
    pub(crate) std: f64,
    /// Smallest FTLE.
    pub(crate) min: f64,
    /// Largest FTLE.
    pub(crate) max: f64,
    /// Chaos threshold used below (the paper: 0.01).
    pub(crate) threshold: f64,
    /// Mean FTLE of the chaotic trajectories (FTLE > `threshold`); `None`
    /// if there are none (an integrable table).
    pub(crate) conditional_mean: Option<f64>,
    /// Share of trajectories with FTLE > `threshold`.
    pub(crate) chaotic_fraction: f64,
    /// Binomial standard error of `chaotic_fraction`.
    pub(crate) chaotic_fraction_sem: f64,
    /// Mean over trajectories of the per-collision exponent `Σ ln / collisions`.
    pub(crate) per_collision_mean: f64,
    /// Collision rate `ν = Σ collisions / Σ time` over the ensemble.
    pub(crate) collision_rate: f64,
    /// Total flight time of all reference trajectories.
    pub(crate) total_time: f64,
    /// Number of initial conditions.
    pub(crate) n_ics: u64,
    /// Index of the first initial condition (they run `first_index..first_index + n_ics`).
    pub(crate) first_index: u64,
    /// Collisions per initial condition.
    pub(crate) collisions_per_ic: u64,
    /// Wall-clock seconds spent computing (summed over merged parts).
    pub(crate) wall_time_s: f64,
    /// Seed of the initial conditions ([`spinball_core::ic_rng`]).
    pub(crate) seed: u64,
    /// The table (its shape, if it has one, and a name).
    pub(crate) table: TableRecord,
    /// Spin parameter α.
    pub(crate) alpha: f64,
    /// How the exponent was measured (with δ0 for finite differences).
    pub(crate) method: Method,
    /// How initial conditions were drawn (`None`: explicit states).
    pub(crate) sampler: Option<Sampler>,
    /// Version of `spinball-analysis` that computed it.
    pub(crate) version: String,
    /// The implementation that ran the trajectories.
    pub(crate) engine: Engine,
    /// Why the run stopped.
    pub(crate) stop: StopReason,
    /// Per-trajectory results, in index order.
    pub(crate) trajectories: Vec<TrajectoryStats>,
}

impl LyapunovEstimate {
    /// The estimate for `trajectories` (contiguous indices, in order)
    /// computed with the parameters `run` (an ensemble's
    /// [`provenance`](crate::run::Ensemble::provenance)). This is how an
    /// ensemble run builds its result; use it for per-trajectory results
    /// computed elsewhere (another kernel, another machine).
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] for fewer than two trajectories,
    /// indices that are not consecutive, or a non-finite exponent.
    pub fn from_trajectories(
        run: &Provenance,
        trajectories: Vec<TrajectoryStats>,
        wall_time_s: f64,
        stop: StopReason,
    ) -> Result<Self, AnalysisError> {
        let mut estimate = LyapunovEstimate {
            mean: 0.0,
            sem: 0.0,
            median: 0.0,
            std: 0.0,
            min: 0.0,
            max: 0.0,
            threshold: run.threshold,
            conditional_mean: None,
            chaotic_fraction: 0.0,
            chaotic_fraction_sem: 0.0,
            per_collision_mean: 0.0,
            collision_rate: 0.0,
            total_time: 0.0,
            n_ics: 0,
            first_index: 0,
            collisions_per_ic: run.collisions_per_ic,
            wall_time_s,
            seed: run.seed,
            table: run.table.clone(),
            alpha: run.alpha,
            method: run.method,
            sampler: run.sampler,
            version: env!("CARGO_PKG_VERSION").to_string(),
            engine: run.engine,
            stop,
            trajectories,
        };
        estimate.recompute()?;
        Ok(estimate)
    }

    /// Recompute every statistic from `trajectories`, sequentially in index
    /// order (this is what makes results independent of threads and splits).
    fn recompute(&mut self) -> Result<(), AnalysisError> {
        let t = &self.trajectories;
        if t.len() < 2 {
            return Err(AnalysisError::invalid(
                "initial conditions",
                format!(
                    "an estimate needs at least 2 trajectories for a standard error, got {}",
                    t.len()
                ),
            ));
        }
        if let Some(w) = t.windows(2).find(|w| w[1].index != w[0].index + 1) {
            return Err(AnalysisError::invalid(
                "trajectories",
                format!(
                    "indices must be consecutive, found {} after {}",
                    w[1].index, w[0].index
                ),
            ));
        }
        let ftle = FtleDistribution::new(t.iter().map(|s| s.exponent).collect())?;
        let acc = ftle.accumulator();
        let per_collision: Accumulator = t.iter().map(|s| s.per_collision).collect();
        let total_time = t.iter().fold(0.0, |sum, s| sum + s.time);
        let total_collisions: u64 = t.iter().map(|s| s.collisions).sum();
        let fraction = ftle.chaotic_fraction_at(self.threshold);

        // n >= 2, so every Option below is Some.
        self.mean = acc.mean().unwrap_or(f64::NAN);
        self.sem = acc.sem().unwrap_or(f64::NAN);
        self.std = acc.std().unwrap_or(f64::NAN);
        self.min = acc.min().unwrap_or(f64::NAN);
        self.max = acc.max().unwrap_or(f64::NAN);
        self.median = ftle.median();
        self.conditional_mean = ftle.conditional_mean(self.threshold);
        self.chaotic_fraction = fraction.fraction;
        self.chaotic_fraction_sem = fraction.sem;
        self.per_collision_mean = per_collision.mean().unwrap_or(f64::NAN);
        self.total_time = total_time;
        self.collision_rate = total_collisions as f64 / total_time;
        self.n_ics = t.len() as u64;
        self.first_index = t[0].index;
        // Finite values can still overflow a statistic (an exponent near
        // 1e308): refuse it rather than write it as JSON `null`.
        let stats = [
            ("mean", self.mean),
            ("sem", self.sem),
            ("std", self.std),
            ("per-collision mean", self.per_collision_mean),
            ("total time", self.total_time),
        ];
        if let Some((what, x)) = stats.into_iter().find(|(_, x)| !x.is_finite()) {
            return Err(AnalysisError::invalid(
                "trajectories",
                format!(
                    "the {what} of the per-trajectory values is {x}: they are not those of a run (no trajectory gives an exponent near 1e308)"
                ),
            ));
        }
        Ok(())
    }

    /// Combine the results of two adjacent index ranges (`[a, k)` and
    /// `[k, b)`, in either order) into the result over `[a, b)`. The
    /// statistics are recomputed from the per-trajectory values in index
    /// order, so they are **bitwise identical** to one run over `[a, b)`;
    /// `wall_time_s` is the sum of the parts; the stop reason is the parts'
    /// if they agree, else that of the later part.
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] if the ranges are not adjacent or any
    /// parameter (table, α, method, δ0, sampler, seed, collisions, threshold,
    /// version) differs.
    pub fn merge(&self, other: &LyapunovEstimate) -> Result<LyapunovEstimate, AnalysisError> {
        let mismatch = |what: &str, a: &dyn fmt::Debug, b: &dyn fmt::Debug| {
            Err(AnalysisError::invalid(
                "merge",
                format!("cannot merge estimates with different {what}: {a:?} vs {b:?}"),
            ))
        };
        // The table by its geometry, bit for bit (never a type name).
        self.table
            .same_table(&other.table)
            .map_err(|e| AnalysisError::invalid("merge", format!("cannot merge estimates: {e}")))?;
        if self.alpha.to_bits() != other.alpha.to_bits() {
            return mismatch("alpha", &self.alpha, &other.alpha);
        }
        if self.method != other.method {
            return mismatch("methods", &self.method, &other.method);
        }
        if self.sampler != other.sampler {
            return mismatch("samplers", &self.sampler, &other.sampler);
        }
        if self.seed != other.seed {
            return mismatch("seeds", &self.seed, &other.seed);
        }
        if self.collisions_per_ic != other.collisions_per_ic {
            return mismatch(
                "collisions per IC",
                &self.collisions_per_ic,
                &other.collisions_per_ic,
            );
        }
        if self.threshold.to_bits() != other.threshold.to_bits() {
            return mismatch("thresholds", &self.threshold, &other.threshold);
        }
        if self.engine != other.engine {
            return mismatch("engines", &self.engine, &other.engine);
        }
        if self.version != other.version {
            return mismatch("crate versions", &self.version, &other.version);
        }
        let (first, second) = if in_order(&self.indices(), &other.indices())? {
            (self, other)
        } else {
            (other, self)
        };
        let mut merged = first.clone();
        merged.trajectories.extend_from_slice(&second.trajectories);
        merged.wall_time_s = first.wall_time_s + second.wall_time_s;
        merged.stop = second.stop;
        merged.recompute()?;
        Ok(merged)
    }

    /// The estimate: mean of the per-trajectory FTLEs.
    #[must_use]
    pub fn mean(&self) -> f64 {
        self.mean
    }

    /// Standard error of the mean, `std / √n_ics`.
    #[must_use]
    pub fn sem(&self) -> f64 {
        self.sem
    }

    /// Median FTLE (robust against the regular islands near zero).
    #[must_use]
    pub fn median(&self) -> f64 {
        self.median
    }

    /// Sample standard deviation of the FTLEs (`n − 1`).
    #[must_use]
    pub fn std(&self) -> f64 {
        self.std
    }

    /// Smallest FTLE.
    #[must_use]
    pub fn min(&self) -> f64 {
        self.min
    }

    /// Largest FTLE.
    #[must_use]
    pub fn max(&self) -> f64 {
        self.max
    }

    /// Chaos threshold used below (the paper: 0.01).
    #[must_use]
    pub fn threshold(&self) -> f64 {
        self.threshold
    }

    /// Mean FTLE of the chaotic trajectories (FTLE > `threshold`); `None`
    /// if there are none (an integrable table).
    #[must_use]
    pub fn conditional_mean(&self) -> Option<f64> {
        self.conditional_mean
    }

    /// Share of trajectories with FTLE > `threshold`.
    #[must_use]
    pub fn chaotic_fraction(&self) -> f64 {
        self.chaotic_fraction
    }

    /// Binomial standard error of `chaotic_fraction`.
    #[must_use]
    pub fn chaotic_fraction_sem(&self) -> f64 {
        self.chaotic_fraction_sem
    }

    /// Mean over trajectories of the per-collision exponent `Σ ln / collisions`.
    #[must_use]
    pub fn per_collision_mean(&self) -> f64 {
        self.per_collision_mean
    }

    /// Collision rate `ν = Σ collisions / Σ time` over the ensemble.
    #[must_use]
    pub fn collision_rate(&self) -> f64 {
        self.collision_rate
    }

    /// Total flight time of all reference trajectories.
    #[must_use]
    pub fn total_time(&self) -> f64 {
        self.total_time
    }

    /// Number of initial conditions.
    #[must_use]
    pub fn n_ics(&self) -> u64 {
        self.n_ics
    }

    /// Index of the first initial condition (they run `first_index..first_index + n_ics`).
    #[must_use]
    pub fn first_index(&self) -> u64 {
        self.first_index
    }

    /// Collisions per initial condition.
    #[must_use]
    pub fn collisions_per_ic(&self) -> u64 {
        self.collisions_per_ic
    }

    /// Wall-clock seconds spent computing (summed over merged parts).
    #[must_use]
    pub fn wall_time_s(&self) -> f64 {
        self.wall_time_s
    }

    /// Seed of the initial conditions ([`spinball_core::ic_rng`]).
    #[must_use]
    pub fn seed(&self) -> u64 {
        self.seed
    }

    /// The table (its shape, if it has one, and a name).
    #[must_use]
    pub fn table(&self) -> &TableRecord {
        &self.table
    }

    /// Spin parameter α.
    #[must_use]
    pub fn alpha(&self) -> f64 {
        self.alpha
    }

    /// How the exponent was measured (with δ0 for finite differences).
    #[must_use]
    pub fn method(&self) -> Method {
        self.method
    }

    /// How initial conditions were drawn (`None`: explicit states).
    #[must_use]
    pub fn sampler(&self) -> Option<Sampler> {
        self.sampler
    }

    /// Version of `spinball-analysis` that computed it.
    #[must_use]
    pub fn version(&self) -> &str {
        &self.version
    }

    /// The implementation that ran the trajectories.
    #[must_use]
    pub fn engine(&self) -> Engine {
        self.engine
    }

    /// Why the run stopped.
    #[must_use]
    pub fn stop(&self) -> StopReason {
        self.stop
    }

    /// Per-trajectory results, in index order.
    #[must_use]
    pub fn trajectories(&self) -> &[TrajectoryStats] {
        &self.trajectories
    }

    /// The initial separation of the finite-difference method (`None` for
    /// the tangent method).
    #[must_use]
    pub fn delta0(&self) -> Option<f64> {
        match self.method {
            Method::FiniteDifference { delta0 } => Some(delta0),
            Method::Tangent => None,
        }
    }

    /// The initial-condition indices covered, `first_index..first_index + n_ics`.
    pub fn indices(&self) -> Range<u64> {
        self.first_index..self.first_index + self.n_ics
    }

    /// Relative standard error `SEM / |mean|` (infinite if the mean is 0).
    pub fn rel_sem(&self) -> f64 {
        self.sem / self.mean.abs()
    }

    /// Mean exponent per collision from the ensemble rates, `λ / ν` (the
    /// paper's `λ_coll`; close to, but not the same number as,
    /// `per_collision_mean`).
    pub fn per_collision_from_rate(&self) -> f64 {
        self.mean / self.collision_rate
    }

    /// The Datseris–Hupe–Fleischmann product `λ · f_ch` at `threshold`.
    pub fn dhf_product(&self) -> f64 {
        self.mean * self.chaotic_fraction
    }

    /// The FTLE distribution (per-trajectory exponents in index order), for
    /// histograms, quantiles and threshold bands.
    ///
    /// # Errors
    /// Only if `trajectories` was emptied or given a non-finite exponent
    /// after the estimate was built.
    pub fn ftle(&self) -> Result<FtleDistribution, AnalysisError> {
        FtleDistribution::new(self.trajectories.iter().map(|s| s.exponent).collect())
    }

    /// Total collisions over all trajectories.
    pub fn total_collisions(&self) -> u64 {
        self.trajectories.iter().map(|s| s.collisions).sum()
    }
}

impl fmt::Display for LyapunovEstimate {
    /// `λ = 0.1865 ± 0.0038 (median 0.1902, f_ch 0.890) [stadium:a=1, α = 0.5, fd, paper, 200 ICs × 20000 collisions, 3.10 s]`:
    /// λ with its SEM to two significant digits ([`PlusMinus`]), the median
    /// to λ's decimals.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let lambda = PlusMinus::new(self.mean, self.sem);
        let d = lambda.decimals().unwrap_or(4);
        write!(
            f,
            "λ = {lambda} (median {:.d$}, f_ch {:.3}) [{}, α = {}, {}, {}, {} ICs × {} collisions, {:.2} s]",
            self.median,
            self.chaotic_fraction,
            self.table,
            self.alpha,
            self.method.name(),
            self.sampler.map_or("states", |s| s.name()),
            self.n_ics,
            self.collisions_per_ic,
            self.wall_time_s
        )
    }
}

/// Whether index range `a` ends where `b` starts (`true`) or `b` ends where
/// `a` starts (`false`): the two orders in which results can be merged.
///
/// # Errors
/// [`AnalysisError::InvalidOption`] if the ranges are not adjacent.
pub(crate) fn in_order(a: &Range<u64>, b: &Range<u64>) -> Result<bool, AnalysisError> {
    if a.end == b.start {
        Ok(true)
    } else if b.end == a.start {
        Ok(false)
    } else {
        Err(AnalysisError::invalid(
            "merge",
            format!("index ranges {a:?} and {b:?} are not adjacent"),
        ))
    }
}
