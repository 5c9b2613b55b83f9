//! Tables and table geometry written for the tests, independently of the
//! code under test.

use std::f64::consts::PI;

use spinball_geometry::{ArcSegment, DVec2, LineSegment, Segment, SegmentTable, Table};

/// Signed distance to the boundary, positive inside (exact inside; outside it
/// is a lower bound on the distance in magnitude, which is all the tests need
/// to stay away from the walls).
pub fn signed_distance(table: &Table, p: DVec2) -> f64 {
    match table {
        Table::Circle(c) => c.radius() - p.length(),
        Table::Rectangle(r) => (r.l() - p.x.abs()).min(r.h() - p.y.abs()),
        Table::Stadium(s) => 1.0 - DVec2::new((p.x.abs() - s.a()).max(0.0), p.y).length(),
        Table::Sinai(s) => (s.l() - p.x.abs())
            .min(s.l() - p.y.abs())
            .min(p.length() - s.r()),
    }
}

/// The mushroom of the `SegmentTable` docs: cap radius 1, stem half-width
/// 0.3, stem height 1.
pub fn mushroom() -> SegmentTable {
    let (r, w, h) = (1.0, 0.3, 1.0);
    let p = DVec2::new;
    let line = |a, b| Segment::Line(LineSegment::new(a, b).expect("valid wall"));
    SegmentTable::new(vec![
        line(p(-w, -h), p(w, -h)),
        line(p(w, -h), p(w, 0.0)),
        line(p(w, 0.0), p(r, 0.0)),
        Segment::Arc(ArcSegment::new(DVec2::ZERO, r, 0.0, PI).expect("valid arc")),
        line(p(-r, 0.0), p(-w, 0.0)),
        line(p(-w, 0.0), p(-w, -h)),
    ])
    .expect("valid mushroom")
}

/// The Sinai table built from segments: the box `[-l, l]²` counter-clockwise
/// and the obstacle of radius `r` as a clockwise (convex) full circle.
pub fn segment_sinai(l: f64, r: f64) -> SegmentTable {
    let p = DVec2::new;
    let line = |a, b| Segment::Line(LineSegment::new(a, b).expect("valid wall"));
    SegmentTable::with_holes(
        vec![
            line(p(-l, -l), p(l, -l)),
            line(p(l, -l), p(l, l)),
            line(p(l, l), p(-l, l)),
            line(p(-l, l), p(-l, -l)),
        ],
        vec![vec![Segment::Arc(
            ArcSegment::new(DVec2::ZERO, r, 0.0, -2.0 * PI).expect("valid arc"),
        )]],
    )
    .expect("valid Sinai from segments")
}
