//! Ensembles of trajectories: many initial conditions, one estimate with its
//! error, bitwise reproducible on any number of threads.
//!
//! A single trajectory's exponent is a finite-time estimate that differs from
//! trajectory to trajectory (and, with spin, is bimodal); the paper's numbers
//! are averages over 10⁴–10⁵ initial conditions. An [`Ensemble`] describes
//! such a run — table, spin law, sampler, seed, index range, collisions per
//! trajectory, method, threads — and [`Ensemble::run`] returns a
//! [`LyapunovEstimate`].
//!
//! # Reproducibility
//! Initial condition `i` is drawn from its own stream
//! [`ic_rng(seed, i)`](spinball_core::ic_rng), and the same stream then draws
//! the initial perturbation direction, so trajectory `i` does not depend on
//! which thread runs it or on which other indices are in the run. Results come
//! back in index order ([`map_indices`](crate::map_indices)) and every statistic is reduced
//! sequentially in that order. Hence an estimate is **bitwise identical for
//! any thread count and for any split of the index range**
//! ([`LyapunovEstimate::merge`] of `[0, k)` and `[k, n)` equals one run over
//! `[0, n)`).
//!
//! # Stop rule
//! [`Ensemble::run_until`] runs batches of initial conditions until
//! `SEM/|mean|` reaches a target or a wall-time budget is spent, and reports
//! which ([`StopReason`]). Stopping on the target is deterministic for a given
//! batch size; stopping on time is not (it depends on the machine), but the
//! trajectories it did run are still the same numbers as in any other run.
//!
//! # Kernel seam
//! All per-trajectory work goes through [`trajectory_ftle`] (one initial
//! condition) and a private chunk function over a contiguous index range: a
//! faster kernel (many trajectories in vector lanes) replaces the chunk
//! function and everything above it — ordering, statistics, stop rule,
//! results — stays as it is.

use std::ops::Range;
use std::time::{Duration, Instant};

use spinball_core::{Billiard, Sampler, SpinLaw, State, TangentVector, ic_rng};
use spinball_geometry::{Boundary, Table, TableVisitor};
use spinball_lanes::{CHUNK, LaneBilliard, LanesError};

use crate::error::AnalysisError;
use crate::ftle::CHAOS_THRESHOLD;
use crate::lyapunov::{LyapunovOptions, Method, largest_lyapunov, random_direction};
use crate::parallel::{Threads, map_chunks};
use crate::result::{LyapunovEstimate, StopReason};
use crate::stats::Accumulator;

/// What one trajectory of an ensemble produced.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct TrajectoryStats {
    /// Index of the initial condition.
    pub index: u64,
    /// Finite-time exponent per unit time, `Σ ln(stretch) / time`.
    pub exponent: f64,
    /// Finite-time exponent per collision, `Σ ln(stretch) / collisions`.
    pub per_collision: f64,
    /// Total flight time of the reference trajectory.
    pub time: f64,
    /// Collisions taken.
    pub collisions: u64,
}

/// Which implementation runs an ensemble's trajectories. Both give the same
/// trajectories (the lane kernels reproduce the scalar reference trajectory
/// bitwise); the summed logarithms agree to rounding, because the lanes
/// accumulate growth factors and take one logarithm at the end: measured
/// relative differences are about `1e-13` for finite differences, `1e-16` for
/// the tangent method on chaotic orbits, up to `5e-11` on regular ones after
/// 5000 collisions, and up to `3e-6` for a ball sliding along a wall at a
/// grazing angle of `1e-9` (which amplifies rounding by about `1e9`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "lowercase"))]
pub enum Engine {
    /// Many trajectories in lockstep vector lanes ([`spinball_lanes`]), the
    /// instruction set (AVX-512, AVX2, baseline) chosen at run time. The default.
    #[default]
    Lanes,
    /// One trajectory at a time through [`trajectory_ftle`], the readable
    /// specification.
    Scalar,
}

impl Engine {
    /// `lanes` or `scalar`.
    pub fn name(&self) -> &'static str {
        match self {
            Engine::Lanes => "lanes",
            Engine::Scalar => "scalar",
        }
    }
}

/// The finite-time Lyapunov exponent of initial condition `index` of the run
/// with `seed`: draws the state with `sampler` from
/// [`ic_rng(seed, index)`](ic_rng), then runs [`largest_lyapunov`] for
/// `collisions` collisions with `method`, drawing the perturbation direction
/// from the same stream.
///
/// This is the one place an ensemble's per-trajectory work happens, and the
/// specification a faster kernel must reproduce.
///
/// ```
/// use spinball_analysis::{Method, trajectory_ftle};
/// use spinball_core::{Billiard, Sampler, SpinLaw};
/// use spinball_geometry::Stadium;
///
/// let billiard = Billiard::new(Stadium::new(1.0)?, SpinLaw::new(0.0)?);
/// let t = trajectory_ftle(&billiard, Sampler::Paper, 7, 3, 5_000, Method::default())?;
/// assert_eq!((t.index, t.collisions), (3, 5_000));
/// assert!(t.exponent > 0.3 && t.exponent < 0.6); // specular stadium: λ ≈ 0.43
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// # Errors
/// As [`largest_lyapunov`], with launch and step errors tagged with `index`.
pub fn trajectory_ftle<B: Boundary>(
    billiard: &Billiard<B>,
    sampler: Sampler,
    seed: u64,
    index: u64,
    collisions: u64,
    method: Method,
) -> Result<TrajectoryStats, AnalysisError> {
    let mut rng = ic_rng(seed, index);
    let start = sampler.sample(billiard.table(), billiard.law(), &mut rng);
    let options = LyapunovOptions::new(collisions, method);
    let lyap =
        largest_lyapunov(billiard, start, &options, &mut rng).map_err(|e| e.at_index(index))?;
    Ok(TrajectoryStats {
        index,
        exponent: lyap.exponent,
        per_collision: lyap.per_collision,
        time: lyap.time,
        collisions: lyap.collisions,
    })
}

/// The per-trajectory results for a contiguous range of indices, in order.
/// The seam for a faster (vector-lane) kernel: it may compute the chunk any
/// way it likes as long as each entry equals [`trajectory_ftle`]'s.
fn ftle_chunk<B: Boundary>(
    billiard: &Billiard<B>,
    sampler: Sampler,
    seed: u64,
    indices: Range<u64>,
    collisions: u64,
    method: Method,
) -> Result<Vec<TrajectoryStats>, AnalysisError> {
    indices
        .map(|i| trajectory_ftle(billiard, sampler, seed, i, collisions, method))
        .collect()
}

/// [`trajectory_ftle`] for every index in `indices`, in index order, on
/// `threads`. Works for any table type, including your own; the result is the
/// same for any thread count. Feed the exponents to
/// [`FtleDistribution`](crate::FtleDistribution) for statistics.
///
/// # Errors
/// [`AnalysisError::InvalidOption`] for zero collisions, a bad method or
/// `Threads::Fixed(0)`; otherwise the first trajectory error.
pub fn ftle_trajectories<B: Boundary + Sync>(
    billiard: &Billiard<B>,
    sampler: Sampler,
    seed: u64,
    indices: Range<u64>,
    collisions: u64,
    method: Method,
    threads: Threads,
) -> Result<Vec<TrajectoryStats>, AnalysisError> {
    LyapunovOptions::new(collisions, method).validate()?;
    if threads == Threads::Fixed(0) {
        return Err(AnalysisError::invalid("threads", "must be at least 1"));
    }
    let n = indices.end.saturating_sub(indices.start);
    // Chunks only balance the load; results do not depend on their size.
    let chunk = (n / (8 * threads.count() as u64)).clamp(1, 64);
    map_chunks(indices, chunk, threads, |range| {
        ftle_chunk(billiard, sampler, seed, range, collisions, method)
    })
}

/// A batch schedule for [`Ensemble::run_until`].
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
    pub fn new(batch: u64, target_rel_sem: f64) -> Self {
        StopRule {
            batch,
            target_rel_sem,
            time_budget: None,
            min_ics: batch,
        }
    }

    /// Also stop once `budget` of wall time is spent.
    pub fn with_time_budget(mut self, budget: Duration) -> Self {
        self.time_budget = Some(budget);
        self
    }

    /// Do not stop on the target before `min_ics` initial conditions.
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
}

/// An ensemble of trajectories to estimate the largest Lyapunov exponent.
///
/// Build it with [`Ensemble::new`] and the `with_*` methods; the table is a
/// runtime [`Table`], dispatched once per run so the collision loop is
/// statically typed. Defaults: the paper's sampler and finite-difference
/// method (δ0 = 1e-7), seed 0, initial conditions `0..1000`, 10⁴ collisions
/// each (converged to the paper's three digits, its Table I), all threads,
/// chaos threshold 0.01.
///
/// ```
/// use spinball_analysis::{Ensemble, Method, Threads};
/// use spinball_core::SpinLaw;
/// use spinball_geometry::Table;
///
/// let table: Table = "stadium:a=1".parse()?; // or Stadium::new(1.0)?
/// let estimate = Ensemble::new(table, SpinLaw::new(0.5)?)
///     .with_seed(1)
///     .with_ics(8)
///     .with_collisions(2_000)
///     .with_method(Method::Tangent)
///     .run()?;
/// assert_eq!(estimate.n_ics, 8);
/// assert!(estimate.sem > 0.0 && estimate.mean > 0.0);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct Ensemble {
    /// The table.
    pub table: Table,
    /// The spin law (α; use [`SpinLaw::extended`] for α > 1).
    pub law: SpinLaw,
    /// How initial conditions are drawn.
    pub sampler: Sampler,
    /// Seed of the initial conditions.
    pub seed: u64,
    /// Initial-condition indices to run.
    pub indices: Range<u64>,
    /// Collisions per trajectory.
    pub collisions: u64,
    /// How the exponent is measured.
    pub method: Method,
    /// Threads to use (results do not depend on it).
    pub threads: Threads,
    /// FTLE above which a trajectory counts as chaotic.
    pub threshold: f64,
    /// Which implementation runs the trajectories (results agree to rounding).
    pub engine: Engine,
}

impl Ensemble {
    /// An ensemble on `table` with `law` and the defaults listed above.
    pub fn new(table: impl Into<Table>, law: SpinLaw) -> Self {
        Ensemble {
            table: table.into(),
            law,
            sampler: Sampler::Paper,
            seed: 0,
            indices: 0..1000,
            collisions: 10_000,
            method: Method::default(),
            threads: Threads::All,
            threshold: CHAOS_THRESHOLD,
            engine: Engine::default(),
        }
    }

    /// Run the trajectories with `engine`.
    pub fn with_engine(mut self, engine: Engine) -> Self {
        self.engine = engine;
        self
    }

    /// Use `sampler` for initial conditions.
    pub fn with_sampler(mut self, sampler: Sampler) -> Self {
        self.sampler = sampler;
        self
    }
    /// Use `seed`.
    pub fn with_seed(mut self, seed: u64) -> Self {
        self.seed = seed;
        self
    }
    /// Run initial conditions `0..n`.
    pub fn with_ics(mut self, n: u64) -> Self {
        self.indices = 0..n;
        self
    }
    /// Run initial conditions `indices` (e.g. one shard of a larger run).
    pub fn with_indices(mut self, indices: Range<u64>) -> Self {
        self.indices = indices;
        self
    }
    /// `collisions` collisions per trajectory.
    pub fn with_collisions(mut self, collisions: u64) -> Self {
        self.collisions = collisions;
        self
    }
    /// Measure with `method`.
    pub fn with_method(mut self, method: Method) -> Self {
        self.method = method;
        self
    }
    /// Run on `threads`.
    pub fn with_threads(mut self, threads: Threads) -> Self {
        self.threads = threads;
        self
    }
    /// Count trajectories with FTLE > `threshold` as chaotic.
    pub fn with_threshold(mut self, threshold: f64) -> Self {
        self.threshold = threshold;
        self
    }

    /// α of the spin law.
    pub fn alpha(&self) -> f64 {
        self.law.alpha()
    }

    /// Number of initial conditions in the index range.
    pub fn n_ics(&self) -> u64 {
        self.indices.end.saturating_sub(self.indices.start)
    }

    /// Check the description.
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] for fewer than 2 initial conditions
    /// (no standard error), zero collisions, a bad method, a non-finite
    /// threshold or `Threads::Fixed(0)`.
    pub fn validate(&self) -> Result<(), AnalysisError> {
        if self.n_ics() < 2 {
            return Err(AnalysisError::invalid(
                "initial conditions",
                format!(
                    "need at least 2 for a standard error, got the range {:?}",
                    self.indices
                ),
            ));
        }
        LyapunovOptions::new(self.collisions, self.method).validate()?;
        if !self.threshold.is_finite() {
            return Err(AnalysisError::invalid(
                "threshold",
                format!("must be finite, got {}", self.threshold),
            ));
        }
        if self.threads == Threads::Fixed(0) {
            return Err(AnalysisError::invalid("threads", "must be at least 1"));
        }
        Ok(())
    }

    /// Per-trajectory results for `indices` (in index order) with this
    /// ensemble's table, law, sampler, seed, collisions, method and threads.
    ///
    /// # Errors
    /// As [`ftle_trajectories`].
    pub fn trajectories(&self, indices: Range<u64>) -> Result<Vec<TrajectoryStats>, AnalysisError> {
        if self.engine == Engine::Lanes {
            return self.lane_trajectories(indices);
        }
        self.table.visit(RunTrajectories {
            ensemble: self,
            indices,
        })
    }

    /// The lane-kernel path of [`trajectories`](Self::trajectories): the
    /// index range is cut into chunks (a multiple of the kernels' lane
    /// groups), each chunk draws its initial conditions and directions from
    /// the per-index streams exactly as [`trajectory_ftle`] does and runs them
    /// in lanes; chunks run on `threads` and come back in index order.
    fn lane_trajectories(
        &self,
        indices: Range<u64>,
    ) -> Result<Vec<TrajectoryStats>, AnalysisError> {
        LyapunovOptions::new(self.collisions, self.method).validate()?;
        let lanes = LaneBilliard::new(self.table, self.law).map_err(|e| lane_error(e, 0))?;
        map_chunks(indices, CHUNK as u64, self.threads, |range| {
            let lo = range.start;
            let (starts, directions): (Vec<State>, Vec<TangentVector>) = range
                .clone()
                .map(|i| {
                    let mut rng = ic_rng(self.seed, i);
                    let state = self.sampler.sample(&self.table, &self.law, &mut rng);
                    (state, random_direction(&mut rng))
                })
                .unzip();
            let stretches = match self.method {
                Method::FiniteDifference { delta0 } => {
                    lanes.lyapunov_fd(&starts, &directions, delta0, self.collisions)
                }
                Method::Tangent => lanes.lyapunov_tangent(&starts, &directions, self.collisions),
            }
            .map_err(|e| lane_error(e, lo))?;
            Ok(range
                .zip(stretches)
                .map(|(index, s)| TrajectoryStats {
                    index,
                    exponent: s.exponent(),
                    per_collision: s.per_collision(),
                    time: s.time,
                    collisions: s.collisions,
                })
                .collect())
        })
    }

    /// Run every initial condition in the index range.
    ///
    /// # Errors
    /// [`Ensemble::validate`], then the first trajectory error.
    pub fn run(&self) -> Result<LyapunovEstimate, AnalysisError> {
        self.validate()?;
        let clock = Instant::now();
        let trajectories = self.trajectories(self.indices.clone())?;
        let wall = clock.elapsed().as_secs_f64();
        LyapunovEstimate::from_trajectories(self, trajectories, wall, StopReason::Completed)
    }

    /// Run batches from the start of the index range until `rule` stops it
    /// (see [`StopRule`]); the estimate says why in `stop`. The range's end
    /// caps the number of initial conditions.
    ///
    /// For the same batch size, a run stopped by the target always stops
    /// after the same batch with the same numbers; and any run's numbers equal
    /// those of [`Ensemble::run`] over the indices it covered.
    ///
    /// ```
    /// use spinball_analysis::{Ensemble, StopReason, StopRule};
    /// use spinball_core::SpinLaw;
    /// use spinball_geometry::Stadium;
    ///
    /// let ensemble = Ensemble::new(Stadium::new(1.0)?, SpinLaw::new(0.0)?)
    ///     .with_ics(1_000)
    ///     .with_collisions(2_000);
    /// let estimate = ensemble.run_until(&StopRule::new(8, 0.02))?;
    /// assert_eq!(estimate.stop, StopReason::TargetReached);
    /// assert!(estimate.sem <= 0.02 * estimate.mean);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// # Errors
    /// [`StopRule::validate`], [`Ensemble::validate`], then the first
    /// trajectory error.
    pub fn run_until(&self, rule: &StopRule) -> Result<LyapunovEstimate, AnalysisError> {
        rule.validate()?;
        self.validate()?;
        let clock = Instant::now();
        let Range { start, end } = self.indices;
        let mut trajectories = Vec::new();
        let mut acc = Accumulator::new();
        let mut next = start;
        let stop = loop {
            let hi = next.saturating_add(rule.batch).min(end);
            let batch = self.trajectories(next..hi)?;
            for t in &batch {
                acc.push(t.exponent);
            }
            trajectories.extend(batch);
            next = hi;
            let target_met = match (acc.mean(), acc.sem()) {
                (Some(mean), Some(sem)) => {
                    acc.count() >= rule.min_ics && sem <= rule.target_rel_sem * mean.abs()
                }
                _ => false,
            };
            if target_met {
                break StopReason::TargetReached;
            }
            if rule.time_budget.is_some_and(|b| clock.elapsed() >= b) {
                break StopReason::TimeBudget;
            }
            if next >= end {
                break StopReason::RangeExhausted;
            }
        };
        let wall = clock.elapsed().as_secs_f64();
        LyapunovEstimate::from_trajectories(self, trajectories, wall, stop)
    }
}

/// Runs [`ftle_trajectories`] with the concrete table type.
struct RunTrajectories<'a> {
    ensemble: &'a Ensemble,
    indices: Range<u64>,
}

impl TableVisitor for RunTrajectories<'_> {
    type Output = Result<Vec<TrajectoryStats>, AnalysisError>;
    fn visit<B: Boundary + Clone + Send + Sync>(self, table: &B) -> Self::Output {
        let e = self.ensemble;
        let billiard = Billiard::new(table.clone(), e.law);
        ftle_trajectories(
            &billiard,
            e.sampler,
            e.seed,
            self.indices,
            e.collisions,
            e.method,
            e.threads,
        )
    }
}

/// A lane-kernel error in terms of the ensemble (indices made absolute).
fn lane_error(e: LanesError, first: u64) -> AnalysisError {
    match e {
        LanesError::Launch { index, source } => AnalysisError::Launch {
            index: first + index as u64,
            source,
        },
        other => AnalysisError::invalid("engine", other.to_string()),
    }
}
