//! Flat walls.
//!
//! A [`LineSegment`] is the building block of polygons and of the flat parts of
//! the stadium and the Sinai box. Its inward normal is the left normal of its
//! direction, so walls listed counter-clockwise enclose the table.

use glam::DVec2;

use crate::error::{GeometryError, MIN_LENGTH, coordinate};

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
    /// [`GeometryError::DegenerateWall`] if the wall is shorter than `1e-60`.
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
        if !(length >= MIN_LENGTH) || !length.is_finite() {
            return Err(GeometryError::DegenerateWall { index: 0 });
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
    let time = (dist / -vn).max(0.0);
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
