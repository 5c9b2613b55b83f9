//! Why a spin law, a launch or a step failed.

use glam::DVec2;
use thiserror::Error;

/// An invalid spin parameter α.
#[derive(Debug, Clone, Copy, PartialEq, Error)]
#[non_exhaustive]
pub enum SpinLawError {
    /// α is NaN or infinite.
    #[error("spin parameter alpha must be finite, got {0}")]
    NonFinite(f64),
    /// α < 0 (a negative moment of inertia).
    #[error("spin parameter alpha = I/(m r^2) must be >= 0, got {0}")]
    Negative(f64),
    /// α > 1 through [`SpinLaw::new`](crate::SpinLaw::new): no rigid body has it.
    #[error(
        "alpha = {0} > 1 is outside the physical range [0, 1] (no rigid body has I > m r^2); use SpinLaw::extended to study it as a mathematical extension"
    )]
    Unphysical(f64),
}

/// A state that cannot be launched.
#[derive(Debug, Clone, Copy, PartialEq, Error)]
#[non_exhaustive]
pub enum LaunchError {
    /// A coordinate is NaN or infinite.
    #[error("state component `{0}` is not finite")]
    NonFinite(&'static str),
    /// The ball does not move: it would never reach a wall.
    #[error("the ball is at rest (velocity zero): it never reaches a wall")]
    AtRest,
    /// The position is outside the table.
    #[error("position ({}, {}) is outside the table", .0.x, .0.y)]
    Outside(DVec2),
}

/// A collision step that could not be taken.
#[derive(Debug, Clone, Copy, PartialEq, Error)]
#[non_exhaustive]
pub enum StepError {
    /// No wall lies ahead of the ball (it would fly to infinity). For a ball
    /// inside a bounded table this means it escaped, which is a bug to report.
    #[error("no wall ahead of the ball at ({}, {}) moving ({}, {})", .position.x, .position.y, .velocity.x, .velocity.y)]
    NoWall {
        /// Position at the start of the step.
        position: DVec2,
        /// Velocity at the start of the step.
        velocity: DVec2,
    },
    /// The step produced a non-finite time or state.
    #[error("the step produced a non-finite value at ({}, {})", .position.x, .position.y)]
    NonFinite {
        /// Position at the start of the step.
        position: DVec2,
    },
}
