//! The rectangle table: integrable without spin, the flat-wall case of the
//! conserved quantity `Q = v∥ - αu`.

use glam::DVec2;

use crate::aabb::Aabb;
use crate::boundary::Boundary;
use crate::error::{GeometryError, length};
use crate::hit::{Hit, WallId};
use crate::positive_part::positive_part;
use crate::shape::Shape;

/// The rectangle `[-l, l] × [-h, h]` (paper §II.A: `l = h = 1` for Lyapunov
/// runs, `l = 1.5, h = 1` for pictures).
///
/// Walls, in id order: 0 bottom (`y = -h`), 1 right (`x = l`), 2 top (`y = h`),
/// 3 left (`x = -l`). Birkhoff `s` starts at the corner `(-l, -h)` and runs
/// counter-clockwise; perimeter `4(l + h)`.
///
/// **Corners**: a ball that reaches a corner is reflected by the two walls in
/// turn, the lower wall id first (ties in [`Boundary::cast`] go to the lower
/// id); the second collision has zero flight time. This is the limit of hits
/// just beside the corner, and for α = 0 it reverses the velocity, as a corner
/// of a rectangle does.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Rectangle {
    l: f64,
    h: f64,
}

/// Relative tolerance of [`Rectangle::contains`] on each axis: the walls'
/// rounding, `64 ε` of the half-side on that axis (the thin side sets its own
/// tolerance).
const CONTAINS_SLACK: f64 = 64.0 * f64::EPSILON;

impl Rectangle {
    /// The rectangle of half-width `l` and half-height `h`.
    ///
    /// # Errors
    /// [`GeometryError::NonFinite`], [`GeometryError::NonPositive`], or
    /// [`GeometryError::OutOfRange`] for a side outside `[1e-60, 1e60]`.
    pub fn new(l: f64, h: f64) -> Result<Self, GeometryError> {
        let l = length("l", l)?;
        let h = length("h", h)?;
        Ok(Rectangle { l, h })
    }

    /// The unit square `[-1, 1]²` used for the paper's Lyapunov runs.
    pub fn square() -> Self {
        Rectangle::new(1.0, 1.0).expect("valid")
    }

    /// Half-width.
    pub fn l(&self) -> f64 {
        self.l
    }
    /// Half-height.
    pub fn h(&self) -> f64 {
        self.h
    }
}

/// The next hit on the walls of the box `[-l, l] × [-h, h]`, wall ids 0..=3 as
/// in [`Rectangle`]. Shared with [`Sinai`](crate::Sinai).
#[inline]
pub(crate) fn cast_box(l: f64, h: f64, origin: DVec2, v: DVec2) -> Option<Hit> {
    let ahead = box_ahead(l, h, origin, v)?;
    land_box(l, h, origin, v, ahead.dist / ahead.speed, ahead.wall)
}

/// The wall of the box a ball meets first, and its flight time as the
/// undivided fraction `dist / speed`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct BoxAhead {
    pub dist: f64,
    pub speed: f64,
    pub wall: WallId,
}

/// The box wall ahead of a ball, without dividing: the horizontal wall ahead
/// (bottom = 0 or top = 2) and the vertical one (right = 1 or left = 3) are
/// compared by cross multiplication, `dy/|v_y|` against `dx/|v_x|`, ties to
/// the lower id. `None` for a ball at rest.
#[inline]
pub(crate) fn box_ahead(l: f64, h: f64, origin: DVec2, v: DVec2) -> Option<BoxAhead> {
    let (dy, wall_y) = if v.y > 0.0 {
        (h - origin.y, 2)
    } else {
        (origin.y + h, 0)
    };
    let (dx, wall_x) = if v.x > 0.0 {
        (l - origin.x, 1)
    } else {
        (origin.x + l, 3)
    };
    let (dy, dx) = (positive_part(dy), positive_part(dx));
    let (avy, avx) = (v.y.abs(), v.x.abs());
    let (ty, tx) = (dy * avx, dx * avy);
    let use_y = avy > 0.0 && (avx == 0.0 || ty < tx || (ty == tx && wall_y < wall_x));
    if use_y {
        Some(BoxAhead {
            dist: dy,
            speed: avy,
            wall: wall_y,
        })
    } else if avx > 0.0 {
        Some(BoxAhead {
            dist: dx,
            speed: avx,
            wall: wall_x,
        })
    } else {
        None
    }
}

/// The hit on box wall `wall` after flying for `time` (`None` if the time
/// is not finite).
#[inline]
pub(crate) fn land_box(
    l: f64,
    h: f64,
    origin: DVec2,
    v: DVec2,
    time: f64,
    wall: WallId,
) -> Option<Hit> {
    if !time.is_finite() {
        return None;
    }
    let time = positive_part(time);
    let p = origin + v * time;
    Some(box_hit(l, h, time, p, wall))
}

/// The hit on the box `[-l, l] × [-h, h]` at arc length `s` (flight time 0).
/// Shared with [`Sinai`](crate::Sinai).
pub(crate) fn box_hit_at(l: f64, h: f64, s: f64) -> Hit {
    let (p, wall) = if s < 2.0 * l {
        (DVec2::new(s - l, -h), 0)
    } else if s < 2.0 * (l + h) {
        (DVec2::new(l, s - 2.0 * l - h), 1)
    } else if s < 4.0 * l + 2.0 * h {
        (DVec2::new(l - (s - 2.0 * l - 2.0 * h), h), 2)
    } else {
        (DVec2::new(-l, h - (s - 4.0 * l - 2.0 * h)), 3)
    };
    let mut hit = box_hit(l, h, 0.0, p, wall);
    // Keep the exact s asked for (the snapped point recomputes it to rounding).
    hit.arc = crate::hit::ArcLength::Known(s);
    hit
}

/// Snap a contact onto box wall `wall` and fill in normal and arc length.
#[inline]
fn box_hit(l: f64, h: f64, time: f64, p: DVec2, wall: WallId) -> Hit {
    let (point, normal, s) = match wall {
        0 => {
            let x = p.x.clamp(-l, l);
            (DVec2::new(x, -h), DVec2::Y, x + l)
        }
        1 => {
            let y = p.y.clamp(-h, h);
            (DVec2::new(l, y), DVec2::NEG_X, 2.0 * l + y + h)
        }
        2 => {
            let x = p.x.clamp(-l, l);
            (DVec2::new(x, h), DVec2::NEG_Y, 2.0 * l + 2.0 * h + (l - x))
        }
        _ => {
            let y = p.y.clamp(-h, h);
            (DVec2::new(-l, y), DVec2::X, 4.0 * l + 2.0 * h + (h - y))
        }
    };
    Hit::new(time, point, normal, 0.0, wall, s)
}

impl Boundary for Rectangle {
    #[inline]
    fn cast(&self, origin: DVec2, velocity: DVec2) -> Option<Hit> {
        cast_box(self.l, self.h, origin, velocity)
    }

    fn contains(&self, p: DVec2) -> bool {
        p.x.abs() <= self.l * (1.0 + CONTAINS_SLACK) && p.y.abs() <= self.h * (1.0 + CONTAINS_SLACK)
    }

    fn aabb(&self) -> Aabb {
        Aabb::new(DVec2::new(-self.l, -self.h), DVec2::new(self.l, self.h))
    }

    fn perimeter(&self) -> f64 {
        4.0 * (self.l + self.h)
    }
    fn hit_at(&self, s: f64) -> Option<Hit> {
        let s = crate::hit::wrap_arc_length(s, self.perimeter())?;
        Some(box_hit_at(self.l, self.h, s))
    }
    /// `min(l, h)`: the thin side (1 for the paper's squares and 1.5 × 1 box).
    fn unit_length(&self) -> f64 {
        self.l.min(self.h)
    }
    fn area(&self) -> f64 {
        4.0 * self.l * self.h
    }
    fn curved_length(&self) -> f64 {
        0.0
    }
    fn shape(&self) -> Option<Shape> {
        Some(Shape::Rectangle {
            l: self.l,
            h: self.h,
        })
    }
}
