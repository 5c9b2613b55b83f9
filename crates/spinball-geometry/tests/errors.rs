//! Every invalid table description returns its own error variant (never a
//! table that would produce NaNs or let a ball out).

use std::f64::consts::{PI, TAU};

use spinball_geometry::{
    ArcSegment, Boundary, Circle, DVec2, GeometryError, LineSegment, Rectangle, Segment,
    SegmentTable, Sinai, Stadium, Table, TableSpecError,
};

const BAD_FINITE: [f64; 3] = [f64::NAN, f64::INFINITY, f64::NEG_INFINITY];
const BAD_SIGN: [f64; 4] = [0.0, -0.0, -1.0, -f64::MIN_POSITIVE];

fn non_finite(e: GeometryError, want: &str) -> bool {
    matches!(e, GeometryError::NonFinite { name, value } if name == want && !value.is_finite())
}

fn non_positive(e: GeometryError, want: &str) -> bool {
    matches!(e, GeometryError::NonPositive { name, value } if name == want && value <= 0.0)
}

#[test]
fn built_in_tables_reject_bad_numbers() {
    for x in BAD_FINITE {
        assert!(non_finite(Circle::new(x).unwrap_err(), "radius"));
        assert!(non_finite(Rectangle::new(x, 1.0).unwrap_err(), "l"));
        assert!(non_finite(Rectangle::new(1.0, x).unwrap_err(), "h"));
        assert!(non_finite(Stadium::new(x).unwrap_err(), "a"));
        assert!(non_finite(Sinai::new(x, 1.0).unwrap_err(), "l"));
        assert!(non_finite(Sinai::new(2.0, x).unwrap_err(), "r"));
    }
    for x in BAD_SIGN {
        assert!(non_positive(Circle::new(x).unwrap_err(), "radius"));
        assert!(non_positive(Rectangle::new(x, 1.0).unwrap_err(), "l"));
        assert!(non_positive(Rectangle::new(1.0, x).unwrap_err(), "h"));
        assert!(non_positive(Stadium::new(x).unwrap_err(), "a"));
        assert!(non_positive(Sinai::new(x, 1.0).unwrap_err(), "l"));
        assert!(non_positive(Sinai::new(2.0, x).unwrap_err(), "r"));
    }
    // The obstacle must fit strictly inside the box.
    assert_eq!(
        Sinai::new(2.0, 2.0).unwrap_err(),
        GeometryError::ObstacleTooLarge { r: 2.0, l: 2.0 }
    );
    assert_eq!(
        Sinai::new(1.0, 1.5).unwrap_err(),
        GeometryError::ObstacleTooLarge { r: 1.5, l: 1.0 }
    );
    // ... and just inside is fine, as are tiny and huge tables.
    assert!(Sinai::new(1.0, 1.0 - 1e-12).is_ok());
    assert!(Circle::new(1e-6).is_ok() && Circle::new(1e6).is_ok());
}

#[test]
fn walls_reject_bad_input() {
    let p = DVec2::new(1.0, 2.0);
    assert_eq!(
        LineSegment::new(p, p).unwrap_err(),
        GeometryError::DegenerateWall { index: 0 }
    );
    assert!(non_finite(
        LineSegment::new(DVec2::new(f64::NAN, 0.0), p).unwrap_err(),
        "start.x"
    ));
    assert!(non_finite(
        LineSegment::new(p, DVec2::new(0.0, f64::INFINITY)).unwrap_err(),
        "end.y"
    ));
    let c = DVec2::ZERO;
    for sweep in [0.0, -0.0, 7.0, -7.0, 2.0 * TAU] {
        assert!(
            matches!(ArcSegment::new(c, 1.0, 0.0, sweep), Err(GeometryError::BadSweep { sweep: s, .. }) if s == sweep),
            "sweep {sweep}"
        );
    }
    assert!(non_finite(
        ArcSegment::new(c, 1.0, 0.0, f64::NAN).unwrap_err(),
        "sweep"
    ));
    assert!(non_finite(
        ArcSegment::new(c, 1.0, f64::INFINITY, 1.0).unwrap_err(),
        "start_angle"
    ));
    assert!(non_positive(
        ArcSegment::new(c, 0.0, 0.0, 1.0).unwrap_err(),
        "radius"
    ));
    assert!(non_positive(
        ArcSegment::new(c, -2.0, 0.0, 1.0).unwrap_err(),
        "radius"
    ));
    assert!(non_finite(
        ArcSegment::new(DVec2::new(0.0, f64::NAN), 1.0, 0.0, 1.0).unwrap_err(),
        "center.y"
    ));
    // A full turn either way is fine.
    assert!(ArcSegment::new(c, 1.0, 0.0, TAU).is_ok());
    assert!(ArcSegment::new(c, 1.0, 0.0, -TAU).is_ok());
}

fn line(a: (f64, f64), b: (f64, f64)) -> Segment {
    Segment::Line(LineSegment::new(DVec2::new(a.0, a.1), DVec2::new(b.0, b.1)).unwrap())
}

fn square_ccw() -> Vec<Segment> {
    vec![
        line((0.0, 0.0), (1.0, 0.0)),
        line((1.0, 0.0), (1.0, 1.0)),
        line((1.0, 1.0), (0.0, 1.0)),
        line((0.0, 1.0), (0.0, 0.0)),
    ]
}

#[test]
fn segment_tables_reject_bad_loops() {
    assert!(SegmentTable::new(square_ccw()).is_ok());
    // Open loop: the third wall ends short of the fourth's start.
    let mut open = square_ccw();
    open[2] = line((1.0, 1.0), (0.0, 0.9));
    assert!(matches!(
        SegmentTable::new(open).unwrap_err(),
        GeometryError::OpenLoop {
            lp: 0,
            index: 2,
            ..
        }
    ));
    // Wrong orientation: the same square listed clockwise.
    let cw: Vec<Segment> = vec![
        line((0.0, 0.0), (0.0, 1.0)),
        line((0.0, 1.0), (1.0, 1.0)),
        line((1.0, 1.0), (1.0, 0.0)),
        line((1.0, 0.0), (0.0, 0.0)),
    ];
    assert!(matches!(
        SegmentTable::new(cw).unwrap_err(),
        GeometryError::WrongOrientation { lp: 0, area } if (area + 1.0).abs() < 1e-15
    ));
    // Zero area: out and back along one line (the two walls run along each
    // other: a loop of zero width).
    let flat = vec![line((0.0, 0.0), (1.0, 0.0)), line((1.0, 0.0), (0.0, 0.0))];
    assert_eq!(
        SegmentTable::new(flat).unwrap_err(),
        GeometryError::Overlap {
            first_loop: 0,
            first_index: 0,
            second_loop: 0,
            second_index: 1
        }
    );
    // A hole listed counter-clockwise (it would be a second table, not a hole).
    let hole_ccw = vec![Segment::Arc(
        ArcSegment::new(DVec2::splat(0.5), 0.2, 0.0, TAU).unwrap(),
    )];
    assert!(matches!(
        SegmentTable::with_holes(square_ccw(), vec![hole_ccw]).unwrap_err(),
        GeometryError::WrongOrientation { lp: 1, .. }
    ));
    let hole_cw = vec![Segment::Arc(
        ArcSegment::new(DVec2::splat(0.5), 0.2, 0.0, -TAU).unwrap(),
    )];
    assert!(SegmentTable::with_holes(square_ccw(), vec![hole_cw]).is_ok());
    // Too few walls.
    assert_eq!(
        SegmentTable::new(vec![]).unwrap_err(),
        GeometryError::TooFewWalls { needed: 1, got: 0 }
    );
    assert_eq!(
        SegmentTable::new(vec![line((0.0, 0.0), (1.0, 0.0))]).unwrap_err(),
        GeometryError::TooFewWalls { needed: 2, got: 1 }
    );
    assert_eq!(
        SegmentTable::with_holes(square_ccw(), vec![vec![]]).unwrap_err(),
        GeometryError::TooFewWalls { needed: 2, got: 0 }
    );
    // A single full concave circle is a valid table (a disk).
    let disk = SegmentTable::new(vec![Segment::Arc(
        ArcSegment::full_circle(DVec2::ZERO, 1.0).unwrap(),
    )]);
    assert!((disk.unwrap().perimeter() - TAU).abs() < 1e-15);
    // A half disk: arc then diameter.
    let half = SegmentTable::new(vec![
        Segment::Arc(ArcSegment::new(DVec2::ZERO, 1.0, 0.0, PI).unwrap()),
        line((-1.0, 0.0), (1.0, 0.0)),
    ]);
    assert!(half.is_ok());
}

#[test]
fn polygons_reject_bad_vertices() {
    let v = DVec2::new;
    assert_eq!(
        SegmentTable::polygon(&[v(0.0, 0.0), v(1.0, 0.0)]).unwrap_err(),
        GeometryError::TooFewWalls { needed: 3, got: 2 }
    );
    assert_eq!(
        SegmentTable::polygon(&[v(0.0, 0.0), v(1.0, 0.0), v(1.0, 0.0), v(0.0, 1.0)]).unwrap_err(),
        GeometryError::DegenerateWall { index: 1 }
    );
    assert!(matches!(
        SegmentTable::polygon(&[v(0.0, 0.0), v(f64::NAN, 0.0), v(0.0, 1.0)]).unwrap_err(),
        GeometryError::NonFinite { .. }
    ));
    assert!(matches!(
        SegmentTable::polygon(&[v(0.0, 0.0), v(0.0, 1.0), v(1.0, 0.0)]).unwrap_err(),
        GeometryError::WrongOrientation { lp: 0, .. }
    ));
    assert!(SegmentTable::polygon(&[v(0.0, 0.0), v(1.0, 0.0), v(0.0, 1.0)]).is_ok());
}

#[test]
fn table_specs_reject_bad_strings() {
    let err = |s: &str| s.parse::<Table>().unwrap_err();
    assert_eq!(
        err("hexagon"),
        TableSpecError::UnknownTable("hexagon".into())
    );
    assert_eq!(err(""), TableSpecError::UnknownTable("".into()));
    assert!(matches!(
        err("stadium:b=1"),
        TableSpecError::UnknownKey { table: "stadium", ref key, .. } if key == "b"
    ));
    assert!(matches!(
        err("circle:L=1"),
        TableSpecError::UnknownKey { table: "circle", ref key, .. } if key == "l"
    ));
    assert_eq!(err("stadium:a"), TableSpecError::BadPair("a".into()));
    assert_eq!(
        err("stadium:a=one"),
        TableSpecError::BadPair("a=one".into())
    );
    assert_eq!(err("sinai:L=2,R"), TableSpecError::BadPair("R".into()));
    assert_eq!(
        err("sinai:L=1,R=2"),
        TableSpecError::Geometry(GeometryError::ObstacleTooLarge { r: 2.0, l: 1.0 })
    );
    assert!(matches!(
        err("circle:R=-1"),
        TableSpecError::Geometry(GeometryError::NonPositive { name: "radius", .. })
    ));
    assert!(matches!(
        err("rectangle:L=nan"),
        TableSpecError::Geometry(GeometryError::NonFinite { name: "l", .. })
    ));
    assert!(matches!(
        err("stadium:a=inf"),
        TableSpecError::Geometry(GeometryError::NonFinite { name: "a", .. })
    ));
    // Every message says something.
    for e in [
        err("hexagon"),
        err("stadium:b=1"),
        err("stadium:a"),
        err("sinai:L=1,R=2"),
    ] {
        assert!(!e.to_string().is_empty());
    }
}

/// A wall end 5e-10 of the size short of the next wall's start: within the
/// closing tolerance (1e-9) but beyond a cast's (64 ε), so a ball aimed
/// at the gap used to slip out of the table. The straight wall is joined
/// onto its neighbour, and the ball hits the corner.
#[test]
fn a_gap_a_ball_could_slip_through_is_closed() {
    let mut gap = square_ccw();
    gap[3] = line((0.0, 1.0 - 5e-10), (0.0, 0.0));
    let t = SegmentTable::new(gap).unwrap();
    assert_eq!(t.walls()[3].start(), DVec2::new(0.0, 1.0));
    let from = DVec2::new(0.5, 0.5);
    let hit = t
        .cast(from, DVec2::new(0.0, 1.0 - 2.5e-10) - from)
        .expect("the ball meets a wall");
    assert!(hit.point.x.abs() < 1e-9 && (hit.point.y - 1.0).abs() < 1e-9);
    // Walls that meet to rounding are kept as given.
    let mut close = square_ccw();
    close[3] = line((0.0, 1.0 - 1e-16), (0.0, 0.0));
    let t = SegmentTable::new(close).unwrap();
    assert_eq!(t.walls()[3].start(), DVec2::new(0.0, 1.0 - 1e-16));
    // Two arcs cannot be moved: they must meet within the cast's tolerance.
    let arcs = vec![
        Segment::Arc(ArcSegment::new(DVec2::ZERO, 1.0, 0.0, PI).unwrap()),
        Segment::Arc(ArcSegment::new(DVec2::ZERO, 1.0, PI + 1e-10, PI - 1e-10).unwrap()),
    ];
    let err = SegmentTable::new(arcs).unwrap_err();
    assert!(
        matches!(err, GeometryError::OpenLoop { index: 0, .. }),
        "{err}"
    );
}

/// A disk hole of radius 1e-9 in a 4 × 4 square: its `r²` drowns in the
/// rounding of squared distances across the table and a ball flew through
/// it. Arcs below 1e-6 of the table's size are refused; 1e-5 is kept.
#[test]
fn an_arc_too_small_for_the_table_is_refused() {
    let square = |s: f64| {
        vec![
            line((0.0, 0.0), (s, 0.0)),
            line((s, 0.0), (s, s)),
            line((s, s), (0.0, s)),
            line((0.0, s), (0.0, 0.0)),
        ]
    };
    let hole = |r: f64| {
        vec![Segment::Arc(
            ArcSegment::new(DVec2::new(2.0, 2.0), r, 0.0, -TAU).unwrap(),
        )]
    };
    let err = SegmentTable::with_holes(square(4.0), vec![hole(1e-9)]).unwrap_err();
    // Named by its loop and index, with the range that works: from 1e-6
    // of the table's size (half the diagonal, 2√2).
    match err {
        GeometryError::ArcRadius {
            lp: 1,
            index: 0,
            radius,
            min,
            ..
        } => {
            assert_eq!(radius, 1e-9);
            assert!((min - 1e-6 * 8f64.sqrt()).abs() < 1e-20, "{min}");
        }
        other => panic!("expected ArcRadius of arc 0 of loop 1, got {other:?}"),
    }
    assert!(err.to_string().contains("arc 0 of loop 1"), "{err}");
    let t = SegmentTable::with_holes(square(4.0), vec![hole(1e-4)]).unwrap();
    // Aimed at the small disk, the ball meets it.
    let hit = t.cast(DVec2::new(1.0, 1.5), DVec2::new(1.0, 0.5)).unwrap();
    assert!(
        (hit.point - DVec2::new(2.0, 2.0)).length() < 2e-4,
        "{:?}",
        hit.point
    );
}

/// A square of side 1 placed 1e7 sizes from the origin: its coordinates
/// cannot resolve the walls to the casts' tolerance, so it is refused; at
/// 1e3 sizes it is kept, with a tolerance that follows the coordinates.
#[test]
fn a_table_too_far_from_the_origin_is_refused() {
    let at = |o: f64| {
        SegmentTable::polygon(&[
            DVec2::new(o, o),
            DVec2::new(o + 1.0, o),
            DVec2::new(o + 1.0, o + 1.0),
            DVec2::new(o, o + 1.0),
        ])
    };
    let err = at(1e7).unwrap_err();
    assert!(
        matches!(
            err,
            GeometryError::OutOfRange {
                name: "largest coordinate / table size",
                ..
            }
        ),
        "{err}"
    );
    // Centred: the tolerance is 64 ε of the size (half the diagonal).
    let near = at(-0.5).unwrap();
    let far = at(1e3).unwrap();
    assert_eq!(near.slack(), 64.0 * f64::EPSILON * 0.5 * 2f64.sqrt());
    assert!(far.slack() > 1e3 * near.slack());
}
