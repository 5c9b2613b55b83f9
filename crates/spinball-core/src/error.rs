//! Why a spin law, a launch or a step failed.

use glam::DVec2;
use thiserror::Error;

use crate::event::Exit;

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
    /// A speed `f64` cannot run: the phase-space speed `|V| = √(|v|² + αu²)`
    /// or the translational speed `|v|` is outside `[MIN_SPEED, MAX_SPEED]`,
    /// where their squares (times a table's squared size) would become
    /// subnormal or overflow.
    #[error(
        "{what} = {value:e} is outside the range f64 can run, [{min:e}, {max:e}] (its square times a table's squared size must stay a normal, finite f64)"
    )]
    Speed {
        /// `speed |V|` or `translational speed |v|`.
        what: &'static str,
        /// The offending speed.
        value: f64,
        /// Smallest accepted speed.
        min: f64,
        /// Largest accepted speed.
        max: f64,
    },
}

/// A finite-difference separation that cannot measure anything on this
/// table and state.
#[derive(Debug, Clone, Copy, PartialEq, Error)]
#[non_exhaustive]
pub enum PerturbationError {
    /// `δ0` is outside the documented range.
    #[error(
        "finite-difference separation delta0 = {delta0:e} is outside [{min:e}, {max:e}] (in units of the table's unit length and the ball's speed): below it rounding (2.2e-16/delta0) swamps the separation, above it the shadow leaves the linear regime"
    )]
    OutOfRange {
        /// The separation asked for.
        delta0: f64,
        /// Smallest accepted.
        min: f64,
        /// Largest accepted.
        max: f64,
    },
    /// The table's coordinates are too large for the position part of the
    /// perturbation (`δ0` times the table's unit length) to be resolved: an
    /// elongated table (thin side tiny against the long one) or one far from
    /// the origin.
    #[error(
        "finite-difference position separation {separation:e} is below 1e4 ulps of the table's coordinates (which reach {extent:e}): f64 cannot resolve it; use the tangent method on this table, or a larger delta0 (the largest accepted is 1e-3)"
    )]
    Unresolved {
        /// `δ0` times the table's unit length (a power of two).
        separation: f64,
        /// Largest coordinate of the table's bounding box.
        extent: f64,
    },
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
    /// The ball is stuck: [`MAX_ZERO_TIME_RUN`](crate::MAX_ZERO_TIME_RUN)
    /// collisions in a row took zero time. This is what a ball started on a
    /// wall and moving along it does when it slides into a curved wall
    /// tangent to it (the stadium's junctions): it stays at the contact
    /// forever. Start it off the wall or not parallel to it.
    #[error(
        "the ball is stuck at ({}, {}) moving ({}, {}): {collisions} collisions in a row took zero time (a ball moving along a wall into a tangent curved wall); start it off the wall or not parallel to it", .position.x, .position.y, .velocity.x, .velocity.y
    )]
    Stuck {
        /// Position at the start of the step.
        position: DVec2,
        /// Velocity at the start of the step.
        velocity: DVec2,
        /// Zero-time collisions in a row.
        collisions: u32,
    },
    /// The step produced a non-finite time or state.
    #[error("the step produced a non-finite value at ({}, {})", .position.x, .position.y)]
    NonFinite {
        /// Position at the start of the step.
        position: DVec2,
    },
    /// The ball reached a hole and left the table before its next
    /// collision (only on a table with holes; use
    /// [`Billiard::advance`](crate::Billiard::advance) to see escapes as
    /// events rather than errors).
    #[error("the ball left the table through hole wall {} at ({}, {})", .0.wall, .0.point.x, .0.point.y)]
    Escaped(Exit),
}

/// A sampler that finds no room in the table: no point of the
/// [`MAX_INTERIOR_DRAWS`](spinball_geometry::MAX_INTERIOR_DRAWS) drawn from
/// its bounding box was inside the region it draws from.
#[derive(Debug, Clone, Copy, PartialEq, Error)]
#[error(
    "the {sampler} sampler found no room in this table: none of {draws} points drawn from its bounding box lay in {region} (the table fills almost none of its box{hint})"
)]
pub struct NoRoom {
    /// `paper` or `microcanonical`.
    pub sampler: &'static str,
    /// What the points had to lie in.
    pub region: &'static str,
    /// How many were drawn.
    pub draws: u64,
    /// What to try instead.
    pub hint: &'static str,
}
