//! What a ray cast returns: where and how the ball meets the wall.
//!
//! A [`Hit`] carries everything the collision law and the tangent map need
//! (flight time, point, inward normal, signed curvature, wall id). The Birkhoff
//! arc length `s` is available through [`Hit::s`]; on curved walls it needs an
//! `atan2`, so it is computed only when asked for (a plain trajectory never
//! pays for it).

use glam::DVec2;

/// Identifier of a wall of a table (its index in the table's wall list).
pub type WallId = u32;

/// How to turn a hit point into the Birkhoff arc length `s`.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub(crate) enum ArcLength {
    /// The arc length is known already.
    Known(f64),
    /// On a circle of `radius` about `center`: `s = base + radius * angle`, the
    /// angle measured from the unit direction `from` (centre to wall start),
    /// counter-clockwise if `ccw`, clockwise otherwise.
    Circle {
        base: f64,
        center: DVec2,
        from: DVec2,
        radius: f64,
        ccw: bool,
    },
}

impl ArcLength {
    #[inline]
    fn eval(self, point: DVec2) -> f64 {
        match self {
            ArcLength::Known(s) => s,
            ArcLength::Circle {
                base,
                center,
                from,
                radius,
                ccw,
            } => {
                let r = point - center;
                let mut angle = from.perp_dot(r).atan2(from.dot(r));
                if !ccw {
                    angle = -angle;
                }
                if angle < 0.0 {
                    angle += std::f64::consts::TAU;
                }
                base + radius * angle
            }
        }
    }
}

/// The next wall hit of a ball in free flight (the answer of [`Boundary::cast`]).
///
/// Conventions ([`docs/PHYSICS.md`](https://github.com/spinball/spinball/blob/main/docs/PHYSICS.md#units-and-conventions), paper §II.B): `normal` is the unit normal pointing
/// **into** the table, the unit tangent is `t = (n_y, -n_x)` so that `t × n = +z`,
/// and the curvature is signed by `dn/ds = k t`: `k = -1/R` on a concave arc
/// (circle table, stadium caps), `+1/R` on a convex obstacle (Sinai disk), `0` on
/// a flat wall.
///
/// [`Boundary::cast`]: crate::Boundary::cast
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Hit {
    /// Flight time from the cast origin to the wall (in units where the cast
    /// velocity is given), `>= 0`.
    pub time: f64,
    /// Point of contact, on the wall.
    pub point: DVec2,
    /// Unit normal at the contact, pointing into the table.
    pub normal: DVec2,
    /// Signed curvature `k` of the wall at the contact.
    pub curvature: f64,
    /// Which wall was hit.
    pub wall: WallId,
    pub(crate) arc: ArcLength,
}

impl Hit {
    /// Build a hit on a wall whose arc length at the contact is already known.
    #[inline]
    pub fn new(
        time: f64,
        point: DVec2,
        normal: DVec2,
        curvature: f64,
        wall: WallId,
        s: f64,
    ) -> Self {
        Hit {
            time,
            point,
            normal,
            curvature,
            wall,
            arc: ArcLength::Known(s),
        }
    }

    /// Build a hit on a circular wall; the arc length is evaluated lazily as
    /// `base + radius * angle`, the angle measured from the unit direction `from`
    /// (centre to the point where `s = base`), counter-clockwise if `ccw`.
    #[inline]
    #[allow(clippy::too_many_arguments)]
    pub fn on_circle(
        time: f64,
        point: DVec2,
        normal: DVec2,
        curvature: f64,
        wall: WallId,
        base: f64,
        center: DVec2,
        from: DVec2,
        radius: f64,
        ccw: bool,
    ) -> Self {
        Hit {
            time,
            point,
            normal,
            curvature,
            wall,
            arc: ArcLength::Circle {
                base,
                center,
                from,
                radius,
                ccw,
            },
        }
    }

    /// Unit tangent `t = (n_y, -n_x)`, so that `t × n = +z` (paper, below eq. 3).
    #[inline]
    pub fn tangent(&self) -> DVec2 {
        tangent_of(self.normal)
    }

    /// Birkhoff arc length `s` of the contact point, in the table's documented
    /// parametrisation (each table's docs say where `s = 0` is and which way it
    /// runs). Costs an `atan2` on curved walls.
    #[inline]
    pub fn s(&self) -> f64 {
        self.arc.eval(self.point)
    }

    /// Whether the wall is curved at the contact.
    #[inline]
    pub fn is_curved(&self) -> bool {
        self.curvature != 0.0
    }
}

/// The tangent that goes with an inward normal: `t = (n_y, -n_x)`, `t × n = +z`.
#[inline]
pub fn tangent_of(normal: DVec2) -> DVec2 {
    DVec2::new(normal.y, -normal.x)
}

/// `s` taken into `[0, perimeter)` (`None` for a non-finite `s` or a
/// perimeter that is not positive and finite).
#[inline]
pub(crate) fn wrap_arc_length(s: f64, perimeter: f64) -> Option<f64> {
    if !(s.is_finite() && perimeter.is_finite() && perimeter > 0.0) {
        return None;
    }
    let w = s.rem_euclid(perimeter);
    // rem_euclid of a tiny negative s rounds up to the perimeter itself.
    Some(if w >= perimeter { 0.0 } else { w })
}
