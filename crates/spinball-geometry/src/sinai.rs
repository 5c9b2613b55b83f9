//! The Sinai billiard: a square box with a convex disk at its centre, the
//! dispersing chaotic table (every collision changes the tangent direction on
//! average, so `Q` never accumulates a constraint for long).

use std::f64::consts::TAU;

use glam::DVec2;

use crate::aabb::Aabb;
use crate::arc::{Root, contact, convex_root};
use crate::boundary::Boundary;
use crate::error::{GeometryError, MIN_SINAI_GAP, MIN_SINAI_RATIO, length, within};
use crate::hit::Hit;
use crate::positive_part::positive_part;
use crate::rectangle::{box_ahead, land_box};
use crate::shape::Shape;

/// The square `[-l, l]²` minus the open disk of radius `r` at the origin
/// (paper §II.A: `l = 2`, `r = 1`; scans over `r`).
///
/// Walls, in id order: 0 bottom, 1 right, 2 top, 3 left (as [`Rectangle`]),
/// 4 the disk (convex, curvature `+1/r`). Birkhoff `s`: the box as for the
/// rectangle (`[0, 8l)`), then the disk from `8l`, starting at `(r, 0)` and
/// running clockwise (the table on the left); perimeter `8l + 2πr`.
///
/// **Corners** of the box are resolved as for the [`Rectangle`]: the two walls
/// in turn, lower id first. A ball that just grazes the disk is reflected by it
/// (the tangential velocity and spin still exchange by the spin law).
///
/// [`Rectangle`]: crate::Rectangle
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Sinai {
    l: f64,
    r: f64,
    slack: f64,
}

impl Sinai {
    /// The box of half-side `l` with a disk of radius `r`.
    ///
    /// # Errors
    /// [`GeometryError::NonFinite`], [`GeometryError::NonPositive`], or
    /// [`GeometryError::ObstacleTooLarge`] if `r >= l` (the disk would touch or
    /// cut the walls and split the table); [`GeometryError::OutOfRange`] for
    /// lengths outside `[1e-60, 1e60]` or `r / l` outside `[1e-6, 1 − 1e-12]`
    /// ([`MIN_SINAI_RATIO`],
    /// [`MIN_SINAI_GAP`]).
    pub fn new(l: f64, r: f64) -> Result<Self, GeometryError> {
        let l = length("l", l)?;
        let r = length("r", r)?;
        if r >= l {
            return Err(GeometryError::ObstacleTooLarge { r, l });
        }
        within(
            "r",
            r,
            MIN_SINAI_RATIO * l,
            l * (1.0 - MIN_SINAI_GAP),
            "r/l must lie in [1e-6, 1 - 1e-12]: a smaller disk drowns in the rounding of |x|^2 ~ l^2, a larger one closes the corners to less than the walls' tolerance",
        )?;
        Ok(Sinai {
            l,
            r,
            slack: 64.0 * f64::EPSILON * l,
        })
    }

    /// Half-side of the box.
    pub fn l(&self) -> f64 {
        self.l
    }
    /// Radius of the obstacle.
    pub fn r(&self) -> f64 {
        self.r
    }
}

impl Boundary for Sinai {
    #[inline]
    /// One division: the box wall ahead (`dist / speed`) and the disk
    /// (`num / |v|²`) are compared cross-multiplied (ties to the box, the
    /// lower ids), and only the winner's fraction is divided.
    fn cast(&self, origin: DVec2, v: DVec2) -> Option<Hit> {
        let ahead = box_ahead(self.l, self.l, origin, v);
        let disk = convex_root(DVec2::ZERO, self.r, origin, v).map(|r| Root {
            num: positive_part(r.num),
            ..r
        });
        let disk_wins = match (disk, ahead) {
            (Some(d), Some(b)) => d.num * b.speed < b.dist * d.a,
            (d, None) => d.is_some(),
            (None, Some(_)) => false,
        };
        if !disk_wins {
            let b = ahead?;
            return land_box(self.l, self.l, origin, v, b.dist / b.speed, b.wall);
        }
        let d = disk?;
        let time = d.num / d.a;
        let (point, radial) = contact(DVec2::ZERO, d.d + v * time, self.r);
        Some(Hit::on_circle(
            time,
            point,
            radial,
            1.0 / self.r,
            4,
            8.0 * self.l,
            DVec2::ZERO,
            DVec2::X,
            self.r,
            false,
        ))
    }

    fn contains(&self, p: DVec2) -> bool {
        p.x.abs() <= self.l + self.slack
            && p.y.abs() <= self.l + self.slack
            && p.length() >= self.r - self.slack
    }

    /// The paper's reference code draws in `shrink` of the box and keeps
    /// points outside `(2 - shrink) r` (1.01 r for shrink 0.99).
    fn contains_shrunk(&self, p: DVec2, shrink: f64) -> bool {
        let m = shrink * self.l;
        p.x.abs() <= m && p.y.abs() <= m && p.length() >= (2.0 - shrink) * self.r
    }

    fn aabb(&self) -> Aabb {
        Aabb::new(DVec2::splat(-self.l), DVec2::splat(self.l))
    }

    /// `l / 2`: 1 for the paper's table (`l = 2`) whatever `r`.
    fn unit_length(&self) -> f64 {
        0.5 * self.l
    }
    fn perimeter(&self) -> f64 {
        8.0 * self.l + TAU * self.r
    }
    fn hit_at(&self, s: f64) -> Option<Hit> {
        let s = crate::hit::wrap_arc_length(s, self.perimeter())?;
        if s < 8.0 * self.l {
            return Some(crate::rectangle::box_hit_at(self.l, self.l, s));
        }
        // Clockwise from (r, 0).
        let radial = DVec2::from_angle(-(s - 8.0 * self.l) / self.r);
        Some(Hit::new(0.0, radial * self.r, radial, 1.0 / self.r, 4, s))
    }
    /// `4L² − πR²`.
    fn area(&self) -> f64 {
        4.0 * self.l * self.l - 0.5 * TAU * self.r * self.r
    }
    fn curved_length(&self) -> f64 {
        TAU * self.r
    }
    fn shape(&self) -> Option<Shape> {
        Some(Shape::Sinai {
            l: self.l,
            r: self.r,
        })
    }
}
