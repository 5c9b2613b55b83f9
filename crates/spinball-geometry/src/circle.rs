//! The circle table: the integrable reference case.
//!
//! A ball in a disk keeps its angular momentum about the centre and its angle of
//! incidence; with spin the (v∥, u) map is an involution
//! ([`docs/PHYSICS.md`](https://github.com/spinball/spinball/blob/main/docs/PHYSICS.md#half-turn-form)), so the
//! motion stays regular for every α.

use std::f64::consts::TAU;

use glam::DVec2;

use crate::aabb::Aabb;
use crate::arc::cast_concave_circle;
use crate::boundary::Boundary;
use crate::error::{GeometryError, length};
use crate::hit::Hit;
use crate::shape::Shape;

/// The disk `x² + y² <= R²` (paper §II.A: `R = 1`).
///
/// One wall (id 0), concave, curvature `-1/R`. Birkhoff `s = R θ`, with θ the
/// polar angle of the contact measured counter-clockwise from +x, in `[0, 2πR)`.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Circle {
    radius: f64,
}

impl Circle {
    /// A disk of the given radius centred at the origin.
    ///
    /// # Errors
    /// [`GeometryError::NonFinite`], [`GeometryError::NonPositive`], or
    /// [`GeometryError::OutOfRange`] outside
    /// `[MIN_LENGTH, MAX_LENGTH]` = `[1e-60, 1e60]` (see [`crate::error::MAX_LENGTH`]).
    pub fn new(radius: f64) -> Result<Self, GeometryError> {
        Ok(Circle {
            radius: length("radius", radius)?,
        })
    }

    /// The paper's unit disk.
    pub fn unit() -> Self {
        Circle { radius: 1.0 }
    }

    /// Radius.
    pub fn radius(&self) -> f64 {
        self.radius
    }
}

impl Boundary for Circle {
    #[inline]
    fn cast(&self, origin: DVec2, velocity: DVec2) -> Option<Hit> {
        let w = cast_concave_circle(DVec2::ZERO, self.radius, origin, velocity)?;
        Some(Hit::on_circle(
            w.time,
            w.point,
            w.normal,
            -1.0 / self.radius,
            0,
            0.0,
            DVec2::ZERO,
            DVec2::X,
            self.radius,
            true,
        ))
    }

    fn contains(&self, p: DVec2) -> bool {
        p.length() <= self.radius * (1.0 + 1e-12)
    }

    fn aabb(&self) -> Aabb {
        Aabb::new(DVec2::splat(-self.radius), DVec2::splat(self.radius))
    }

    /// The radius.
    fn unit_length(&self) -> f64 {
        self.radius
    }
    fn perimeter(&self) -> f64 {
        TAU * self.radius
    }
    fn hit_at(&self, s: f64) -> Option<Hit> {
        let s = crate::hit::wrap_arc_length(s, self.perimeter())?;
        let radial = DVec2::from_angle(s / self.radius);
        Some(Hit::new(
            0.0,
            radial * self.radius,
            -radial,
            -1.0 / self.radius,
            0,
            s,
        ))
    }
    fn area(&self) -> f64 {
        0.5 * TAU * self.radius * self.radius
    }
    fn curved_length(&self) -> f64 {
        TAU * self.radius
    }
    fn shape(&self) -> Option<Shape> {
        Some(Shape::Circle {
            radius: self.radius,
        })
    }
}
