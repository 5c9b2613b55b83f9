//! Issue 9, geometry side: sizes f64 cannot run are rejected with their
//! range (F1–F3), the launch tolerance follows the thin dimension (F8), and
//! walls that do not bound a table are rejected with the walls named (F7).
//! The reproducers are the issue's, literally.

use spinball_geometry::{
    ArcSegment, Boundary, Circle, DVec2, GeometryError, LineSegment, Rectangle, Segment,
    SegmentTable, Sinai, Stadium,
};

fn out_of_range(e: GeometryError, want: &str) {
    match e {
        GeometryError::OutOfRange { name, min, max, .. } => {
            assert_eq!(name, want);
            assert!(min < max);
            let msg = e.to_string();
            assert!(msg.contains("range"), "{msg}");
        }
        other => panic!("expected OutOfRange for `{want}`, got {other:?}"),
    }
}

#[test]
fn f3_huge_and_tiny_tables_are_rejected_with_their_range() {
    out_of_range(Sinai::new(1e160, 5e159).unwrap_err(), "l");
    out_of_range(Sinai::new(1e-160, 5e-161).unwrap_err(), "l");
    out_of_range(Circle::new(1e160).unwrap_err(), "radius");
    out_of_range(Circle::new(1e-160).unwrap_err(), "radius");
    out_of_range(Rectangle::new(1e61, 1.0).unwrap_err(), "l");
    out_of_range(Stadium::new(1e9).unwrap_err(), "a");
    // A disk too small for the rounding of |x|² and a channel narrower than
    // the walls' tolerance.
    out_of_range(Sinai::new(2.0, 1e-7).unwrap_err(), "r");
    out_of_range(Sinai::new(2.0, 2.0 * (1.0 - 1e-14)).unwrap_err(), "r");
    // The issue's sensible scales still build.
    for t in [Circle::new(1e8), Circle::new(1e-8)] {
        t.unwrap();
    }
    Sinai::new(2.0, 1.999999).unwrap();
    Stadium::new(1e-9).unwrap();
    Stadium::new(1e4).unwrap();
    Rectangle::new(1e6, 1e-6).unwrap();
}

#[test]
fn f8_launch_tolerance_follows_the_thin_dimension() {
    let thin = Rectangle::new(1e6, 1e-6).unwrap();
    assert!(!thin.contains(DVec2::new(0.0, 1.01e-6)));
    assert!(thin.contains(DVec2::new(0.0, 1e-6)));
    assert!(thin.contains(DVec2::new(1e6, -1e-6)));
    let long = Stadium::new(1e8).unwrap();
    assert!(!long.contains(DVec2::new(0.0, 1.0 + 1e-7)));
    assert!(long.contains(DVec2::new(0.0, 1.0)));
    // On the caps, x carries the rounding of a: the cap's end is inside.
    assert!(long.contains(DVec2::new(1e8 + 1.0, 0.0)));
    assert!(!long.contains(DVec2::new(1e8 + 1.0 + 1e-5, 0.0)));
}

fn lines(v: &[(f64, f64)]) -> Vec<Segment> {
    (0..v.len())
        .map(|i| {
            let (a, b) = (v[i], v[(i + 1) % v.len()]);
            Segment::Line(LineSegment::new(DVec2::new(a.0, a.1), DVec2::new(b.0, b.1)).unwrap())
        })
        .collect()
}

#[test]
fn f7_self_intersecting_outer_loop_is_rejected() {
    let v = [(0.0, 0.0), (0.0, 1.0), (3.0, 0.0), (3.0, 3.0)].map(|(x, y)| DVec2::new(x, y));
    let e = SegmentTable::polygon(&v).unwrap_err();
    match e {
        GeometryError::Crossing {
            first_loop: 0,
            first_index: 1,
            second_loop: 0,
            second_index: 3,
            x,
            y,
        } => {
            // (0,1)-(3,0) meets (3,3)-(0,0) at x = y = 0.75.
            assert!((x - 0.75).abs() < 1e-12 && (y - 0.75).abs() < 1e-12);
        }
        other => panic!("expected Crossing of walls 1 and 3, got {other:?}"),
    }
}

#[test]
fn f7_zero_width_spike_is_rejected() {
    let v = [
        (0.0, 0.0),
        (2.0, 0.0),
        (2.0, 3.0),
        (2.0, 0.5),
        (2.0, 1.0),
        (0.0, 1.0),
    ]
    .map(|(x, y)| DVec2::new(x, y));
    let e = SegmentTable::polygon(&v).unwrap_err();
    // (2,0)-(2,3) and (2,3)-(2,0.5) run along each other.
    assert_eq!(
        e,
        GeometryError::Overlap {
            first_loop: 0,
            first_index: 1,
            second_loop: 0,
            second_index: 2,
        }
    );
}

fn square(c: (f64, f64), h: f64, clockwise: bool) -> Vec<Segment> {
    let mut v = vec![
        (c.0 - h, c.1 - h),
        (c.0 + h, c.1 - h),
        (c.0 + h, c.1 + h),
        (c.0 - h, c.1 + h),
    ];
    if clockwise {
        v.reverse();
    }
    lines(&v)
}

#[test]
fn f7_misplaced_holes_are_rejected() {
    let outer = || square((0.0, 0.0), 2.0, false);
    // A hole outside the outer loop.
    let e = SegmentTable::with_holes(outer(), vec![square((5.0, 0.0), 0.5, true)]).unwrap_err();
    assert!(
        matches!(e, GeometryError::MisplacedHole { hole: 1, .. }),
        "{e:?}"
    );
    assert!(e.to_string().contains("outside the outer loop"), "{e}");
    // A hole crossing the outer loop.
    let e = SegmentTable::with_holes(outer(), vec![square((2.0, 0.0), 0.5, true)]).unwrap_err();
    assert!(
        matches!(
            e,
            GeometryError::Crossing {
                first_loop: 0,
                second_loop: 1,
                ..
            }
        ),
        "{e:?}"
    );
    // Two holes crossing each other.
    let e = SegmentTable::with_holes(
        outer(),
        vec![
            square((0.0, 0.0), 0.5, true),
            square((0.5, 0.25), 0.5, true),
        ],
    )
    .unwrap_err();
    assert!(
        matches!(
            e,
            GeometryError::Crossing {
                first_loop: 1,
                second_loop: 2,
                ..
            }
        ),
        "{e:?}"
    );
    // A hole inside another hole.
    let e = SegmentTable::with_holes(
        outer(),
        vec![
            square((0.0, 0.0), 1.0, true),
            square((0.0, 0.0), 0.25, true),
        ],
    )
    .unwrap_err();
    assert!(
        matches!(e, GeometryError::MisplacedHole { hole: 2, .. }),
        "{e:?}"
    );
    // A disk hole inside the square is fine (the Sinai table from walls).
    let disk = ArcSegment::new(DVec2::ZERO, 1.0, 0.0, -std::f64::consts::TAU).unwrap();
    SegmentTable::with_holes(outer(), vec![vec![Segment::Arc(disk)]]).unwrap();
    // A disk hole crossing the outer wall is not.
    let poking = ArcSegment::new(DVec2::new(1.5, 0.0), 1.0, 0.0, -std::f64::consts::TAU).unwrap();
    let e = SegmentTable::with_holes(outer(), vec![vec![Segment::Arc(poking)]]).unwrap_err();
    assert!(matches!(e, GeometryError::Crossing { .. }), "{e:?}");
}

#[test]
fn tangent_junctions_of_lines_and_arcs_still_build() {
    // The stadium from walls: flats tangent to the caps at the junctions.
    use std::f64::consts::PI;
    let p = DVec2::new;
    let walls = vec![
        Segment::Line(LineSegment::new(p(-1.0, -1.0), p(1.0, -1.0)).unwrap()),
        Segment::Arc(ArcSegment::new(p(1.0, 0.0), 1.0, -0.5 * PI, PI).unwrap()),
        Segment::Line(LineSegment::new(p(1.0, 1.0), p(-1.0, 1.0)).unwrap()),
        Segment::Arc(ArcSegment::new(p(-1.0, 0.0), 1.0, 0.5 * PI, PI).unwrap()),
    ];
    SegmentTable::new(walls).unwrap();
}
