//! Why a table could not be built.
//!
//! Every constructor in this crate validates its input and returns one of these
//! variants instead of building a table that would produce NaNs or let a ball out.

use thiserror::Error;

/// An invalid table or wall description.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum GeometryError {
    /// A parameter is NaN or infinite.
    #[error("table parameter `{name}` must be finite, got {value}")]
    NonFinite {
        /// Name of the parameter, as in the constructor.
        name: &'static str,
        /// The offending value.
        value: f64,
    },
    /// A length that must be strictly positive is zero or negative.
    #[error("table parameter `{name}` must be > 0, got {value}")]
    NonPositive {
        /// Name of the parameter, as in the constructor.
        name: &'static str,
        /// The offending value.
        value: f64,
    },
    /// The Sinai obstacle does not fit strictly inside the square.
    #[error("Sinai obstacle radius r = {r} must be smaller than the half-side l = {l}")]
    ObstacleTooLarge {
        /// Obstacle radius.
        r: f64,
        /// Half-side of the square.
        l: f64,
    },
    /// A wall has (numerically) zero length.
    #[error("wall {index} is degenerate (zero length)")]
    DegenerateWall {
        /// Index of the wall in the list given to the constructor.
        index: usize,
    },
    /// An arc sweeps more than a full turn or nothing at all.
    #[error("arc {index} sweep {sweep} must satisfy 0 < |sweep| <= 2*pi")]
    BadSweep {
        /// Index of the wall in the list given to the constructor.
        index: usize,
        /// The sweep angle given.
        sweep: f64,
    },
    /// A table built from walls has fewer walls than it needs.
    #[error("a table needs at least {needed} walls, got {got}")]
    TooFewWalls {
        /// Minimum number of walls.
        needed: usize,
        /// Number of walls given.
        got: usize,
    },
    /// Consecutive walls of a boundary loop do not meet.
    #[error(
        "boundary loop {lp} is open: wall {index} ends at ({x1}, {y1}) but the next starts at ({x2}, {y2})"
    )]
    OpenLoop {
        /// Index of the loop.
        lp: usize,
        /// Index of the wall (within the loop) whose end does not meet the next start.
        index: usize,
        /// End point x.
        x1: f64,
        /// End point y.
        y1: f64,
        /// Next start x.
        x2: f64,
        /// Next start y.
        y2: f64,
    },
    /// The walls enclose no area, or the outer loop is oriented clockwise.
    #[error(
        "boundary loop {lp} must enclose the table counter-clockwise (outer loop) or clockwise (holes); signed area {area}"
    )]
    WrongOrientation {
        /// Index of the loop.
        lp: usize,
        /// Signed area enclosed by the loop (positive = counter-clockwise).
        area: f64,
    },
}

/// Reject NaN and infinities.
pub(crate) fn finite(name: &'static str, value: f64) -> Result<f64, GeometryError> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(GeometryError::NonFinite { name, value })
    }
}

/// Reject NaN, infinities, zero and negative values.
pub(crate) fn positive(name: &'static str, value: f64) -> Result<f64, GeometryError> {
    let value = finite(name, value)?;
    if value > 0.0 {
        Ok(value)
    } else {
        Err(GeometryError::NonPositive { name, value })
    }
}
