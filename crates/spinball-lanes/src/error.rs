//! Why a lane run could not start or finish.
//!
//! One error type for the public API. It sits above [`isa`](crate::isa),
//! whose own [`IsaError`] converts into it.

use spinball_core::{LaunchError, PerturbationError};
use thiserror::Error;

use crate::isa::{Isa, IsaError};

/// A lane run that could not start or finish.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum LanesError {
    /// The instruction set asked for is not supported by this CPU.
    #[error("{}", IsaError::Unavailable(*.0))]
    IsaUnavailable(Isa),
    /// An option or input is out of range.
    #[error("invalid option `{name}`: {reason}")]
    InvalidOption {
        /// Name of the option.
        name: &'static str,
        /// What is wrong with it.
        reason: String,
    },
    /// An initial state could not be launched (as `Billiard::launch`).
    #[error("initial condition {index}: {source}")]
    Launch {
        /// Position of the initial condition in the input slice.
        index: usize,
        /// The launch error.
        source: LaunchError,
    },
    /// The finite-difference perturbation cannot measure anything for this
    /// initial condition (as `spinball_core::Perturbation::new`).
    #[error("initial condition {index}: {source}")]
    Perturbation {
        /// Position of the initial condition in the input slice.
        index: usize,
        /// Why.
        source: PerturbationError,
    },
    /// The table has no lane form ([`Boundary::shape`] is `None`): run it on
    /// the scalar path.
    ///
    /// [`Boundary::shape`]: spinball_geometry::Boundary::shape
    #[error(
        "the table has no lane form (its Boundary::shape() is None); run it on the scalar path"
    )]
    NoLaneForm,
    /// The table has holes or periodic walls: the λ kernels only run
    /// closed tables (every wall reflecting), and escape
    /// ([`LaneBilliard::escape_times`](crate::LaneBilliard::escape_times))
    /// runs tables with holes but not periodic walls. Run it on the scalar
    /// path.
    #[error(
        "the table has holes or periodic walls, which the lane kernels of λ and trajectories do not run (escape from holes runs in lanes: LaneBilliard::new_open); run it on the scalar path"
    )]
    OpenTable,
    /// The escape kernel runs tables built from segments (a
    /// `SegmentTable`, the only tables with holes) whose walls reflect or
    /// are holes; this table is a built-in one or has periodic walls.
    #[error(
        "escape runs in lanes on tables built from segments whose walls reflect or are holes, not on {shape}; run it on the scalar path"
    )]
    NoEscapeForm {
        /// The table, as its shape prints.
        shape: String,
    },
    /// A trajectory (or its shadow or tangent vectors) became non-finite: no
    /// wall ahead, a shadow separation of zero, a vector that collapsed, or
    /// the ball got stuck (more than `spinball_core::MAX_ZERO_TIME_RUN`
    /// zero-time collisions in a row).
    /// Where the scalar path fails it fails too; run that initial condition
    /// through the scalar path for the exact step and reason.
    #[error(
        "initial condition {index}: the trajectory, its shadow or its tangent vectors became non-finite (run it through the scalar path for the failing step)"
    )]
    NonFinite {
        /// Position of the initial condition in the input slice.
        index: usize,
    },
}

impl LanesError {
    /// Shorthand for [`LanesError::InvalidOption`].
    pub fn invalid(name: &'static str, reason: impl Into<String>) -> Self {
        LanesError::InvalidOption {
            name,
            reason: reason.into(),
        }
    }
}

impl From<IsaError> for LanesError {
    fn from(e: IsaError) -> Self {
        match e {
            IsaError::Unavailable(isa) => LanesError::IsaUnavailable(isa),
            e @ IsaError::Unknown(_) => LanesError::invalid("isa", e.to_string()),
        }
    }
}
