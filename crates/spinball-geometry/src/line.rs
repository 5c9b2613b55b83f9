//! Flat walls.
//!
//! A [`LineSegment`] is the building block of polygons and of the flat parts of
//! the stadium and the Sinai box. Its inward normal is the left normal of its
//! direction, so walls listed counter-clockwise enclose the table.

use glam::DVec2;

use crate::error::{GeometryError, MIN_LENGTH, coordinate};
use crate::positive_part::positive_part;

/// Where a ray meets a single wall, in the wall's own terms.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WallHit {
    /// Flight time to the wall, `>= 0`.
    pub time: f64,
    /// Contact point, snapped onto the wall.
    pub point: DVec2,
    /// Unit normal pointing into the table.
    pub normal: DVec2,
    /// Arc length from the wall's start to the contact, in `[0, length]`.
    pub along: f64,
}

/// A wall's flight time as an undivided fraction `dist / speed` (see
/// [`LineSegment::approach`] and [`ArcSegment::approach`]): comparing two
/// of them needs no division (`d₁·s₂ < d₂·s₁`, both denominators
/// positive).
///
/// [`ArcSegment::approach`]: crate::ArcSegment::approach
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Approach {
    /// The numerator, `≥ 0`: for a flat wall the distance to its line
    /// (clamped at 0), for an arc the circle root `t·|v|²` (clamped at 0).
    pub dist: f64,
    /// The denominator, `> 0`: for a flat wall the speed towards it,
    /// `−(v·n)`; for an arc `|v|²`.
    pub speed: f64,
}

/// A straight wall from `start` to `end`; the table lies to its left.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct LineSegment {
    start: DVec2,
    end: DVec2,
    dir: DVec2,
    normal: DVec2,
    length: f64,
}

impl LineSegment {
    /// A wall from `start` to `end`. The inward normal is the left normal of
    /// `end - start` (so a counter-clockwise loop encloses the table).
    ///
    /// # Errors
    /// [`GeometryError::NonFinite`] for NaN or infinite coordinates,
    /// [`GeometryError::OutOfRange`] for a coordinate beyond `±1e60`,
    /// [`GeometryError::DegenerateWall`] if its ends coincide,
    /// [`GeometryError::WallTooShort`] if it is shorter than
    /// [`MIN_LENGTH`] (`1e-60`).
    pub fn new(start: DVec2, end: DVec2) -> Result<Self, GeometryError> {
        for (name, v) in [
            ("start.x", start.x),
            ("start.y", start.y),
            ("end.x", end.x),
            ("end.y", end.y),
        ] {
            coordinate(name, v)?;
        }
        let delta = end - start;
        let length = delta.length();
        if delta == DVec2::ZERO {
            return Err(GeometryError::DegenerateWall { index: 0 });
        }
        if !(length >= MIN_LENGTH) {
            // Two distinct points closer than any table can run (a square
            // of side 1e-300): not degenerate, too small.
            return Err(GeometryError::WallTooShort {
                index: 0,
                // `hypot` does not underflow where `x² + y²` does (a wall
                // of length 1e-300 has a squared length of 0).
                length: delta.x.hypot(delta.y),
                min: MIN_LENGTH,
            });
        }
        let dir = delta / length;
        Ok(LineSegment {
            start,
            end,
            dir,
            normal: dir.perp(),
            length,
        })
    }

    /// First point of the wall.
    pub fn start(&self) -> DVec2 {
        self.start
    }
    /// Last point of the wall.
    pub fn end(&self) -> DVec2 {
        self.end
    }
    /// Length of the wall.
    pub fn length(&self) -> f64 {
        self.length
    }
    /// Unit normal pointing into the table.
    pub fn normal(&self) -> DVec2 {
        self.normal
    }

    /// Where a ball at `origin` with velocity `velocity` meets this wall, if it
    /// is moving towards it from the table side. `slack` is the length
    /// tolerance for hits at the wall's ends (they count as hits) and for a
    /// ball found behind the wall by rounding.
    #[inline]
    pub fn cast(&self, origin: DVec2, velocity: DVec2, slack: f64) -> Option<WallHit> {
        cast_line(
            self.start,
            self.dir,
            self.normal,
            self.length,
            origin,
            velocity,
            slack,
        )
    }

    /// Unit direction from start to end (the normal is its left
    /// perpendicular, `normal = (−dir.y, dir.x)` exactly).
    #[must_use]
    pub fn direction(&self) -> DVec2 {
        self.dir
    }

    /// Whether and how soon a ball at `origin` with velocity `velocity`
    /// reaches this wall from the table side, without dividing: the flight
    /// time is the fraction [`Approach::dist`]` / `[`Approach::speed`].
    ///
    /// The same acceptance as [`cast`](Self::cast) (moving into the wall,
    /// not behind it by more than `slack`, reaching it between its ends
    /// widened by `slack`) with the end check multiplied through by the
    /// positive divisor: `along·w ∈ [−slack·w, (length + slack)·w]` where
    /// `along·w = (rel·dir)·w + (v·dir)·dist`. It differs from `cast`'s
    /// check only by rounding, far inside `slack`. A table picks the
    /// earliest wall by comparing these fractions cross-multiplied and
    /// divides once, for the wall it picked ([`land`](Self::land)).
    #[inline]
    #[must_use]
    pub fn approach(&self, origin: DVec2, velocity: DVec2, slack: f64) -> Option<Approach> {
        // −(v·n), exactly the negation of `velocity.dot(normal)`.
        let w = velocity.dot(-self.normal);
        if !(w > 0.0) {
            return None;
        }
        let rel = origin - self.start;
        let dist = rel.dot(self.normal);
        if dist < -slack {
            return None;
        }
        let dist = positive_part(dist);
        let along_w = rel.dot(self.dir) * w + velocity.dot(self.dir) * dist;
        if !(along_w >= -slack * w && along_w <= (self.length + slack) * w) {
            return None;
        }
        Some(Approach { dist, speed: w })
    }

    /// The contact of a ball at `origin` with velocity `velocity` after
    /// flying for `time` (the fraction of an [`approach`](Self::approach),
    /// divided): the point on the wall and its distance `along` it from the
    /// start, clamped to the wall.
    #[inline]
    #[must_use]
    pub fn land(&self, origin: DVec2, velocity: DVec2, time: f64) -> (DVec2, f64) {
        // The contact relative to the start, projected on the wall, as
        // `cast` computes it (and as an arc's `land` offsets the contact
        // from its centre: the lanes share that offset between the kinds).
        let along = ((origin - self.start) + velocity * time).dot(self.dir);
        let along = along.clamp(0.0, self.length);
        (self.start + self.dir * along, along)
    }

    /// Signed distance of `p` from the wall's line, positive on the table side.
    #[inline]
    pub fn signed_distance(&self, p: DVec2) -> f64 {
        (p - self.start).dot(self.normal)
    }
}

/// Cast against the wall through `start` with unit direction `dir`, unit
/// inward normal `normal` and length `length` (free function for static
/// dispatch in the built-in tables).
///
/// Only a ball moving *into* the wall (`v·n < 0`) from its table side hits it,
/// so the wall a ball has just left is never found again. A ball numerically a
/// hair behind the wall (within `slack`) gets flight time 0 and the contact is
/// snapped onto the wall; a ball farther behind it (in a non-convex table, on
/// the far side of a wall that faces elsewhere) does not hit it.
#[inline]
pub fn cast_line(
    start: DVec2,
    dir: DVec2,
    normal: DVec2,
    length: f64,
    origin: DVec2,
    velocity: DVec2,
    slack: f64,
) -> Option<WallHit> {
    let vn = velocity.dot(normal);
    if !(vn < 0.0) {
        return None;
    }
    let rel = origin - start;
    let dist = rel.dot(normal);
    if dist < -slack {
        // Behind the wall (on its far side), not a hair behind: never a hit.
        return None;
    }
    let time = positive_part(dist / -vn);
    let along = (rel + velocity * time).dot(dir);
    if !(along >= -slack && along <= length + slack) {
        return None;
    }
    let along = along.clamp(0.0, length);
    Some(WallHit {
        time,
        point: start + dir * along,
        normal,
        along,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_ball_on_the_line_is_at_distance_plus_zero() {
        // A wall whose normal, (−0.8, −0.6), has two negative components:
        // from its start the dot product is (+0)(−0.8) + (+0)(−0.6) = −0,
        // and the clamped distance is +0 (as the lanes' `maxpd` gives it).
        let wall = LineSegment::new(DVec2::ZERO, DVec2::new(-0.6, 0.8)).unwrap();
        let n = wall.normal();
        assert!(n.x < 0.0 && n.y < 0.0, "{n:?}");
        let a = wall
            .approach(DVec2::ZERO, DVec2::new(0.8, 0.6), 1e-12)
            .unwrap();
        assert_eq!(a.dist.to_bits(), 0.0_f64.to_bits());
        assert!(a.speed > 0.99, "{}", a.speed);
        // A ball a hair behind the line (within the slack) is clamped to +0 too.
        let a = wall
            .approach(DVec2::new(1e-14, 0.0), DVec2::new(0.8, 0.6), 1e-12)
            .unwrap();
        assert_eq!(a.dist.to_bits(), 0.0_f64.to_bits());
    }
}
