//! Results that are not finished yet: a shard of a campaign, or a run
//! stopped by a signal or a time limit, kept so that it can be resumed and
//! merged.
//!
//! Documented in the group docs (`run/mod.rs`), section "Partial runs".

use std::{ops::Range, time::Instant};

use spinball_geometry::Boundary;
use thiserror::Error;

#[cfg(feature = "serde")]
use super::checksum::Fnv1a;
use super::checksum::{IntegrityError, finite};
use super::driver::{Point, RunObserver};
use super::ensemble::Ensemble;
use super::provenance::{Provenance, RunDifference};
use super::result::{LyapunovEstimate, StopReason};
use super::trajectory::TrajectoryStats;
use crate::error::AnalysisError;

/// A run over an index range, possibly unfinished.
///
/// As JSON (feature `serde`) it carries, besides its fields,
/// `n_trajectories` (the count of per-IC values) and `checksum`
/// (`fnv1a64:` and 16 hex digits: FNV-1a over the exact bits of the
/// provenance, range, wall time, version, count and every per-IC value).
/// Reading one back checks both and that every value is finite
/// ([`IntegrityError`]), so an edited or damaged file is refused, never
/// merged or resumed; writing one with a non-finite value fails (it would
/// read back as `null`).
#[derive(Debug, Clone, PartialEq)]
pub struct PartialRun {
    /// The run's parameters.
    pub provenance: Provenance,
    /// The initial-condition indices this run is responsible for.
    pub indices: Range<u64>,
    /// The trajectories finished, from `indices.start` on, in order.
    pub trajectories: Vec<TrajectoryStats>,
    /// Wall-clock seconds spent so far (summed over resumptions).
    pub wall_time_s: f64,
    /// The spinball version that computed it.
    pub version: String,
}

impl PartialRun {
    /// A run of `provenance` over `indices` with nothing done yet.
    #[must_use]
    pub fn new(provenance: Provenance, indices: Range<u64>) -> Self {
        PartialRun {
            provenance,
            indices,
            trajectories: Vec::new(),
            wall_time_s: 0.0,
            version: env!("CARGO_PKG_VERSION").to_string(),
        }
    }

    /// Check that the run holds together: its trajectories are the
    /// consecutive indices from the start of its range, within it, each
    /// with a finite exponent, per-collision exponent and time. A run made
    /// by [`Ensemble::run_partial`] always does; [`merge_partials`] and a
    /// resume refuse one that does not.
    ///
    /// # Errors
    /// [`IntegrityError::Indices`] or [`IntegrityError::NonFinite`].
    pub fn check(&self) -> Result<(), IntegrityError> {
        for (expected, t) in (self.indices.start..).zip(&self.trajectories) {
            if t.index != expected || expected >= self.indices.end {
                return Err(IntegrityError::Indices {
                    range: self.indices.clone(),
                    expected,
                    found: t.index,
                });
            }
            finite(t.index, "exponent", t.exponent)?;
            finite(t.index, "per-collision exponent", t.per_collision)?;
            finite(t.index, "time", t.time)?;
        }
        Ok(())
    }

    /// The checksum of the content (written and checked with the JSON).
    #[cfg(feature = "serde")]
    fn checksum(&self) -> Fnv1a {
        let mut h = Fnv1a::new("spinball.partial_run");
        h.provenance(&self.provenance);
        h.u64(self.indices.start);
        h.u64(self.indices.end);
        h.f64(self.wall_time_s);
        h.str(&self.version);
        h.u64(self.trajectories.len() as u64);
        for t in &self.trajectories {
            h.trajectory(t);
        }
        h
    }

    /// The indices finished.
    #[must_use]
    pub fn done(&self) -> Range<u64> {
        self.indices.start..self.indices.start + self.trajectories.len() as u64
    }

    /// The indices still to run.
    #[must_use]
    pub fn remaining(&self) -> Range<u64> {
        self.done().end..self.indices.end
    }

    /// Whether every index of the range is done.
    #[must_use]
    pub fn is_complete(&self) -> bool {
        self.remaining().is_empty()
    }

    /// Append trajectories that continue the finished ones.
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] if they do not start at the next
    /// index, are not consecutive, or run past the range.
    pub fn extend(&mut self, more: &[TrajectoryStats]) -> Result<(), AnalysisError> {
        for (next, t) in (self.done().end..).zip(more) {
            if t.index != next || next >= self.indices.end {
                return Err(AnalysisError::invalid(
                    "trajectories",
                    format!(
                        "trajectory {} does not continue the run over {:?} (next index {next})",
                        t.index, self.indices
                    ),
                ));
            }
        }
        self.trajectories.extend_from_slice(more);
        Ok(())
    }

    /// The estimate over the finished trajectories (stop reason
    /// [`StopReason::Completed`] if the range is done, else
    /// [`StopReason::Cancelled`]).
    ///
    /// # Errors
    /// [`LyapunovEstimate::from_trajectories`]'s (fewer than two
    /// trajectories, a non-finite exponent).
    pub fn estimate(&self) -> Result<LyapunovEstimate, AnalysisError> {
        let stop = if self.is_complete() {
            StopReason::Completed
        } else {
            StopReason::Cancelled
        };
        LyapunovEstimate::from_trajectories(
            &self.provenance,
            self.trajectories.clone(),
            self.wall_time_s,
            stop,
        )
    }
}

#[cfg(feature = "serde")]
mod file {
    use std::ops::Range;

    use serde::{Deserialize, Deserializer, Serialize, Serializer, de, ser};

    use super::{IntegrityError, PartialRun, Provenance, TrajectoryStats};
    use crate::run::checksum::verify;

    /// A partial run as written: its fields, the count and the checksum.
    #[derive(Serialize)]
    struct Written<'a> {
        provenance: &'a Provenance,
        indices: &'a Range<u64>,
        trajectories: &'a [TrajectoryStats],
        wall_time_s: f64,
        version: &'a str,
        n_trajectories: u64,
        checksum: String,
    }

    /// A partial run as read, before its checks.
    #[derive(Deserialize)]
    struct Read {
        provenance: Provenance,
        indices: Range<u64>,
        trajectories: Vec<TrajectoryStats>,
        wall_time_s: f64,
        version: String,
        #[serde(default)]
        n_trajectories: Option<u64>,
        #[serde(default)]
        checksum: Option<String>,
    }

    impl Serialize for PartialRun {
        fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
            self.check().map_err(ser::Error::custom)?;
            Written {
                provenance: &self.provenance,
                indices: &self.indices,
                trajectories: &self.trajectories,
                wall_time_s: self.wall_time_s,
                version: &self.version,
                n_trajectories: self.trajectories.len() as u64,
                checksum: self.checksum().text(),
            }
            .serialize(s)
        }
    }

    impl<'de> Deserialize<'de> for PartialRun {
        fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
            let r = Read::deserialize(d)?;
            let stated = match (r.n_trajectories, &r.checksum) {
                (Some(n), Some(_)) => n,
                _ => {
                    return Err(de::Error::custom(IntegrityError::NoChecksum {
                        version: r.version,
                    }));
                }
            };
            let run = PartialRun {
                provenance: r.provenance,
                indices: r.indices,
                trajectories: r.trajectories,
                wall_time_s: r.wall_time_s,
                version: r.version,
            };
            let found = run.trajectories.len() as u64;
            if stated != found {
                return Err(de::Error::custom(IntegrityError::Count { stated, found }));
            }
            verify(r.checksum.as_deref(), &run.checksum(), &run.version)
                .and_then(|()| run.check())
                .map_err(de::Error::custom)?;
            Ok(run)
        }
    }
}

/// Why partial runs could not be merged.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum MergeError {
    /// Nothing to merge.
    #[error("no partial results to merge")]
    Empty,
    /// Two pieces come from different runs.
    #[error(
        "the partial results are of different runs: {what} {first} in one, {other} in another; merge only the shards of one command"
    )]
    DifferentRuns {
        /// The parameter that differs.
        what: &'static str,
        /// Its value in the first piece.
        first: String,
        /// Its value in the other piece.
        other: String,
    },
    /// Two pieces cover some of the same indices.
    #[error(
        "initial conditions {first:?} and {second:?} overlap: each index must come from one shard"
    )]
    Overlap {
        /// One piece's range.
        first: Range<u64>,
        /// The other's.
        second: Range<u64>,
    },
    /// Indices between two pieces (or at the ends) are missing.
    #[error("initial conditions {missing:?} are missing: no partial result covers them")]
    Missing {
        /// The indices no piece covers.
        missing: Range<u64>,
    },
    /// A piece has not finished its range (resume it first).
    #[error(
        "the partial result over {indices:?} is unfinished (done {done:?}); resume it before merging"
    )]
    Unfinished {
        /// Its range.
        indices: Range<u64>,
        /// What it finished.
        done: Range<u64>,
    },
    /// The table has no shape, so nothing shows the pieces are of one
    /// table ([`RunDifference::NoShape`]).
    #[error(transparent)]
    Table(RunDifference),
    /// A piece does not hold together ([`PartialRun::check`]).
    #[error("the partial result over {indices:?} is refused: {source}")]
    Invalid {
        /// Its range.
        indices: Range<u64>,
        /// What does not hold.
        source: IntegrityError,
    },
    /// The merged trajectories do not make an estimate.
    #[error(transparent)]
    Estimate(#[from] AnalysisError),
}

impl From<RunDifference> for MergeError {
    /// A field that differs is [`MergeError::DifferentRuns`]; a table
    /// without a shape is [`MergeError::Table`].
    fn from(e: RunDifference) -> Self {
        match e {
            RunDifference::Field { what, first, other } => {
                MergeError::DifferentRuns { what, first, other }
            }
            e => MergeError::Table(e),
        }
    }
}

/// Join the pieces of a run (shards, in any order) into the estimate over
/// `expected` (the whole range the pieces should tile; `None`: the union of
/// their ranges, which must then be contiguous). The result is bitwise that
/// of one uninterrupted run over the range, except `wall_time_s`, the sum of
/// the pieces'.
///
/// # Errors
/// [`MergeError`]: pieces of different runs or versions, overlapping or
/// missing indices, an unfinished piece, a piece that does not hold
/// together ([`PartialRun::check`]), a table without a shape.
pub fn merge_partials(
    mut parts: Vec<PartialRun>,
    expected: Option<Range<u64>>,
) -> Result<LyapunovEstimate, MergeError> {
    let first = parts.first().ok_or(MergeError::Empty)?.clone();
    for p in &parts {
        p.check().map_err(|source| MergeError::Invalid {
            indices: p.indices.clone(),
            source,
        })?;
        first.provenance.difference(&p.provenance)?;
        if p.version != first.version {
            return Err(MergeError::DifferentRuns {
                what: "version",
                first: first.version.clone(),
                other: p.version.clone(),
            });
        }
    }
    parts.sort_by_key(|p| (p.indices.start, p.indices.end));
    let start = expected
        .as_ref()
        .map_or(parts[0].indices.start, |r| r.start);
    let mut next = start;
    for (i, p) in parts.iter().enumerate() {
        if p.indices.start > next {
            return Err(MergeError::Missing {
                missing: next..p.indices.start,
            });
        }
        if p.indices.start < next {
            return Err(MergeError::Overlap {
                first: parts[i - 1].indices.clone(),
                second: p.indices.clone(),
            });
        }
        if !p.is_complete() {
            return Err(MergeError::Unfinished {
                indices: p.indices.clone(),
                done: p.done(),
            });
        }
        next = p.indices.end;
    }
    if let Some(end) = expected.map(|r| r.end)
        && next < end
    {
        return Err(MergeError::Missing { missing: next..end });
    }
    let wall = parts.iter().map(|p| p.wall_time_s).sum();
    let trajectories = parts.into_iter().flat_map(|p| p.trajectories).collect();
    Ok(LyapunovEstimate::from_trajectories(
        &first.provenance,
        trajectories,
        wall,
        StopReason::Completed,
    )?)
}

impl<B: Boundary + Sync> Ensemble<B> {
    /// Run the ensemble's index range as a [`PartialRun`], continuing
    /// `resume` (a previous partial run of this ensemble) if given. Stops
    /// when the range is done or when `observer` answers
    /// [`Control::Stop`](crate::run::Control::Stop) (a signal, a time limit);
    /// what was finished is in the result either way, and running it again
    /// finishes the rest. An observer that writes every
    /// [`RunEvent::Trajectories`](crate::run::RunEvent::Trajectories) to disk
    /// keeps a checkpoint that survives a kill.
    ///
    /// ```
    /// use spinball_analysis::run::{Control, Ensemble, RunEvent, merge_partials};
    /// use spinball_core::SpinLaw;
    /// use spinball_geometry::Stadium;
    ///
    /// let ensemble = Ensemble::new(Stadium::new(1.0)?, SpinLaw::new(0.5)?)
    ///     .with_ics(200)
    ///     .with_collisions(500);
    /// // Interrupted after its first batch...
    /// let part = ensemble.run_partial(None, &mut |e: &RunEvent<'_>| match e {
    ///     RunEvent::Batch(_) => Control::Stop,
    ///     _ => Control::Continue,
    /// })?;
    /// assert!(!part.is_complete());
    /// // ...and resumed: the same numbers as one uninterrupted run.
    /// let done = ensemble.run_partial(Some(part), &mut spinball_analysis::run::Silent)?;
    /// let resumed = merge_partials(vec![done], None)?;
    /// assert_eq!(resumed.mean().to_bits(), ensemble.run()?.mean().to_bits());
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// # Errors
    /// [`AnalysisError::InvalidOption`] if `resume` is of another run or
    /// range (the message names the first field that differs: `seed 7 in
    /// the checkpoint, 8 asked`), of a table without a shape, or does not
    /// hold together ([`PartialRun::check`]); [`Ensemble::validate`]; the
    /// first trajectory error.
    pub fn run_partial<O: RunObserver + ?Sized>(
        &self,
        resume: Option<PartialRun>,
        observer: &mut O,
    ) -> Result<PartialRun, AnalysisError> {
        let provenance = self.provenance();
        let part = match resume {
            None => PartialRun::new(provenance, self.indices.clone()),
            Some(p) => {
                p.check().map_err(|e| {
                    AnalysisError::invalid("resume", format!("the checkpoint is refused: {e}"))
                })?;
                let another = |what: &str,
                               first: &dyn std::fmt::Display,
                               asked: &dyn std::fmt::Display| {
                    AnalysisError::invalid(
                        "resume",
                        format!(
                            "the checkpoint is of another run: {what} {first} in the checkpoint, \
                             {asked} asked; resume with the command that wrote it"
                        ),
                    )
                };
                match p.provenance.difference(&provenance) {
                    Ok(()) => {}
                    Err(RunDifference::Field { what, first, other }) => {
                        return Err(another(what, &first, &other));
                    }
                    Err(e) => {
                        return Err(AnalysisError::invalid(
                            "resume",
                            format!("cannot resume: {e}"),
                        ));
                    }
                }
                if p.indices != self.indices {
                    return Err(another(
                        "initial conditions",
                        &format_args!("{:?}", p.indices),
                        &format_args!("{:?}", self.indices),
                    ));
                }
                p
            }
        };
        let clock = Instant::now();
        let PartialRun {
            provenance,
            indices,
            trajectories,
            wall_time_s,
            version,
        } = part;
        let batches = self.batches(None, Point::SINGLE, trajectories, observer)?;
        Ok(PartialRun {
            provenance,
            indices,
            trajectories: batches.trajectories,
            wall_time_s: wall_time_s + clock.elapsed().as_secs_f64(),
            version,
        })
    }
}
