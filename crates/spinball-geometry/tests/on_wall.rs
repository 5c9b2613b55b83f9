//! Issue 39 item 6: `contains()` was false on a small hole's own wall (483
//! of 1605 contacts within 3e-17 of a disk of radius 1e-3). A point on a
//! wall counts as inside, at every scale the constructors accept. And item
//! 5: a wall of length 1e-300 is below the smallest length that works, not
//! "degenerate".

mod common;

use std::f64::consts::TAU;

use common::CastOnly;
use rand::{Rng, SeedableRng};
use rand_pcg::Pcg64;
use spinball_geometry::error::MIN_LENGTH;
use spinball_geometry::{
    ArcSegment, Boundary, Circle, DVec2, GeometryError, Hit, LineSegment, Rectangle, Segment,
    SegmentTable, Sinai,
};

/// A scalar run of `steps` cast-and-reflect collisions from `start`.
fn contacts<B: Boundary>(table: &B, start: DVec2, steps: usize, seed: u64) -> Vec<Hit> {
    let mut rng = Pcg64::seed_from_u64(seed);
    let (mut o, mut v) = (start, DVec2::from_angle(rng.random::<f64>() * TAU));
    (0..steps)
        .map(|_| {
            let hit = table.cast(o, v).expect("a wall ahead");
            o = hit.point;
            v -= 2.0 * v.dot(hit.normal) * hit.normal;
            hit
        })
        .collect()
}

/// The square `[0, s]²` with a disk hole of radius `1e-3 s` at `(0.3, 0.7) s`.
fn square_with_small_hole(s: f64) -> SegmentTable {
    let p = |x: f64, y: f64| DVec2::new(x * s, y * s);
    let line = |a, b| Segment::Line(LineSegment::new(a, b).unwrap());
    SegmentTable::with_holes(
        vec![
            line(p(0.0, 0.0), p(1.0, 0.0)),
            line(p(1.0, 0.0), p(1.0, 1.0)),
            line(p(1.0, 1.0), p(0.0, 1.0)),
            line(p(0.0, 1.0), p(0.0, 0.0)),
        ],
        vec![vec![Segment::Arc(
            ArcSegment::new(p(0.3, 0.7), 1e-3 * s, 0.0, -TAU).unwrap(),
        )]],
    )
    .unwrap()
}

#[test]
fn contacts_on_a_small_hole_are_inside_at_every_scale() {
    for s in [1e-55, 1e-20, 1.0, 1e20, 1e55] {
        let t = square_with_small_hole(s);
        // Shots aimed across the hole from random points of the square,
        // then one more collision from the contact (1605 shots, as in the
        // issue).
        let mut on_hole = 0;
        let mut missed_by_chord_test = 0;
        let mut rng = Pcg64::seed_from_u64(39);
        let c = DVec2::new(0.3, 0.7) * s;
        for _ in 0..1605 {
            let o = DVec2::new(rng.random::<f64>(), rng.random::<f64>()) * s;
            if (o - c).length() < 0.01 * s {
                continue;
            }
            let to = c - o;
            let aim = c + to.perp().normalize() * (1e-3 * s * (1.98 * rng.random::<f64>() - 0.99));
            let first = t.cast(o, aim - o).expect("a wall ahead");
            let v = aim - o;
            let v = v - 2.0 * v.dot(first.normal) * first.normal;
            let second = t.cast(first.point, v).expect("a wall ahead");
            for h in [first, second] {
                assert!(
                    t.contains(h.point),
                    "s = {s}: contact {:?} on wall {}",
                    h.point,
                    h.wall
                );
                if h.wall == 4 {
                    on_hole += 1;
                    // The reproduction: the trait's chord test alone misses
                    // some (contacts round by ε of their coordinates, ~1e-13
                    // of the hole's radius).
                    if !CastOnly(&t).contains(h.point) {
                        missed_by_chord_test += 1;
                    }
                }
            }
        }
        assert!(on_hole > 1500, "s = {s}: {on_hole} contacts on the hole");
        if s == 1.0 {
            assert!(
                missed_by_chord_test > 0,
                "the reproducer no longer reproduces"
            );
        }
        // Points of the hole's circle, exactly as `hit_at` puts them, are
        // inside; its centre and a point 1e-6 of the radius inside it are not.
        let hole_s0: f64 = t.walls()[..4].iter().map(Segment::length).sum();
        for k in 0..64 {
            let h = t
                .hit_at(hole_s0 + TAU * 1e-3 * s * (k as f64 + 0.5) / 64.0)
                .unwrap();
            assert_eq!(h.wall, 4);
            assert!(t.contains(h.point), "s = {s}: {:?}", h.point);
            let c = DVec2::new(0.3, 0.7) * s;
            let deeper = c + (h.point - c) * (1.0 - 1e-6);
            assert!(!t.contains(deeper), "s = {s}: {deeper:?} inside the hole");
        }
        assert!(!t.contains(DVec2::new(0.3, 0.7) * s));
    }
}

#[test]
fn contacts_of_built_in_tables_are_inside_at_every_scale() {
    for s in [1e-55, 1.0, 1e55] {
        let sinai = Sinai::new(2.0 * s, 2e-3 * s).unwrap();
        let circle = Circle::new(s).unwrap();
        let rect = Rectangle::new(s, 0.5 * s).unwrap();
        for seed in 0..10 {
            for h in contacts(&sinai, DVec2::new(0.01, 0.01) * s, 400, seed) {
                assert!(sinai.contains(h.point), "sinai s = {s}: {:?}", h.point);
            }
            for h in contacts(&circle, DVec2::new(0.1, 0.2) * s, 400, seed) {
                assert!(circle.contains(h.point), "circle s = {s}: {:?}", h.point);
            }
            for h in contacts(&rect, DVec2::new(0.1, 0.2) * s, 400, seed) {
                assert!(rect.contains(h.point), "rectangle s = {s}: {:?}", h.point);
            }
        }
    }
}

#[test]
fn a_square_below_the_smallest_size_says_so() {
    let v = |x: f64, y: f64| DVec2::new(x, y) * 1e-300;
    let e =
        SegmentTable::polygon(&[v(0.0, 0.0), v(1.0, 0.0), v(1.0, 1.0), v(0.0, 1.0)]).unwrap_err();
    assert_eq!(
        e,
        GeometryError::WallTooShort {
            index: 0,
            length: 1e-300,
            min: MIN_LENGTH,
        }
    );
    let msg = e.to_string();
    assert!(!msg.contains("degenerate"), "{msg}");
    assert!(
        msg.contains("below the smallest length that works, 1e-60"),
        "{msg}"
    );
    // The second wall of a polygon is named as such.
    let e = SegmentTable::polygon(&[
        DVec2::new(0.0, 0.0),
        DVec2::new(1.0, 0.0),
        DVec2::new(1.0, 1e-70),
        DVec2::new(0.0, 1.0),
    ])
    .unwrap_err();
    assert!(
        matches!(e, GeometryError::WallTooShort { index: 1, .. }),
        "{e:?}"
    );
    // Coinciding ends are still degenerate; the smallest length works.
    assert_eq!(
        LineSegment::new(DVec2::ONE, DVec2::ONE).unwrap_err(),
        GeometryError::DegenerateWall { index: 0 }
    );
    assert!(LineSegment::new(DVec2::ZERO, DVec2::new(MIN_LENGTH, 0.0)).is_ok());
}
