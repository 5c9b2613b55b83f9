//! A largest-exponent trajectory stopped after a run, ready to go on.
//!
//! A multilevel ensemble reads each trajectory at several run lengths
//! `T_0 < T_1 < …`. The kernels keep a trajectory's whole state in
//! registers and return only its end, so without a way to stop and go on a
//! caller reruns the trajectory from its start once per length it reads. A
//! [`Paused`] is everything a kernel holds for one trajectory at the end of
//! a run — the reference state, the partner (finite-difference shadow or
//! tangent vector), the launch state whose energy shell every step restores,
//! the running product of stretches, the flight time and the current run of
//! zero-time collisions — so [`LaneBilliard::resume`] continues it exactly
//! where it stopped: `T_0` then `T_1 − T_0` more collisions is bitwise one run
//! of `T_1`. (One exception, outside the dynamics: at α = 0 the spin
//! component of an exact tangent vector takes no part in the motion and is
//! shrunk by the renormalisations into subnormal numbers, where its low
//! bits depend on where the run was renormalised; neither the other
//! components nor the stretch do.)
//!
//! [`LaneBilliard::resume`]: crate::LaneBilliard::resume

use spinball_core::{State, TangentVector};

use crate::outcome::Stretch;

/// Which kernel a [`Paused`] trajectory runs on, and what that kernel needs
/// besides the state.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub(crate) enum Partner {
    /// The finite-difference shadow, launched `delta0` away (in units).
    Shadow {
        /// The initial separation in units.
        delta0: f64,
    },
    /// An exact tangent vector.
    Tangent {
        /// Length of the starting vector in units: the growth is measured
        /// against it.
        from: f64,
    },
}

/// One trajectory of [`LaneBilliard::start_fd`] or
/// [`LaneBilliard::start_tangent`] stopped after some collisions: its
/// largest-exponent sums so far ([`stretch`](Self::stretch)) and what
/// [`LaneBilliard::resume`] needs to continue it bitwise as if it had never
/// stopped.
///
/// [`LaneBilliard::start_fd`]: crate::LaneBilliard::start_fd
/// [`LaneBilliard::start_tangent`]: crate::LaneBilliard::start_tangent
/// [`LaneBilliard::resume`]: crate::LaneBilliard::resume
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Paused {
    /// The state the trajectory was launched from (its energy shell, and
    /// the units the separation is measured in).
    pub(crate) launch: State,
    /// The reference trajectory now.
    pub(crate) reference: State,
    /// The shadow's state, or the tangent vector (scaled by a power of two).
    pub(crate) partner: [f64; 5],
    /// Which kernel, and its constants.
    pub(crate) kind: Partner,
    /// Finite differences: the product of stretches is
    /// `log_mantissa · 2^log_exponent`; tangent: the vector's growth is its
    /// length times `2^log_exponent` (and `log_mantissa` is 1).
    pub(crate) log_mantissa: f64,
    pub(crate) log_exponent: i64,
    /// `Σ ln(stretch)` so far (NaN if a lane went non-finite).
    pub(crate) log_stretch: f64,
    /// Flight time so far.
    pub(crate) time: f64,
    /// Zero-time collisions in a row just before the stop.
    pub(crate) zero_run: f64,
    /// Collisions so far.
    pub(crate) collisions: u64,
}

impl Paused {
    /// A trajectory before its first collision.
    pub(crate) fn launched(start: State, partner: [f64; 5], kind: Partner) -> Self {
        Paused {
            launch: start,
            reference: start,
            partner,
            kind,
            log_mantissa: 1.0,
            log_exponent: 0,
            log_stretch: 0.0,
            time: 0.0,
            zero_run: 0.0,
            collisions: 0,
        }
    }

    /// The largest-exponent sums of the run so far (all zero before the
    /// first collision).
    #[must_use]
    pub fn stretch(&self) -> Stretch {
        Stretch {
            log_stretch: self.log_stretch,
            time: self.time,
            collisions: self.collisions,
            end: self.reference,
        }
    }

    /// Collisions taken so far.
    #[must_use]
    pub fn collisions(&self) -> u64 {
        self.collisions
    }

    /// The state the trajectory was launched from.
    #[must_use]
    pub fn launch(&self) -> State {
        self.launch
    }

    /// The partner now: the finite-difference shadow's state
    /// `(x, y, v_x, v_y, u)`, or the tangent vector (scaled by a power of
    /// two; its length in units is the growth so far divided by
    /// `2^log_exponent`).
    #[must_use]
    pub fn partner(&self) -> [f64; 5] {
        self.partner
    }

    /// The partner as a tangent vector (the shadow's state for finite
    /// differences).
    pub(crate) fn partner_vector(&self) -> TangentVector {
        TangentVector::from_array(self.partner)
    }

    /// Tangent method: the starting vector's length in units (NaN for a
    /// finite-difference trajectory, which `resume` never runs on the
    /// tangent kernel).
    pub(crate) fn tangent_from(&self) -> f64 {
        match self.kind {
            Partner::Tangent { from } => from,
            Partner::Shadow { .. } => f64::NAN,
        }
    }

    /// Whether the sums so far are sound (finite throughout).
    pub(crate) fn is_sound(&self) -> bool {
        self.log_stretch.is_finite()
            && self.time.is_finite()
            && self.reference.to_array().iter().all(|x| x.is_finite())
    }
}
