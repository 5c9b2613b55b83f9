//! Circular walls, concave (the ball inside the circle) or convex (the ball
//! outside, an obstacle).
//!
//! Curved walls are where billiards become chaotic: a concave arc focuses, a
//! convex one defocuses. An [`ArcSegment`] is described by its centre, radius,
//! start angle and a signed sweep: a positive (counter-clockwise) sweep makes a
//! concave wall, a negative (clockwise) sweep a convex one, so that in both
//! cases the table lies to the left of the direction of travel.

use std::f64::consts::TAU;

use glam::DVec2;

use crate::error::{GeometryError, coordinate, finite, length};
use crate::line::{Approach, WallHit};
use crate::positive_part::positive_part;

/// A circular wall. See the [module docs](self) for the orientation rule.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ArcSegment {
    center: DVec2,
    radius: f64,
    start_angle: f64,
    sweep: f64,
    /// Unit direction from the centre to the start point.
    from: DVec2,
    /// Chord from the start point to the end point and the side of it the arc
    /// lies on (`side * chord.perp_dot(p - start) >= 0` on the arc).
    chord: DVec2,
    side: f64,
    full: bool,
}

impl ArcSegment {
    /// An arc of `radius` about `center`, starting at angle `start_angle`
    /// (radians from +x) and sweeping `sweep` radians: `sweep > 0` runs
    /// counter-clockwise and makes a **concave** wall (table inside the
    /// circle), `sweep < 0` runs clockwise and makes a **convex** wall.
    ///
    /// # Errors
    /// [`GeometryError::NonFinite`], [`GeometryError::NonPositive`] for the
    /// radius, [`GeometryError::OutOfRange`] for a radius outside
    /// `[1e-60, 1e60]` or a centre coordinate beyond `±1e60`, [`GeometryError::BadSweep`] unless `0 < |sweep| <= 2π`.
    pub fn new(
        center: DVec2,
        radius: f64,
        start_angle: f64,
        sweep: f64,
    ) -> Result<Self, GeometryError> {
        coordinate("center.x", center.x)?;
        coordinate("center.y", center.y)?;
        let radius = length("radius", radius)?;
        finite("start_angle", start_angle)?;
        finite("sweep", sweep)?;
        if !(sweep != 0.0 && sweep.abs() <= TAU * (1.0 + 1e-12)) {
            return Err(GeometryError::BadSweep { index: 0, sweep });
        }
        let full = sweep.abs() >= TAU * (1.0 - 1e-12);
        let from = DVec2::from_angle(start_angle);
        let to = DVec2::from_angle(start_angle + sweep);
        let chord = square_up((to - from) * radius);
        // Going counter-clockwise about the centre the arc lies to the right
        // of its chord (start to end), clockwise to the left, whatever the
        // sweep. (This used to be the sign of `chord × (mid − start)`: the
        // same ±1 wherever that cross product is resolved, but noise for an
        // arc whose sagitta is below the rounding of its radius, which then
        // covered the far side of its circle.)
        let side = -sweep.signum();
        Ok(ArcSegment {
            center,
            radius,
            start_angle,
            sweep,
            from,
            chord,
            side,
            full,
        })
    }

    /// A full concave circle (the ball inside), starting at angle 0.
    pub fn full_circle(center: DVec2, radius: f64) -> Result<Self, GeometryError> {
        Self::new(center, radius, 0.0, TAU)
    }

    /// Centre of the circle.
    pub fn center(&self) -> DVec2 {
        self.center
    }
    /// Radius of the circle.
    pub fn radius(&self) -> f64 {
        self.radius
    }
    /// Start angle (radians from +x).
    pub fn start_angle(&self) -> f64 {
        self.start_angle
    }
    /// Signed sweep (radians); positive = concave.
    pub fn sweep(&self) -> f64 {
        self.sweep
    }
    /// Whether the table lies inside the circle.
    pub fn is_concave(&self) -> bool {
        self.sweep > 0.0
    }
    /// Signed curvature: `-1/R` concave, `+1/R` convex.
    pub fn curvature(&self) -> f64 {
        if self.is_concave() {
            -1.0 / self.radius
        } else {
            1.0 / self.radius
        }
    }
    /// Arc length.
    pub fn length(&self) -> f64 {
        self.radius * self.sweep.abs()
    }
    /// Start point.
    pub fn start(&self) -> DVec2 {
        self.center + self.from * self.radius
    }
    /// End point.
    pub fn end(&self) -> DVec2 {
        self.center + DVec2::from_angle(self.start_angle + self.sweep) * self.radius
    }
    /// Unit direction from the centre to the start point.
    pub fn start_direction(&self) -> DVec2 {
        self.from
    }
    /// The chord from the start point to the end point, as the test of
    /// whether a contact lies on the arc uses it: a component within `4ε`
    /// of the chord's length is exactly zero (an arc whose ends are
    /// computed from `cos` and `sin` of angles such as `±π/2` and `π` has
    /// its chord exactly along the axis the angles put it on).
    #[must_use]
    pub fn chord(&self) -> DVec2 {
        self.chord
    }
    /// The side of the [`chord`](Self::chord) the arc lies on: `+1` if it
    /// lies to the left of the chord's direction, `-1` if to the right.
    #[must_use]
    pub fn chord_side(&self) -> f64 {
        self.side
    }
    /// Whether the arc is a full circle (a sweep within `1e-12` of `2π`):
    /// it then covers every contact.
    #[must_use]
    pub fn is_full(&self) -> bool {
        self.full
    }

    /// The sagitta: how far the arc's middle lies from its chord,
    /// `R (1 − cos(θ/2)) = 2 R sin²(θ/4)` for a sweep `θ` (computed in the
    /// second form, which does not cancel for a nearly flat arc).
    #[must_use]
    pub fn sagitta(&self) -> f64 {
        let q = (0.25 * self.sweep).sin();
        2.0 * self.radius * q * q
    }

    /// Whether the direction `angle` (radians from +x, seen from the
    /// centre) lies within the arc's sweep, decided on the angles given to
    /// the constructor; `None` within `tol` radians of either end, where
    /// the answer is rounding.
    pub(crate) fn spans_angle(&self, angle: f64, tol: f64) -> Option<bool> {
        if self.full {
            return Some(true);
        }
        // How far along the sweep (in its own direction) the angle lies.
        let u = ((angle - self.start_angle) * self.sweep.signum()).rem_euclid(TAU);
        let span = self.sweep.abs();
        let near = |x: f64, y: f64| (x - y).abs() <= tol;
        if near(u, 0.0) || near(u, TAU) || near(u, span) {
            None
        } else {
            Some(u < span)
        }
    }

    /// Whether a point on the circle lies on this arc (ends included, within
    /// `slack`).
    #[inline]
    pub fn covers(&self, p: DVec2, slack: f64) -> bool {
        self.full
            || self.side * self.chord.perp_dot(p - self.start()) >= -slack * self.chord.length()
    }

    /// Where a ball at `origin` with velocity `velocity` meets this arc from
    /// the table side, if it does. `along` of the result is left at 0 (the arc
    /// length needs an `atan2`; see [`Hit::s`](crate::Hit::s)).
    ///
    /// [`approach`](Self::approach), one division, then
    /// [`land`](Self::land).
    #[inline]
    pub fn cast(&self, origin: DVec2, velocity: DVec2, slack: f64) -> Option<WallHit> {
        let a = self.approach(origin, velocity, slack)?;
        let time = a.dist / a.speed;
        let (point, normal) = self.land(origin, velocity, time);
        Some(WallHit {
            time,
            point,
            normal,
            along: 0.0,
        })
    }

    /// Whether and how soon a ball at `origin` with velocity `velocity`
    /// meets this arc from the table side, without dividing: the flight
    /// time is the fraction [`Approach::dist`]` / `[`Approach::speed`], here
    /// the circle root `t·|v|²` (clamped at 0) over `|v|²`. Every arc of a
    /// table shares the denominator, so arcs compare by their numerators.
    ///
    /// The circle root is the exit for a concave arc (the larger root) and
    /// the entry for a convex one (the smaller root, moving towards the
    /// circle). A root behind the ball counts (as flight time 0) only for a
    /// ball on the circle to rounding (`|d|² − R²` within `128 ε R²` on the
    /// arc's side); a ball clear of the circle whose root is behind it does
    /// not meet the arc. The contact must then lie on the arc: on the arc's
    /// side of its chord, within `slack` (times the chord's length), tested
    /// on the unsnapped contact relative to the centre, `d + v·t`,
    /// multiplied through by `|v|²`:
    /// `side · chord × (d|v|² + v·t|v|²) ≥ (−slack·|chord| − lift)·|v|²`,
    /// where `lift = side · chord × (centre − start)` moves the chord's
    /// line through the centre.
    #[inline]
    #[must_use]
    pub fn approach(&self, origin: DVec2, velocity: DVec2, slack: f64) -> Option<Approach> {
        let touch = touch(self.radius);
        let root = if self.is_concave() {
            let r = concave_root(self.center, self.radius, origin, velocity)?;
            (r.num >= 0.0 || r.c <= touch).then_some(r)?
        } else {
            let r = convex_root(self.center, self.radius, origin, velocity)?;
            (r.num >= 0.0 || r.c >= -touch).then_some(r)?
        };
        let num = positive_part(root.num);
        if !self.full {
            let q = root.d * root.a + velocity * num;
            let lift = self.side * self.chord.perp_dot(self.center - self.start());
            let floor = (-slack * self.chord.length() - lift) * root.a;
            if !(self.side * self.chord.perp_dot(q) >= floor) {
                return None;
            }
        }
        Some(Approach {
            dist: num,
            speed: root.a,
        })
    }

    /// The contact of a ball at `origin` with velocity `velocity` after
    /// flying for `time` (an [`approach`](Self::approach)'s fraction,
    /// divided): the point snapped onto the circle and the unit normal
    /// pointing into the table.
    #[inline]
    #[must_use]
    pub fn land(&self, origin: DVec2, velocity: DVec2, time: f64) -> (DVec2, DVec2) {
        let (point, radial) = contact(
            self.center,
            (origin - self.center) + velocity * time,
            self.radius,
        );
        if self.is_concave() {
            (point, -radial)
        } else {
            (point, radial)
        }
    }
}

/// `chord` with a component that is rounding against the other (within
/// `4ε` of the chord's length) set to exactly zero: the chord of an arc
/// whose ends lie on a line along an axis is along that axis, not tilted by
/// the rounding of `cos` and `sin` (which would cost every cast of it a
/// product of the other component).
fn square_up(chord: DVec2) -> DVec2 {
    let tiny = 4.0 * f64::EPSILON * chord.length();
    let snap = |c: f64| if c.abs() <= tiny { 0.0 } else { c };
    DVec2::new(snap(chord.x), snap(chord.y))
}

/// Below this `|d|² − R²` a ball counts as on the circle of radius `r`
/// (rounding): a concave cast then clamps `disc` at 0, and an arc accepts a
/// root behind the ball as flight time 0.
#[inline]
pub(crate) fn touch(r: f64) -> f64 {
    128.0 * f64::EPSILON * r * r
}

/// The ball inside the circle `|x - c| = R`: where it leaves through the
/// circle (the larger root). Flight time clamped at 0, contact snapped onto the
/// circle, normal pointing to the centre.
#[inline]
pub fn cast_concave_circle(
    center: DVec2,
    radius: f64,
    origin: DVec2,
    velocity: DVec2,
) -> Option<WallHit> {
    let root = concave_root(center, radius, origin, velocity)?;
    let mut hit = root.land(center, radius, velocity);
    hit.normal = -hit.normal;
    Some(hit)
}

/// A circle root as an undivided fraction: the flight time is `num / a`
/// (before clamping at 0), with `d` the ball's offset from the centre.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Root {
    pub num: f64,
    pub a: f64,
    pub d: DVec2,
    /// `|d|² − R²`: how far off the circle the ball is.
    pub c: f64,
}

impl Root {
    /// The hit of a circle cast: flight time `num · (1/a)` clamped at 0
    /// (`1/a` only needs the velocity, so it is computed while the square
    /// root is still running), contact snapped onto the circle, normal the
    /// outward radial direction (a concave cast negates it).
    #[inline]
    fn land(&self, center: DVec2, radius: f64, velocity: DVec2) -> WallHit {
        let inv_a = 1.0 / self.a;
        let time = positive_part(self.num * inv_a);
        let (point, radial) = contact(center, self.d + velocity * time, radius);
        WallHit {
            time,
            point,
            normal: radial,
            along: 0.0,
        }
    }
}

/// The larger root of `|d + v t| = R` for a ball inside the circle, if it
/// leaves through it (see [`cast_concave_circle`]), undivided.
#[inline]
pub(crate) fn concave_root(
    center: DVec2,
    radius: f64,
    origin: DVec2,
    velocity: DVec2,
) -> Option<Root> {
    let d = origin - center;
    let a = velocity.length_squared();
    let b = d.dot(velocity);
    let c = d.length_squared() - radius * radius;
    let disc = b * b - a * c;
    // A ball on the circle to rounding (c = O(ε R²) > 0) moving almost along
    // it can get disc < 0 from rounding alone (b² < a c): it touches the wall
    // at once rather than finding no wall.
    let disc = if c <= touch(radius) {
        positive_part(disc)
    } else {
        disc
    };
    if !(disc >= 0.0 && a > 0.0) {
        return None;
    }
    // Larger root of a t² + 2 b t + c. When b > 0 and c ≈ 0 (a ball on the
    // circle moving out) this cancels, but only in absolute terms of order
    // ε|d|/|v|, which is the accuracy of the contact anyway.
    Some(Root {
        num: disc.sqrt() - b,
        a,
        d,
        c,
    })
}

/// The smaller root of `|d + v t| = R` for a ball outside the circle moving
/// towards it (see [`cast_convex_circle`]), undivided.
#[inline]
pub(crate) fn convex_root(
    center: DVec2,
    radius: f64,
    origin: DVec2,
    velocity: DVec2,
) -> Option<Root> {
    let d = origin - center;
    let b = d.dot(velocity);
    if !(b < 0.0) {
        return None;
    }
    let a = velocity.length_squared();
    let c = d.length_squared() - radius * radius;
    let disc = b * b - a * c;
    if !(disc > 0.0) {
        return None;
    }
    // For b < 0 the cancellation of -b - sqrt(disc) when c ≈ 0 is absolute,
    // of order ε|d|/|v|, the accuracy of the contact anyway.
    Some(Root {
        num: -b - disc.sqrt(),
        a,
        d,
        c,
    })
}

/// Contact point and unit radial direction for a root `r` (relative to the
/// centre) that lies on the circle up to rounding: one Newton step for `1/|r|`
/// (no square root or division) makes the normal unit and puts the contact on
/// the circle to an ulp, which keeps each collision's energy and `Q` rounding
/// at the ulp level. A ball found off the wall (a
/// clamped flight time) is projected onto the circle exactly, in a branch the
/// processor predicts away.
#[inline]
pub(crate) fn contact(center: DVec2, r: DVec2, radius: f64) -> (DVec2, DVec2) {
    let inv_radius = 1.0 / radius;
    let rr = r.length_squared() * (inv_radius * inv_radius);
    if (rr - 1.0).abs() < 1e-8 {
        let radial = r * (inv_radius * (1.5 - 0.5 * rr));
        (center + radial * radius, radial)
    } else {
        let radial = r * r.length_recip();
        (center + radial * radius, radial)
    }
}

/// The ball outside the circle `|x - c| = R`: where it first meets it (the
/// smaller root), if it is moving towards it. Flight time clamped at 0, contact
/// snapped onto the circle, normal pointing away from the centre.
#[inline]
pub fn cast_convex_circle(
    center: DVec2,
    radius: f64,
    origin: DVec2,
    velocity: DVec2,
) -> Option<WallHit> {
    let root = convex_root(center, radius, origin, velocity)?;
    Some(root.land(center, radius, velocity))
}
