//! The one run driver: every ensemble run — [`Ensemble::run`],
//! [`Ensemble::run_until`], each point of an
//! [`AlphaSweep`](crate::run::AlphaSweep), each column of a convergence table in
//! the lane engine — goes through [`Ensemble::run_observed`].
//!
//! Documented in the group docs (`run/mod.rs`), section "The run driver".

use std::time::Instant;

use spinball_geometry::Boundary;
use spinball_lanes::CHUNK;

use super::ensemble::Ensemble;
use super::result::{LyapunovEstimate, StopReason};
use super::stop_rule::StopRule;
use super::trajectory::TrajectoryStats;
use crate::error::AnalysisError;
use crate::estimators::Accumulator;

/// Where a run (or a point of a sweep) stands after a batch.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct BatchProgress {
    /// Index of the point in a sweep (0 for a single run).
    pub point: usize,
    /// Number of points in the sweep (1 for a single run).
    pub points: usize,
    /// Its α.
    pub alpha: f64,
    /// Initial conditions done so far.
    pub ics_done: u64,
    /// Most initial conditions the run can take (the index range).
    pub ics_max: u64,
    /// Running mean FTLE.
    pub mean: f64,
    /// Running standard error (NaN before two trajectories).
    pub sem: f64,
    /// The stop rule's target `SEM/|mean|`, if there is a rule.
    pub target_rel_sem: Option<f64>,
    /// Wall-clock seconds spent on this run so far.
    pub elapsed_s: f64,
}

impl BatchProgress {
    /// Running `SEM/|mean|`.
    #[must_use]
    pub fn rel_sem(&self) -> f64 {
        self.sem / self.mean.abs()
    }
}

/// What a run reports while it goes.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum RunEvent<'a> {
    /// Point `point` (of `points`) at `alpha` starts.
    Started {
        /// Index of the point in a sweep (0 for a single run).
        point: usize,
        /// Number of points (1 for a single run).
        points: usize,
        /// Its α.
        alpha: f64,
    },
    /// The trajectories of the batch that just finished, in index order
    /// (reported before its [`RunEvent::Batch`]): what a checkpoint writer
    /// keeps.
    Trajectories(&'a [TrajectoryStats]),
    /// A batch of initial conditions finished.
    Batch(&'a BatchProgress),
    /// Point `point` finished with `estimate`.
    Finished {
        /// Index of the point in a sweep (0 for a single run).
        point: usize,
        /// Number of points (1 for a single run).
        points: usize,
        /// Its result.
        estimate: &'a LyapunovEstimate,
    },
}

/// What an observer tells the run after an event.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Control {
    /// Go on.
    #[default]
    Continue,
    /// Stop after this batch: the estimate covers what is done
    /// ([`StopReason::Cancelled`]); a sweep stops after this point.
    Stop,
}

/// Something that watches a run: a progress bar, a logger, a writer of
/// rows, a cancellation flag. Closures `FnMut(&RunEvent) -> Control` are
/// observers; [`Silent`] watches nothing.
pub trait RunObserver {
    /// Called on every event; the answer may stop the run.
    fn observe(&mut self, event: &RunEvent<'_>) -> Control;
}

impl<F: FnMut(&RunEvent<'_>) -> Control> RunObserver for F {
    fn observe(&mut self, event: &RunEvent<'_>) -> Control {
        self(event)
    }
}

/// The observer that watches nothing.
#[derive(Debug, Clone, Copy, Default)]
pub struct Silent;

impl RunObserver for Silent {
    fn observe(&mut self, _: &RunEvent<'_>) -> Control {
        Control::Continue
    }
}

/// Which point of how many a run is (for the events of a sweep).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Point {
    pub index: usize,
    pub of: usize,
}

impl Point {
    pub(crate) const SINGLE: Point = Point { index: 0, of: 1 };
}

/// Batches of a run without a stop rule: about 20 progress reports, each a
/// whole number of lane chunks ([`CHUNK`], a multiple of every lane kernel's
/// register group) per thread. A batch is cut into chunks from its start, so
/// a batch that is not such a multiple ends in a partial register group
/// whose idle lanes cost as much as full ones (64 initial conditions in the
/// 24-lane groups of the AVX-512 finite-difference kernel run as 72), and a
/// batch of an odd number of chunks leaves one of two threads idle for a
/// chunk. Only the run's last batch is partial. The batch size does not
/// change any number of the run.
fn default_batch(n: u64, threads: usize) -> u64 {
    let whole = CHUNK as u64 * threads.max(1) as u64;
    n.div_ceil(20).max(1).next_multiple_of(whole)
}

impl<B: Boundary + Sync> Ensemble<B> {
    /// Run every initial condition in the index range.
    ///
    /// ```
    /// use spinball_analysis::estimators::Method;
    /// use spinball_analysis::run::Ensemble;
    /// use spinball_core::SpinLaw;
    /// use spinball_geometry::Stadium;
    ///
    /// // λ of the stadium (a = 1) for a solid sphere, 64 initial conditions.
    /// let estimate = Ensemble::new(Stadium::new(1.0)?, SpinLaw::new(0.4)?)
    ///     .with_ics(64)
    ///     .with_collisions(5_000)
    ///     .with_method(Method::Tangent)
    ///     .with_seed(1)
    ///     .run()?;
    /// assert!(estimate.mean() > 0.1 && estimate.mean() < 0.3); // paper §IV: ≈ 0.20
    /// assert!(estimate.sem() > 0.0 && estimate.n_ics() == 64);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// # Errors
    /// [`Ensemble::validate`], then the first trajectory error.
    pub fn run(&self) -> Result<LyapunovEstimate, AnalysisError> {
        self.run_observed(None, &mut Silent)
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
    /// use spinball_analysis::run::{Ensemble, StopReason, StopRule};
    /// use spinball_core::SpinLaw;
    /// use spinball_geometry::Stadium;
    ///
    /// let ensemble = Ensemble::new(Stadium::new(1.0)?, SpinLaw::new(0.0)?)
    ///     .with_ics(1_000)
    ///     .with_collisions(2_000);
    /// let estimate = ensemble.run_until(&StopRule::new(8, 0.02))?;
    /// assert_eq!(estimate.stop(), StopReason::TargetReached);
    /// assert!(estimate.sem() <= 0.02 * estimate.mean());
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// # Errors
    /// [`StopRule::validate`], [`Ensemble::validate`], then the first
    /// trajectory error.
    pub fn run_until(&self, rule: &StopRule) -> Result<LyapunovEstimate, AnalysisError> {
        self.run_observed(Some(rule), &mut Silent)
    }

    /// The driver: run in batches (the rule's, or about 20 without one),
    /// report every event to `observer`, stop on the rule, on the end of
    /// the range or when the observer says [`Control::Stop`].
    ///
    /// ```
    /// use spinball_analysis::run::{Control, Ensemble, RunEvent, StopReason, Threads};
    /// use spinball_core::SpinLaw;
    /// use spinball_geometry::Sinai;
    ///
    /// let ensemble = Ensemble::new(Sinai::new(2.0, 1.0)?, SpinLaw::new(0.5)?)
    ///     .with_ics(1_000)
    ///     .with_collisions(1_000)
    ///     .with_threads(Threads::Fixed(1));
    /// // Cancel after the first batch (e.g. on Ctrl-C).
    /// let estimate = ensemble.run_observed(None, &mut |event: &RunEvent<'_>| match event {
    ///     RunEvent::Batch(_) => Control::Stop,
    ///     _ => Control::Continue,
    /// })?;
    /// assert_eq!(estimate.stop(), StopReason::Cancelled);
    /// // A batch of about a twentieth of the range, in whole lane chunks
    /// // (96 initial conditions) per thread.
    /// assert_eq!(estimate.n_ics(), 96);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// # Errors
    /// As [`run_until`](Self::run_until); [`AnalysisError::Cancelled`] if
    /// the observer stops the run before two initial conditions are done.
    pub fn run_observed<O: RunObserver + ?Sized>(
        &self,
        stop: Option<&StopRule>,
        observer: &mut O,
    ) -> Result<LyapunovEstimate, AnalysisError> {
        self.drive(stop, Point::SINGLE, observer)
    }

    pub(crate) fn drive<O: RunObserver + ?Sized>(
        &self,
        stop: Option<&StopRule>,
        point: Point,
        observer: &mut O,
    ) -> Result<LyapunovEstimate, AnalysisError> {
        self.validate()?;
        let clock = Instant::now();
        let Batches {
            trajectories,
            reason,
        } = self.batches(stop, point, Vec::new(), observer)?;
        if trajectories.len() < 2 && reason == StopReason::Cancelled {
            return Err(AnalysisError::Cancelled);
        }
        let wall = clock.elapsed().as_secs_f64();
        let estimate =
            LyapunovEstimate::from_trajectories(&self.provenance(), trajectories, wall, reason)?;
        let finished = RunEvent::Finished {
            point: point.index,
            points: point.of,
            estimate: &estimate,
        };
        // A stop asked for at the very end has nothing left to stop.
        let _ = observer.observe(&finished);
        Ok(estimate)
    }

    /// The batch loop: run from the end of `done` (trajectories already
    /// computed from the start of the index range, in order) until the
    /// rule, the range or the observer stops it.
    pub(crate) fn batches<O: RunObserver + ?Sized>(
        &self,
        stop: Option<&StopRule>,
        point: Point,
        done: Vec<TrajectoryStats>,
        observer: &mut O,
    ) -> Result<Batches, AnalysisError> {
        if let Some(rule) = stop {
            rule.validate()?;
        }
        self.validate_settings()?;
        let alpha = self.alpha();
        let started = RunEvent::Started {
            point: point.index,
            points: point.of,
            alpha,
        };
        let mut cancelled = observer.observe(&started) == Control::Stop;
        let clock = Instant::now();
        let (start, end) = (self.indices.start, self.indices.end);
        let n = end - start;
        let batch = stop.map_or_else(|| default_batch(n, self.threads.count()), |r| r.batch);
        let mut acc: Accumulator = done.iter().map(|t| t.exponent).collect();
        let mut next = start.saturating_add(done.len() as u64).min(end);
        let mut trajectories = done;
        if next >= end && stop.is_none() {
            return Ok(Batches {
                trajectories,
                reason: StopReason::Completed,
            });
        }
        let reason = loop {
            if cancelled {
                break StopReason::Cancelled;
            }
            let hi = next.saturating_add(batch).min(end);
            let part = self.trajectories(next..hi)?;
            for t in &part {
                acc.push(t.exponent);
            }
            cancelled = observer.observe(&RunEvent::Trajectories(&part)) == Control::Stop;
            trajectories.extend(part);
            next = hi;
            let (mean, sem) = (
                acc.mean().unwrap_or(f64::NAN),
                acc.sem().unwrap_or(f64::NAN),
            );
            let progress = BatchProgress {
                point: point.index,
                points: point.of,
                alpha,
                ics_done: acc.count(),
                ics_max: n,
                mean,
                sem,
                target_rel_sem: stop.map(|r| r.target_rel_sem),
                elapsed_s: clock.elapsed().as_secs_f64(),
            };
            cancelled |= observer.observe(&RunEvent::Batch(&progress)) == Control::Stop;
            match stop {
                Some(rule) => {
                    if rule.target_met(acc.count(), mean, sem) {
                        break rule.reached();
                    }
                    if rule.time_budget.is_some_and(|b| clock.elapsed() >= b) {
                        break StopReason::TimeBudget;
                    }
                    if next >= end {
                        break StopReason::RangeExhausted;
                    }
                }
                None if next >= end => break StopReason::Completed,
                None => {}
            }
        };
        Ok(Batches {
            trajectories,
            reason,
        })
    }
}

/// What the batch loop produced: the trajectories from the start of the
/// range, and why it stopped.
pub(crate) struct Batches {
    pub trajectories: Vec<TrajectoryStats>,
    pub reason: StopReason,
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::run::parallel::Threads;
    use crate::test_support::template;

    #[test]
    fn default_batches_fill_whole_lane_chunks_per_thread() {
        // About 20 batches, rounded up to whole chunks per thread.
        assert_eq!(default_batch(1_000, 1), CHUNK as u64);
        assert_eq!(default_batch(1_000, 2), 2 * CHUNK as u64);
        assert_eq!(default_batch(100_000, 2), 27 * 2 * CHUNK as u64);
        assert_eq!(default_batch(1, 1), CHUNK as u64);
        for (n, threads) in [(10, 1), (999, 2), (4_000, 3), (123_456, 8)] {
            let batch = default_batch(n, threads);
            assert_eq!(
                batch % (CHUNK * threads) as u64,
                0,
                "n {n} threads {threads}"
            );
            assert!(batch >= n.div_ceil(20), "n {n} threads {threads}");
            assert!(batch < n.div_ceil(20) + (CHUNK * threads) as u64);
        }
    }

    #[test]
    fn a_run_reports_batches_of_whole_chunks_and_a_partial_last() {
        let n = 2 * CHUNK as u64 + 5;
        let ensemble = template()
            .with_ics(n)
            .with_collisions(50)
            .with_threads(Threads::Fixed(1));
        let mut sizes = Vec::new();
        let estimate = ensemble
            .run_observed(None, &mut |event: &RunEvent<'_>| {
                if let RunEvent::Trajectories(part) = event {
                    sizes.push(part.len());
                }
                Control::Continue
            })
            .unwrap();
        assert_eq!(sizes, [CHUNK, CHUNK, 5]);
        // The batch size changes no number.
        let whole = ensemble.run_until(&StopRule::new(n, 0.0)).unwrap();
        assert_eq!(estimate.mean.to_bits(), whole.mean.to_bits());
        assert_eq!(estimate.sem.to_bits(), whole.sem.to_bits());
    }
}
