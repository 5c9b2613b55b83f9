//! The Bunimovich stadium: the classic chaotic table, and the paper's main
//! subject (flat walls where `Q` is conserved, caps where it jumps).

use std::f64::consts::PI;

use glam::DVec2;

use crate::aabb::Aabb;
use crate::arc::{concave_root, contact};
use crate::boundary::Boundary;
use crate::error::{GeometryError, MAX_STADIUM_A, MIN_LENGTH, length, within};
use crate::hit::Hit;
use crate::positive_part::positive_part;
use crate::shape::Shape;

/// The stadium: flat walls `y = ±1` for `|x| <= a` joined by semicircular caps
/// of radius 1 centred at `(±a, 0)` (paper §II.A; `a = 1` unless scanning).
///
/// Walls, in id order: 0 bottom flat, 1 right cap, 2 top flat, 3 left cap.
/// Birkhoff `s` starts at `(-a, -1)` and runs counter-clockwise: bottom flat
/// `[0, 2a]`, right cap `[2a, 2a + π]`, top flat, left cap; perimeter `4a + 2π`.
///
/// **Junctions** (`x = ±a`, `y = ±1`): the stadium is convex, so a ray leaves it
/// once. The rule is: the flat wall takes the hit if its crossing of `y = ±1`
/// lies within `|x| <= a` (to a tolerance of `64 ε (a + 1)`); otherwise the cap
/// on the side of that crossing (`x > a`: right, `x < -a`: left) does. The
/// tangent is continuous across a junction, so either choice gives the same
/// collision; only the curvature (and hence the tangent map, undefined exactly
/// there) differs.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Stadium {
    a: f64,
    slack: f64,
}

impl Stadium {
    /// A stadium with flat half-length `a` and unit cap radius.
    ///
    /// # Errors
    /// [`GeometryError::NonFinite`] or [`GeometryError::NonPositive`] (`a = 0`
    /// is the circle: use [`Circle`](crate::Circle)); [`GeometryError::OutOfRange`]
    /// outside `[1e-60, 1e8]` ([`MAX_STADIUM_A`]).
    pub fn new(a: f64) -> Result<Self, GeometryError> {
        let a = within(
            "a",
            length("a", a)?,
            MIN_LENGTH,
            MAX_STADIUM_A,
            "the caps have radius 1 and coordinates of size a resolve them only to 2.2e-16 a",
        )?;
        Ok(Stadium {
            a,
            slack: 64.0 * f64::EPSILON * (a + 1.0),
        })
    }

    /// Flat half-length `a`.
    pub fn a(&self) -> f64 {
        self.a
    }
}

impl Boundary for Stadium {
    #[inline]
    fn cast(&self, origin: DVec2, v: DVec2) -> Option<Hit> {
        let a = self.a;
        // Crossing of the line y = ±1 ahead, tested without dividing:
        // |x_cross| <= a  <=>  |x |v_y| + v_x dist| <= a |v_y|.
        let side = if v.y != 0.0 {
            let (dist, wall, y, normal) = if v.y > 0.0 {
                (1.0 - origin.y, 2, 1.0, DVec2::NEG_Y)
            } else {
                (origin.y + 1.0, 0, -1.0, DVec2::Y)
            };
            let dist = positive_part(dist);
            let avy = v.y.abs();
            let x_scaled = origin.x * avy + v.x * dist;
            if x_scaled.abs() <= (a + self.slack) * avy {
                let time = dist / avy;
                let x = (origin.x + v.x * time).clamp(-a, a);
                let s = if wall == 0 { x + a } else { 3.0 * a + PI - x };
                return Some(Hit::new(time, DVec2::new(x, y), normal, 0.0, wall, s));
            }
            x_scaled
        } else if v.x != 0.0 {
            v.x
        } else {
            return None;
        };
        // Through a cap: the one on the side of the crossing.
        let (center, wall, base, from) = if side > 0.0 {
            (DVec2::new(a, 0.0), 1, 2.0 * a, DVec2::NEG_Y)
        } else {
            (DVec2::new(-a, 0.0), 3, 4.0 * a + PI, DVec2::Y)
        };
        // One division for the cap, as for the flat wall: the flight time
        // of the larger root, clamped at 0, divided by |v|².
        let root = concave_root(center, 1.0, origin, v)?;
        let time = positive_part(root.num) / root.a;
        let (point, radial) = contact(center, root.d + v * time, 1.0);
        Some(Hit::on_circle(
            time, point, -radial, -1.0, wall, base, center, from, 1.0, true,
        ))
    }

    fn contains(&self, p: DVec2) -> bool {
        // Along x the coordinates round at ε (a + 1), across (y, the cap
        // radius 1) at ε: each direction gets its own tolerance, so a long
        // stadium does not accept points beyond its flat walls.
        let dx = (p.x.abs() - self.a - self.slack).max(0.0);
        let tol = 1.0 + 64.0 * f64::EPSILON;
        dx * dx + p.y * p.y <= tol * tol
    }

    fn aabb(&self) -> Aabb {
        Aabb::new(
            DVec2::new(-self.a - 1.0, -1.0),
            DVec2::new(self.a + 1.0, 1.0),
        )
    }

    /// 1, the cap radius, whatever `a`.
    fn unit_length(&self) -> f64 {
        1.0
    }
    fn perimeter(&self) -> f64 {
        4.0 * self.a + 2.0 * PI
    }
    fn hit_at(&self, s: f64) -> Option<Hit> {
        let a = self.a;
        let s = crate::hit::wrap_arc_length(s, self.perimeter())?;
        let cap = |center: DVec2, angle: f64, wall| {
            let radial = DVec2::from_angle(angle);
            Hit::new(0.0, center + radial, -radial, -1.0, wall, s)
        };
        Some(if s < 2.0 * a {
            Hit::new(0.0, DVec2::new(s - a, -1.0), DVec2::Y, 0.0, 0, s)
        } else if s < 2.0 * a + PI {
            cap(DVec2::new(a, 0.0), s - 2.0 * a - 0.5 * PI, 1)
        } else if s < 4.0 * a + PI {
            let x = a - (s - 2.0 * a - PI);
            Hit::new(0.0, DVec2::new(x, 1.0), DVec2::NEG_Y, 0.0, 2, s)
        } else {
            cap(DVec2::new(-a, 0.0), s - 4.0 * a - 0.5 * PI, 3)
        })
    }
    /// `4a + π` (unit caps).
    fn area(&self) -> f64 {
        4.0 * self.a + PI
    }
    fn curved_length(&self) -> f64 {
        2.0 * PI
    }
    fn shape(&self) -> Option<Shape> {
        Some(Shape::Stadium { a: self.a })
    }
}
