//! Shared helpers for the geometry integration tests: an independent
//! description of each table (signed distance and the documented Birkhoff
//! parametrisation), written from the docs rather than from the code under test.
#![allow(dead_code, unused_imports)]

pub use spinball_test_support::{mushroom, segment_sinai, signed_distance};

use std::f64::consts::PI;

use spinball_geometry::{
    ArcSegment, Boundary, DVec2, Hit, LineSegment, Segment, SegmentTable, Sinai, Stadium, Table,
};

/// Delegates `cast` and nothing else, so every other method of the wrapped
/// table is the trait's provided default.
pub struct CastOnly<B>(pub B);

impl<B: Boundary> Boundary for CastOnly<B> {
    fn cast(&self, origin: DVec2, velocity: DVec2) -> Option<Hit> {
        self.0.cast(origin, velocity)
    }
}

/// The four built-in tables at the paper's parameters plus a few shapes that
/// make the edge cases different (long stadium, small and large obstacle,
/// non-square rectangle, non-unit circle).
pub fn tables() -> Vec<Table> {
    [
        "circle",
        "circle:R=2.5",
        "rectangle",
        "rectangle:L=1.5,H=1",
        "stadium:a=1",
        "stadium:a=0.2",
        "stadium:a=4",
        "sinai:L=2,R=1",
        "sinai:L=2,R=0.3",
        "sinai:L=1,R=0.9",
    ]
    .iter()
    .map(|s| s.parse().expect("valid spec"))
    .collect()
}

/// The boundary point, inward normal and wall id at Birkhoff coordinate
/// `sigma` in `[0, perimeter)`, from each table's documented parametrisation.
pub fn birkhoff_point(table: &Table, sigma: f64) -> (DVec2, DVec2, u32) {
    match table {
        Table::Circle(c) => {
            let r = c.radius();
            let dir = DVec2::from_angle(sigma / r);
            (dir * r, -dir, 0)
        }
        Table::Rectangle(r) => box_point(r.l(), r.h(), sigma),
        Table::Stadium(s) => stadium_point(s, sigma),
        Table::Sinai(s) => sinai_point(s, sigma),
    }
}

/// Box `[-l, l] × [-h, h]`: `s` from `(-l, -h)` counter-clockwise, walls
/// bottom 0, right 1, top 2, left 3.
fn box_point(l: f64, h: f64, sigma: f64) -> (DVec2, DVec2, u32) {
    if sigma < 2.0 * l {
        (DVec2::new(-l + sigma, -h), DVec2::Y, 0)
    } else if sigma < 2.0 * l + 2.0 * h {
        (DVec2::new(l, -h + (sigma - 2.0 * l)), DVec2::NEG_X, 1)
    } else if sigma < 4.0 * l + 2.0 * h {
        (
            DVec2::new(l - (sigma - 2.0 * l - 2.0 * h), h),
            DVec2::NEG_Y,
            2,
        )
    } else {
        (DVec2::new(-l, h - (sigma - 4.0 * l - 2.0 * h)), DVec2::X, 3)
    }
}

/// Stadium: `s` from `(-a, -1)` counter-clockwise: bottom `[0, 2a]`, right
/// cap `[2a, 2a + π]`, top, left cap.
fn stadium_point(s: &Stadium, sigma: f64) -> (DVec2, DVec2, u32) {
    let a = s.a();
    if sigma < 2.0 * a {
        (DVec2::new(-a + sigma, -1.0), DVec2::Y, 0)
    } else if sigma < 2.0 * a + PI {
        let dir = DVec2::from_angle(-0.5 * PI + (sigma - 2.0 * a));
        (DVec2::new(a, 0.0) + dir, -dir, 1)
    } else if sigma < 4.0 * a + PI {
        (DVec2::new(a - (sigma - 2.0 * a - PI), 1.0), DVec2::NEG_Y, 2)
    } else {
        let dir = DVec2::from_angle(0.5 * PI + (sigma - 4.0 * a - PI));
        (DVec2::new(-a, 0.0) + dir, -dir, 3)
    }
}

/// Sinai: the box as for the rectangle (`[0, 8l)`), then the disk from `(r, 0)`
/// clockwise.
fn sinai_point(s: &Sinai, sigma: f64) -> (DVec2, DVec2, u32) {
    let (l, r) = (s.l(), s.r());
    if sigma < 8.0 * l {
        box_point(l, l, sigma)
    } else {
        let dir = DVec2::from_angle(-(sigma - 8.0 * l) / r);
        (dir * r, dir, 4)
    }
}

/// Point and inward normal at fraction `f` in `[0, 1]` along a wall of a
/// segment table, from the documented orientation rules (table on the left;
/// counter-clockwise arcs concave).
pub fn segment_point(w: &Segment, f: f64) -> (DVec2, DVec2) {
    match w {
        Segment::Line(l) => (l.start() + (l.end() - l.start()) * f, l.normal()),
        Segment::Arc(a) => {
            let dir = DVec2::from_angle(a.start_angle() + f * a.sweep());
            let n = if a.is_concave() { -dir } else { dir };
            (a.center() + dir * a.radius(), n)
        }
    }
}

/// Whether `p` is in the closed mushroom (cap radius 1, stem half-width 0.3,
/// stem height 1).
pub fn in_mushroom(p: DVec2) -> bool {
    let in_cap = p.y >= 0.0 && p.length() <= 1.0;
    let in_stem = p.x.abs() <= 0.3 && (-1.0..=0.0).contains(&p.y);
    in_cap || in_stem
}

/// Distance from `p` to one wall of a segment table.
pub fn wall_distance(w: &Segment, p: DVec2) -> f64 {
    match w {
        Segment::Line(l) => {
            let d = l.end() - l.start();
            let f = ((p - l.start()).dot(d) / d.length_squared()).clamp(0.0, 1.0);
            (p - (l.start() + d * f)).length()
        }
        Segment::Arc(a) => {
            let rel = p - a.center();
            // Angle of p past the start, in the arc's sweep direction.
            let mut ang = a
                .start_direction()
                .perp_dot(rel)
                .atan2(a.start_direction().dot(rel));
            if a.sweep() < 0.0 {
                ang = -ang;
            }
            if ang < 0.0 {
                ang += 2.0 * PI;
            }
            if ang <= a.sweep().abs() {
                (rel.length() - a.radius()).abs()
            } else {
                (p - a.start()).length().min((p - a.end()).length())
            }
        }
    }
}

/// Distance from `p` to the nearest wall of a segment table.
pub fn walls_distance(t: &SegmentTable, p: DVec2) -> f64 {
    t.walls()
        .iter()
        .map(|w| wall_distance(w, p))
        .fold(f64::INFINITY, f64::min)
}
