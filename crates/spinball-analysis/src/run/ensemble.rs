//! Ensembles of trajectories: many initial conditions, one estimate with its
//! error, bitwise reproducible on any number of threads, for any table.
//!
//! Documented in the group docs (`run/mod.rs`), section "Ensembles".

use std::ops::Range;

use spinball_core::{Billiard, Sampler, SpinLaw, State, TangentVector, random_direction};
use spinball_geometry::{Boundary, Table};
use spinball_lanes::{CHUNK, LaneBilliard, LanesError};

use super::defaults::RunDefaults;
use super::engine::Engine;
use super::parallel::{Threads, map_chunks};
use super::provenance::{Provenance, TableRecord};
use super::starts::Starts;
use super::trajectory::{TrajectoryStats, scalar_chunked, start_ftle};
use crate::error::AnalysisError;
use crate::estimators::{LyapunovOptions, Method};

/// An ensemble of trajectories to estimate the largest Lyapunov exponent.
///
/// Build it with [`Ensemble::new`] (a sampler draws the initial conditions)
/// or [`Ensemble::from_states`] (you give them) and the `with_*` methods.
/// The table is any [`Boundary`]; the built-in [`Table`] enum is the
/// default type parameter, for a table chosen at run time. Defaults
/// ([`RunDefaults`]): the
/// paper's sampler and finite-difference method (δ0 = 1e-7), seed 0,
/// initial conditions `0..1000`, 10⁴ collisions each (converged to the
/// paper's three digits, its Table I), all threads, chaos threshold 0.01,
/// lane kernels.
///
/// ```
/// use spinball_analysis::estimators::Method;
/// use spinball_analysis::run::{Engine, Ensemble};
/// use spinball_core::SpinLaw;
/// use spinball_geometry::{DVec2, SegmentTable};
///
/// // Your own table: an L-shaped room, run in lanes like the built-in ones.
/// let p = DVec2::new;
/// let room = SegmentTable::polygon(&[
///     p(0.0, 0.0), p(2.0, 0.0), p(2.0, 1.0), p(1.0, 1.0), p(1.0, 2.0), p(0.0, 2.0),
/// ])?;
/// let estimate = Ensemble::new(room, SpinLaw::new(0.5)?)
///     .with_seed(1)
///     .with_ics(16)
///     .with_collisions(2_000)
///     .with_method(Method::Tangent)
///     .run()?;
/// assert_eq!(estimate.n_ics(), 16);
/// assert_eq!(estimate.engine(), Engine::Lanes);
/// assert!(estimate.mean().is_finite() && estimate.sem() >= 0.0);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct Ensemble<B = Table> {
    /// The table.
    pub table: B,
    /// The spin law (α; use [`SpinLaw::extended`] for α > 1).
    pub law: SpinLaw,
    /// Where the initial conditions come from.
    pub starts: Starts,
    /// Seed of the initial conditions and perturbation directions.
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

impl<B: Boundary> Ensemble<B> {
    /// An ensemble on `table` with `law` and the defaults listed above.
    #[must_use]
    pub fn new(table: B, law: SpinLaw) -> Self {
        Ensemble {
            table,
            law,
            starts: Starts::Sampled(RunDefaults::SAMPLER),
            seed: RunDefaults::SEED,
            indices: 0..RunDefaults::ICS,
            collisions: RunDefaults::COLLISIONS,
            method: RunDefaults::METHOD,
            threads: RunDefaults::THREADS,
            threshold: RunDefaults::THRESHOLD,
            engine: RunDefaults::ENGINE,
        }
    }

    /// An ensemble over the given initial `states` (initial condition `i`
    /// is `states[i]`; indices `0..states.len()`); the seed still draws
    /// each trajectory's perturbation direction.
    #[must_use]
    pub fn from_states(table: B, law: SpinLaw, states: Vec<State>) -> Self {
        let n = states.len() as u64;
        Ensemble {
            starts: Starts::States(states),
            indices: 0..n,
            ..Self::new(table, law)
        }
    }

    /// Run the trajectories with `engine`.
    #[must_use]
    pub fn with_engine(mut self, engine: Engine) -> Self {
        self.engine = engine;
        self
    }
    /// Draw initial conditions with `sampler`.
    #[must_use]
    pub fn with_sampler(mut self, sampler: Sampler) -> Self {
        self.starts = Starts::Sampled(sampler);
        self
    }
    /// Use `seed`.
    #[must_use]
    pub fn with_seed(mut self, seed: u64) -> Self {
        self.seed = seed;
        self
    }
    /// Run initial conditions `0..n`.
    #[must_use]
    pub fn with_ics(mut self, n: u64) -> Self {
        self.indices = 0..n;
        self
    }
    /// Run initial conditions `indices` (e.g. one shard of a larger run).
    #[must_use]
    pub fn with_indices(mut self, indices: Range<u64>) -> Self {
        self.indices = indices;
        self
    }
    /// `collisions` collisions per trajectory.
    #[must_use]
    pub fn with_collisions(mut self, collisions: u64) -> Self {
        self.collisions = collisions;
        self
    }
    /// Measure with `method`.
    #[must_use]
    pub fn with_method(mut self, method: Method) -> Self {
        self.method = method;
        self
    }
    /// Run on `threads`.
    #[must_use]
    pub fn with_threads(mut self, threads: Threads) -> Self {
        self.threads = threads;
        self
    }
    /// Count trajectories with FTLE > `threshold` as chaotic.
    #[must_use]
    pub fn with_threshold(mut self, threshold: f64) -> Self {
        self.threshold = threshold;
        self
    }
    /// The same ensemble with spin law `law`.
    #[must_use]
    pub fn with_law(mut self, law: SpinLaw) -> Self {
        self.law = law;
        self
    }

    /// α of the spin law.
    #[must_use]
    pub fn alpha(&self) -> f64 {
        self.law.alpha()
    }

    /// Number of initial conditions in the index range.
    #[must_use]
    pub fn n_ics(&self) -> u64 {
        self.indices.end.saturating_sub(self.indices.start)
    }

    /// The sampler, if the initial conditions are drawn.
    #[must_use]
    pub fn sampler(&self) -> Option<Sampler> {
        self.starts.sampler()
    }

    /// The engine a run of this ensemble uses: [`Engine::Lanes`] if asked
    /// for and the table has a lane form, else [`Engine::Scalar`].
    #[must_use]
    pub fn engine_used(&self) -> Engine {
        match self.engine {
            Engine::Lanes if spinball_lanes::has_lane_form(&self.table) => Engine::Lanes,
            _ => Engine::Scalar,
        }
    }

    /// The parameters a result of this ensemble records.
    #[must_use]
    pub fn provenance(&self) -> Provenance {
        Provenance::new(
            TableRecord::of(&self.table),
            self.law.alpha(),
            self.method,
            self.sampler(),
            self.seed,
            self.collisions,
            self.threshold,
            self.engine_used(),
        )
    }

    /// Check the description.
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] for fewer than 2 initial conditions
    /// (no standard error), an index range past the end of explicit states,
    /// zero collisions, a bad method (finite differences on a periodic
    /// table), a non-finite threshold or `Threads::Fixed(0)`.
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
        self.validate_settings()
    }

    /// Check everything [`validate`](Self::validate) checks except the
    /// number of initial conditions: what a piece of a run (a
    /// [`PartialRun`](crate::run::PartialRun), a shard of one initial condition)
    /// needs.
    ///
    /// # Errors
    /// As [`validate`](Self::validate), bar the count.
    pub fn validate_settings(&self) -> Result<(), AnalysisError> {
        if let Some(n) = self.starts.count()
            && self.indices.end > n
        {
            return Err(AnalysisError::invalid(
                "indices",
                format!(
                    "the range {:?} runs past the {n} states given (use 0..{n} or less)",
                    self.indices
                ),
            ));
        }
        LyapunovOptions::new(self.collisions, self.method).validate()?;
        if self.table.lattice().is_some() && matches!(self.method, Method::FiniteDifference { .. })
        {
            return Err(AnalysisError::invalid(
                "method",
                "finite differences compare a shadow ball's position with the reference's, and on a periodic table the two may sit in neighbouring cells near a periodic wall: use Method::Tangent (the tangent map is unchanged by a crossing)",
            ));
        }
        if !self.threshold.is_finite() {
            return Err(AnalysisError::invalid(
                "threshold",
                format!("must be finite, got {}", self.threshold),
            ));
        }
        self.threads.validate()
    }
}

impl<B: Boundary + Sync> Ensemble<B> {
    /// Per-trajectory results for `indices` (in index order) with this
    /// ensemble's table, law, initial conditions, seed, collisions, method,
    /// engine and threads. The numbers do not depend on how a range is
    /// split into calls.
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] for zero collisions, a bad method or
    /// `Threads::Fixed(0)`; otherwise the first failing trajectory's error
    /// (the same on both engines, with its absolute index).
    pub fn trajectories(&self, indices: Range<u64>) -> Result<Vec<TrajectoryStats>, AnalysisError> {
        LyapunovOptions::new(self.collisions, self.method).validate()?;
        self.threads.validate()?;
        let billiard = Billiard::new(&self.table, self.law);
        match self.engine_used() {
            Engine::Lanes => self.lane_trajectories(&billiard, indices),
            Engine::Scalar => scalar_chunked(
                &billiard,
                &self.starts,
                self.seed,
                indices,
                self.collisions,
                self.method,
                self.threads,
            ),
        }
    }

    /// The lane-kernel path of [`trajectories`](Self::trajectories): the
    /// index range is cut into chunks (a multiple of the kernels' lane
    /// groups), each chunk draws its initial conditions and directions from
    /// the per-index streams exactly as the scalar path does and runs them
    /// in lanes; chunks run on `threads` and come back in index order.
    fn lane_trajectories(
        &self,
        billiard: &Billiard<&B>,
        indices: Range<u64>,
    ) -> Result<Vec<TrajectoryStats>, AnalysisError> {
        let rows = self.lane_reads(billiard, indices, &[self.collisions])?;
        Ok(rows.into_iter().flatten().collect())
    }

    /// The lane-kernel runs of `indices` read at each run length of
    /// `reads` (increasing): per index, its statistics at each read, in
    /// order. The trajectories stop at each read and go on from there
    /// ([`LaneBilliard::resume`]), so a read costs nothing beyond the
    /// collisions up to the longest, and each read is bitwise a run of that
    /// length.
    ///
    /// # Errors
    /// As [`trajectories`](Self::trajectories) with `collisions` the read
    /// that failed.
    pub(crate) fn lane_reads(
        &self,
        billiard: &Billiard<&B>,
        indices: Range<u64>,
        reads: &[u64],
    ) -> Result<Vec<Vec<TrajectoryStats>>, AnalysisError> {
        let lanes = LaneBilliard::new(&self.table, self.law).map_err(AnalysisError::Lanes)?;
        map_chunks(indices, CHUNK as u64, self.threads, |range| {
            let lo = range.start;
            let mut starts = Vec::with_capacity(CHUNK);
            let mut directions: Vec<TangentVector> = Vec::with_capacity(CHUNK);
            for i in range.clone() {
                let (state, mut rng) =
                    self.starts
                        .draw(billiard.table(), billiard.law(), self.seed, i)?;
                starts.push(state);
                directions.push(random_direction(&mut rng));
            }
            let mut paused = match self.method {
                Method::FiniteDifference { delta0 } => lanes.start_fd(&starts, &directions, delta0),
                Method::Tangent => lanes.start_tangent(&starts, &directions),
            }
            .map_err(|e| self.lane_error(billiard, e, lo, reads[0]))?;
            let mut rows: Vec<Vec<TrajectoryStats>> = range
                .clone()
                .map(|_| Vec::with_capacity(reads.len()))
                .collect();
            let mut done = 0;
            for &t in reads {
                paused = lanes
                    .resume(&paused, t - done)
                    .map_err(|e| self.lane_error(billiard, e, lo, t))?;
                done = t;
                for ((row, index), p) in rows.iter_mut().zip(range.clone()).zip(&paused) {
                    let s = p.stretch();
                    row.push(TrajectoryStats {
                        index,
                        exponent: s.exponent(),
                        per_collision: s.per_collision(),
                        time: s.time,
                        collisions: s.collisions,
                    });
                }
            }
            Ok(rows)
        })
    }

    /// A lane-kernel error as the scalar path reports it: the launch error
    /// with its absolute index, and for a trajectory that went non-finite
    /// the scalar path's own error for that initial condition.
    fn lane_error(
        &self,
        billiard: &Billiard<&B>,
        e: LanesError,
        first: u64,
        collisions: u64,
    ) -> AnalysisError {
        match e {
            LanesError::Launch { index, source } => AnalysisError::Launch {
                index: first + index as u64,
                source,
            },
            LanesError::NonFinite { index } => {
                let index = first + index as u64;
                match start_ftle(
                    billiard,
                    &self.starts,
                    self.seed,
                    index,
                    collisions,
                    self.method,
                ) {
                    Err(scalar) => scalar,
                    Ok(_) => AnalysisError::EngineMismatch { index },
                }
            }
            LanesError::Perturbation { index, source } => AnalysisError::Perturbation {
                index: first + index as u64,
                source,
            },
            // The same option checks as the scalar path's, so the same error.
            LanesError::InvalidOption { name, reason } => {
                AnalysisError::InvalidOption { name, reason }
            }
            other => AnalysisError::Lanes(other),
        }
    }
}
