//! What a lane run returns per initial condition.
//!
//! The kernels return raw sums, not exponents: `Σ ln(stretch)`, total flight
//! time and collisions, which is what an ensemble needs to form per-time and
//! per-collision exponents, to merge runs, and to compare with the scalar
//! path without a division in between.

use spinball_core::{Exit, State};

/// A plain trajectory: where it ended and how long it flew.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Flight {
    /// State after the last collision (bitwise the scalar `Billiard::step`'s).
    pub end: State,
    /// Total flight time.
    pub time: f64,
    /// Collisions taken.
    pub collisions: u64,
}

impl Flight {
    /// Collisions per unit time.
    pub fn collision_rate(&self) -> f64 {
        self.collisions as f64 / self.time
    }
}

/// The largest Lyapunov exponent's raw sums for one trajectory.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Stretch {
    /// `Σ ln(stretch)` over the run (finite differences: `Σ ln(δ/δ0)`; exact
    /// tangent: `ln` of the growth of the tangent vector).
    pub log_stretch: f64,
    /// Total flight time of the reference trajectory.
    pub time: f64,
    /// Collisions taken.
    pub collisions: u64,
    /// State of the reference trajectory after the last collision.
    pub end: State,
}

impl Stretch {
    /// λ per unit time, `Σ ln(stretch) / Σ Δt`
    /// ([`docs/PHYSICS.md`](https://github.com/spinball/spinball/blob/main/docs/PHYSICS.md#lyapunov-exponents)).
    pub fn exponent(&self) -> f64 {
        self.log_stretch / self.time
    }
    /// λ per collision.
    pub fn per_collision(&self) -> f64 {
        self.log_stretch / self.collisions as f64
    }
}

/// The Lyapunov spectrum's raw sums for one trajectory.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SpectrumStretch {
    /// `Σ ln R_ii` for the five vectors, in the order of the Gram–Schmidt
    /// sweep (not sorted).
    pub log_stretch: [f64; 5],
    /// Total flight time of the reference trajectory.
    pub time: f64,
    /// Collisions taken.
    pub collisions: u64,
    /// State of the reference trajectory after the last collision.
    pub end: State,
}

impl SpectrumStretch {
    /// The five exponents per unit time, sorted descending.
    pub fn exponents(&self) -> [f64; 5] {
        let mut e = self.log_stretch.map(|l| l / self.time);
        e.sort_by(|a, b| b.total_cmp(a));
        e
    }
}

/// One ball of an escape run: when, where and how it left through a hole,
/// or that it was still inside when the budget ran out (censored).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Escape {
    /// Escape time; for a censored ball, the time it was last seen inside
    /// (the time budget, or the time of its last collision when the
    /// collision budget ran out).
    pub time: f64,
    /// Collisions before the escape (or before the run stopped).
    pub collisions: u64,
    /// Where and how it left (`None`: censored, still inside). `exit.time`
    /// is the last flight only; the escape time is `time`.
    pub exit: Option<Exit>,
}

impl Escape {
    /// Whether the ball was still inside when the budget ran out.
    #[must_use]
    pub fn is_censored(&self) -> bool {
        self.exit.is_none()
    }
}
