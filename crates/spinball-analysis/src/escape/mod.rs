//! Escape from an open table: how long a ball stays before it finds a hole.
//!
//! A table with a hole in its wall loses every ball sooner or later (or
//! keeps the ones on islands that never visit the hole). A run of many
//! initial conditions gives one **escape time** per ball, or, for a ball
//! still inside when the budget ran out, a lower bound on it (the ball is
//! **censored** at the budget: counted, never dropped). This group turns
//! such a sample, given as plain data (`&[f64]` times or `&[u64]`
//! collision counts with a `&[bool]` censored flag per ball), into the
//! numbers physicists quote, each with its error and the range it used:
//!
//! - [`Survival`]: the survival probability `P(t)` (Kaplan–Meier) with
//!   Greenwood errors and a log–log confidence band that stays in `[0, 1]`,
//!   in continuous time or by collision count; the mean escape time
//!   ([`MeanEscape`]);
//! - [`EscapeRate`]: the rate `γ` of the exponential regime
//!   `P(t) ≈ A e^{−γt}`, by maximum likelihood over a stated window
//!   ([`RateWindow`]), with a check that the rate is constant in it;
//! - [`AlgebraicTail`]: the exponent `β` of an algebraic tail
//!   `P(t) ∝ t^{−β}` and a stated decision [`TailLaw`] between an
//!   exponential and an algebraic tail;
//! - [`EscapeLaw`]: the verdict of the drift check and the tail test,
//!   whether the rate of a window may be quoted as the table's;
//! - [`KacPrediction`]: the mean escape time the invariant measure predicts
//!   for a small hole (Kac's lemma), in collisions and in time, for any α;
//! - [`EscapeSummary`]: all of the above for the records of a run
//!   ([`EscapeRecord`](crate::open::EscapeRecord)s), in time and in
//!   collisions: what the command line, Python and the examples report.
//!
//! The definitions, estimators and their errors are in `docs/TRANSPORT.md`.
//!
//! # Conventions
//! - A ball's escape collision count `n ≥ 1` counts the wall encounter
//!   through the hole itself; its escape time is the flight time up to
//!   that encounter.
//! - A censored ball was still inside at its recorded time (the budget):
//!   its escape time is larger.
//! - At equal times, escapes come before censorings (a ball censored at `t`
//!   was at risk at `t`), the usual Kaplan–Meier convention.

mod algebraic_tail;
mod escape_law;
mod escape_rate;
mod kac;
mod summary;
mod survival;

pub use algebraic_tail::{AlgebraicTail, DECISION_Z, TailLaw, TailWindow};
pub use escape_law::{DRIFT_Z, EscapeLaw};
pub use escape_rate::{EscapeRate, MIN_EVENTS, RateWindow};
pub use kac::{KacPrediction, KacRatio};
pub use summary::{ClockSummary, EscapeOptions, EscapeSummary};
pub use survival::{Clock, MeanEscape, Survival, SurvivalPoint, Z95};

use thiserror::Error;

/// Why an escape sample could not be analysed.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum EscapeError {
    /// No balls at all.
    #[error("the escape sample is empty: give at least one ball")]
    Empty,
    /// One censored flag per ball is needed.
    #[error("{times} escape times but {flags} censored flags: give one flag per ball")]
    LengthMismatch {
        /// Number of times (or collision counts).
        times: usize,
        /// Number of censored flags.
        flags: usize,
    },
    /// A time that is NaN, infinite or negative.
    #[error("escape time {value} of ball {index} is not a finite number >= 0")]
    NotFinite {
        /// Index of the ball.
        index: usize,
        /// The value found.
        value: f64,
    },
    /// No ball escaped: the survival is 1 with no error to put on it.
    #[error(
        "none of the {n} balls escaped by t = {last}: P(t) = 1 has no error estimate (at 95% only P(t) > 1 − 3/{n} is known); run longer or use a larger hole"
    )]
    AllCensored {
        /// Number of balls.
        n: usize,
        /// The largest censoring time.
        last: f64,
    },
    /// Too few escapes in the window of a fit for its error to mean
    /// anything.
    #[error(
        "only {events} escapes in the fit window [{t0}, {t1}], at least {min} are needed: widen the window or run more balls"
    )]
    TooFewEvents {
        /// Escapes in the window.
        events: u64,
        /// The least accepted.
        min: u64,
        /// Window start.
        t0: f64,
        /// Window end.
        t1: f64,
    },
    /// An escape run on a table without a hole.
    #[error(
        "the table has no hole, so no ball can escape: add one (e.g. `stadium:a=1,hole=0.2`, or `exits`/`openings` in a table file)"
    )]
    NoHole,
    /// An option out of range.
    #[error("invalid option `{name}`: {reason}")]
    InvalidOption {
        /// Name of the option.
        name: &'static str,
        /// What is wrong, and what works.
        reason: String,
    },
}

impl EscapeError {
    pub(crate) fn invalid(name: &'static str, reason: impl Into<String>) -> Self {
        EscapeError::InvalidOption {
            name,
            reason: reason.into(),
        }
    }
}

/// One ball's observation: its time and whether it was censored there.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Observation {
    pub(crate) t: f64,
    pub(crate) censored: bool,
}

/// A validated escape sample, sorted by time, escapes before censorings at
/// equal times.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Sample {
    pub(crate) obs: Vec<Observation>,
    pub(crate) escaped: usize,
}

impl Sample {
    /// Check and sort `times` with their `censored` flags.
    pub(crate) fn new(times: &[f64], censored: &[bool]) -> Result<Self, EscapeError> {
        if times.len() != censored.len() {
            return Err(EscapeError::LengthMismatch {
                times: times.len(),
                flags: censored.len(),
            });
        }
        if times.is_empty() {
            return Err(EscapeError::Empty);
        }
        if let Some((index, &value)) = times
            .iter()
            .enumerate()
            .find(|(_, t)| !(t.is_finite() && **t >= 0.0))
        {
            return Err(EscapeError::NotFinite { index, value });
        }
        let mut obs: Vec<Observation> = times
            .iter()
            .zip(censored)
            .map(|(&t, &censored)| Observation { t, censored })
            .collect();
        obs.sort_by(|a, b| a.t.total_cmp(&b.t).then(a.censored.cmp(&b.censored)));
        let escaped = obs.iter().filter(|o| !o.censored).count();
        if escaped == 0 {
            return Err(EscapeError::AllCensored {
                n: obs.len(),
                last: obs.last().map_or(0.0, |o| o.t),
            });
        }
        Ok(Sample { obs, escaped })
    }

    /// The same from collision counts (exact as `f64` below 2⁵³).
    pub(crate) fn from_collisions(counts: &[u64], censored: &[bool]) -> Result<Self, EscapeError> {
        let times: Vec<f64> = counts.iter().map(|&n| n as f64).collect();
        Sample::new(&times, censored)
    }

    pub(crate) fn len(&self) -> usize {
        self.obs.len()
    }

    /// The time of the `k`-th escape (0-based, in time order).
    pub(crate) fn escape_time(&self, k: usize) -> Option<f64> {
        self.obs.iter().filter(|o| !o.censored).nth(k).map(|o| o.t)
    }

    /// Balls with an observed time `>= t` (at risk at `t`).
    pub(crate) fn at_risk(&self, t: f64) -> usize {
        self.obs.len() - self.obs.partition_point(|o| o.t < t)
    }

    /// Balls with an observed time `> t` (still inside just after `t`).
    pub(crate) fn beyond(&self, t: f64) -> usize {
        self.obs.len() - self.obs.partition_point(|o| o.t <= t)
    }
}
