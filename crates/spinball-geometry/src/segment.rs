//! One wall of a table built from walls: a line segment or a circular arc.

use glam::DVec2;

use crate::aabb::Aabb;
use crate::arc::ArcSegment;
use crate::line::LineSegment;

/// One wall of a [`SegmentTable`](crate::SegmentTable).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Segment {
    /// A flat wall.
    Line(LineSegment),
    /// A circular wall (concave or convex by the sign of its sweep).
    Arc(ArcSegment),
}

impl Segment {
    /// First point.
    pub fn start(&self) -> DVec2 {
        match self {
            Segment::Line(l) => l.start(),
            Segment::Arc(a) => a.start(),
        }
    }
    /// Last point.
    pub fn end(&self) -> DVec2 {
        match self {
            Segment::Line(l) => l.end(),
            Segment::Arc(a) => a.end(),
        }
    }
    /// Length of the wall.
    pub fn length(&self) -> f64 {
        match self {
            Segment::Line(l) => l.length(),
            Segment::Arc(a) => a.length(),
        }
    }
    /// Signed curvature (`0` flat, `-1/R` concave, `+1/R` convex).
    pub fn curvature(&self) -> f64 {
        match self {
            Segment::Line(_) => 0.0,
            Segment::Arc(a) => a.curvature(),
        }
    }
    /// Twice the signed area between the chord and the wall (zero for a line).
    pub(crate) fn bulge2(&self) -> f64 {
        match self {
            Segment::Line(_) => 0.0,
            Segment::Arc(a) => a.radius() * a.radius() * (a.sweep() - a.sweep().sin()),
        }
    }
    pub(crate) fn aabb(&self) -> Aabb {
        let (s, e) = (self.start(), self.end());
        let mut b = Aabb::new(s.min(e), s.max(e));
        if let Segment::Arc(a) = self {
            for dir in [DVec2::X, DVec2::Y, DVec2::NEG_X, DVec2::NEG_Y] {
                let p = a.center() + dir * a.radius();
                if a.covers(p, 0.0) {
                    b = b.union(&Aabb::new(p, p));
                }
            }
        }
        b
    }
}
