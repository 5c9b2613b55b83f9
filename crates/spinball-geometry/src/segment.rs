//! One wall of a table built from walls: a line segment or a circular arc.

use std::f64::consts::{FRAC_PI_2, PI};

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
            Segment::Arc(a) => a.radius() * a.radius() * sweep_minus_sine(a.sweep()),
        }
    }
    /// The wall's bounding box: its ends and, for an arc, each extreme
    /// point of its circle along an axis that the arc spans.
    ///
    /// Whether the arc spans an axis direction is decided on its angles
    /// (exact for any radius); only an extreme point within `1e-12` rad of
    /// an end (where the answer is rounding, and the point is the end to
    /// `1e-12 R`) is left to the test [`ArcSegment::covers`] makes, as it
    /// always was. (That test alone compares the point against the chord
    /// through the arc's rounded ends: for an arc whose sagitta is below
    /// the rounding of its radius it took the far side of the circle, and
    /// the box of a unit square with a top wall of radius 1e8 was
    /// `[-1e8, 1e8] × [-2e8, 1]`.)
    pub(crate) fn aabb(&self) -> Aabb {
        let (s, e) = (self.start(), self.end());
        let mut b = Aabb::new(s.min(e), s.max(e));
        if let Segment::Arc(a) = self {
            let tol = 1e-12 + 8.0 * f64::EPSILON * a.start_angle().abs();
            let axes = [
                (DVec2::X, 0.0),
                (DVec2::Y, FRAC_PI_2),
                (DVec2::NEG_X, PI),
                (DVec2::NEG_Y, -FRAC_PI_2),
            ];
            for (dir, angle) in axes {
                let p = a.center() + dir * a.radius();
                if a.spans_angle(angle, tol)
                    .unwrap_or_else(|| a.covers(p, 0.0))
                {
                    b = b.union(&Aabb::new(p, p));
                }
            }
        }
        b
    }
}

/// `θ − sin θ` without cancellation for a small sweep: below `|θ| = 1/2`
/// by its series (`θ³/6 − θ⁵/120 + …`, ten terms: the next is below
/// `ε θ³/6`), else directly (the two terms then differ by a factor of at
/// least 24, and the difference loses at most 5 bits).
fn sweep_minus_sine(t: f64) -> f64 {
    if t.abs() >= 0.5 {
        return t - t.sin();
    }
    // Σ_{k≥1} (−1)^(k+1) θ^(2k+1) / (2k+1)!
    let t2 = t * t;
    let mut term = t * t2 / 6.0;
    let mut sum = 0.0;
    for k in 1..=10 {
        sum += term;
        let n = 2.0 * k as f64;
        term *= -t2 / ((n + 2.0) * (n + 3.0));
    }
    sum
}
