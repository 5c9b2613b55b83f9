//! `Boundary::hit_at` is the inverse of the arc length of a cast: for every
//! built-in table and for segment tables (concave and convex arcs, holes),
//! the hit at `s` lies on the wall, has `s` as its arc length, and a ball
//! sent straight at that point along the normal meets the same wall there
//! with the same normal and curvature.

use std::f64::consts::PI;

use glam::DVec2;
use spinball_geometry::{
    ArcSegment, Boundary, Circle, LineSegment, Rectangle, Segment, SegmentTable, Sinai, Stadium,
    Table,
};

fn check<B: Boundary>(name: &str, table: &B) {
    let p = table.perimeter();
    let n = 997;
    for k in 0..n {
        let s = p * (k as f64 + 0.31) / n as f64;
        let hit = table
            .hit_at(s)
            .unwrap_or_else(|| panic!("{name}: no hit at s = {s}"));
        assert!(
            (hit.s() - s).abs() < 1e-12 * p,
            "{name}: s {s} -> {}",
            hit.s()
        );
        assert!(table.contains(hit.point), "{name}: {:?} outside", hit.point);
        assert!((hit.normal.length() - 1.0).abs() < 1e-14);
        // Send a ball at the point along −normal from just inside.
        let eps = 1e-6 * table.length_scale();
        let back = table
            .cast(hit.point + hit.normal * eps, -hit.normal)
            .unwrap_or_else(|| panic!("{name}: nothing ahead at s = {s}"));
        assert_eq!(back.wall, hit.wall, "{name}: wall at s = {s}");
        assert!(
            (back.point - hit.point).length() < 1e-9,
            "{name}: point at s = {s}"
        );
        assert!(
            (back.normal - hit.normal).length() < 1e-9,
            "{name}: normal at s = {s}"
        );
        assert_eq!(
            back.curvature, hit.curvature,
            "{name}: curvature at s = {s}"
        );
        assert!(
            (back.s() - s).abs() < 1e-8 * p,
            "{name}: s {s} vs cast {}",
            back.s()
        );
        // s is taken modulo the perimeter.
        let again = table.hit_at(s + 3.0 * p).expect("wrapped");
        assert!((again.point - hit.point).length() < 1e-12 * p);
    }
    assert!(table.hit_at(f64::NAN).is_none());
    assert!(table.hit_at(f64::INFINITY).is_none());
}

#[test]
fn built_in_tables_invert_their_arc_length() {
    check("circle", &Circle::new(1.3).unwrap());
    check("rectangle", &Rectangle::new(1.5, 1.0).unwrap());
    check("stadium", &Stadium::new(1.0).unwrap());
    check("long stadium", &Stadium::new(4.0).unwrap());
    check("sinai", &Sinai::new(2.0, 1.0).unwrap());
    check("table enum", &"stadium:a=2".parse::<Table>().unwrap());
    let shape = Stadium::new(0.5).unwrap().shape().unwrap();
    check("built", &shape.build().unwrap());
}

#[test]
fn segment_tables_invert_their_arc_length() {
    let p = DVec2::new;
    let line = |a, b| Segment::Line(LineSegment::new(a, b).unwrap());
    // A mushroom: flat stem, concave cap.
    let (r, w, h) = (1.0, 0.3, 1.0);
    let mushroom = SegmentTable::new(vec![
        line(p(-w, -h), p(w, -h)),
        line(p(w, -h), p(w, 0.0)),
        line(p(w, 0.0), p(r, 0.0)),
        Segment::Arc(ArcSegment::new(DVec2::ZERO, r, 0.0, PI).unwrap()),
        line(p(-r, 0.0), p(-w, 0.0)),
        line(p(-w, 0.0), p(-w, -h)),
    ])
    .unwrap();
    check("mushroom", &mushroom);
    // A square with a convex disk hole (a Sinai table built from segments).
    let square = vec![
        line(p(-2.0, -2.0), p(2.0, -2.0)),
        line(p(2.0, -2.0), p(2.0, 2.0)),
        line(p(2.0, 2.0), p(-2.0, 2.0)),
        line(p(-2.0, 2.0), p(-2.0, -2.0)),
    ];
    let hole = vec![Segment::Arc(
        ArcSegment::new(DVec2::ZERO, 0.7, 0.0, -2.0 * PI).unwrap(),
    )];
    check(
        "holed square",
        &SegmentTable::with_holes(square, vec![hole]).unwrap(),
    );
}
