//! Wall kinds: holes and periodic walls on segment tables, their
//! validation, the Lorentz gases and their horizon, and that every wrapper
//! forwards the kinds (a wrapper that dropped them would turn holes and
//! periodic walls into mirrors, silently).

use std::f64::consts::PI;

use spinball_geometry::{
    Boundary, Built, Cell, DVec2, GeometryError, Horizon, LorentzGas, Segment, SegmentTable,
    Stadium, Table, WallKind,
};

fn unit_square() -> SegmentTable {
    SegmentTable::polygon(&[
        DVec2::new(0.0, 0.0),
        DVec2::new(1.0, 0.0),
        DVec2::new(1.0, 1.0),
        DVec2::new(0.0, 1.0),
    ])
    .unwrap()
}

#[test]
fn closed_tables_reflect_everywhere() {
    let table: Table = "stadium:a=1".parse().unwrap();
    for w in 0..4 {
        assert_eq!(table.wall_kind(w), WallKind::Reflecting);
    }
    assert!(table.lattice().is_none() && !table.has_holes());
    let square = unit_square();
    assert!(square.kinds().iter().all(WallKind::is_reflecting));
    assert!(square.shape().unwrap().is_closed());
}

#[test]
fn every_wrapper_forwards_the_kinds() {
    let cell = LorentzGas::square(1.0, 0.3).unwrap().table().unwrap();
    let holed = SegmentTable::stadium_with_hole(1.0, 1.0, 0.2).unwrap();
    fn same<B: Boundary>(a: &B, b: &SegmentTable) {
        for w in 0..b.walls().len() as u32 {
            assert_eq!(a.wall_kind(w), b.wall_kind(w), "wall {w}");
        }
        assert_eq!(a.lattice(), b.lattice());
        assert_eq!(a.has_holes(), b.has_holes());
    }
    for t in [&cell, &holed] {
        same(&t, t);
        same(&&t, t);
        same(&Built::Segments(t.clone()), t);
        let rebuilt = t.shape().unwrap().build().unwrap();
        same(&rebuilt, t);
    }
    assert!(holed.has_holes() && cell.lattice().is_some());
}

#[test]
fn the_square_cell_has_its_lattice_and_steps() {
    let cell = LorentzGas::square(2.0, 0.5).unwrap().table().unwrap();
    assert_eq!(
        cell.lattice(),
        Some([DVec2::new(2.0, 0.0), DVec2::new(0.0, 2.0)])
    );
    // Leaving through the right wall (1) moves the ball one cell in +x.
    assert_eq!(
        cell.wall_kind(1),
        WallKind::Periodic {
            partner: 3,
            shift: DVec2::new(2.0, 0.0),
            step: Cell::new(1, 0)
        }
    );
    assert_eq!(
        cell.wall_kind(2),
        WallKind::Periodic {
            partner: 0,
            shift: DVec2::new(0.0, 2.0),
            step: Cell::new(0, 1)
        }
    );
    assert_eq!(cell.wall_kind(4), WallKind::Reflecting);
    assert!((cell.area() - (4.0 - PI * 0.25)).abs() < 1e-12);
}

#[test]
fn the_triangular_cell_is_a_rhombus_minus_one_disk() {
    let (w, r) = (1.0, 0.45);
    let cell = LorentzGas::triangular(w, r).unwrap().table().unwrap();
    let h = 0.5 * 3f64.sqrt() * w;
    // Area: the rhombus w·h minus the four corner pieces (one disk).
    assert!(
        (cell.area() - (w * h - PI * r * r)).abs() < 1e-12,
        "{}",
        cell.area()
    );
    let [b1, b2] = cell.lattice().unwrap();
    assert!((b1 - DVec2::new(w, 0.0)).length() < 1e-15);
    assert!((b2 - DVec2::new(0.5 * w, h)).length() < 1e-15);
    let periodic: Vec<u32> = (0..8)
        .filter(|&i| cell.wall_kind(i).is_periodic())
        .collect();
    assert_eq!(periodic, [0, 2, 4, 6]);
    // The bottom side's partner is the top, one cell down along b2.
    let WallKind::Periodic { partner, step, .. } = cell.wall_kind(0) else {
        panic!("periodic")
    };
    assert_eq!((partner, step), (4, Cell::new(0, -1)));
}

#[test]
fn the_horizon_is_the_closed_form() {
    let corridor = |width| Horizon::Infinite {
        direction: DVec2::X,
        width,
    };
    for r in [0.01, 0.3, 0.49] {
        assert_eq!(
            LorentzGas::square(1.0, r).unwrap().horizon(),
            corridor(1.0 - 2.0 * r)
        );
    }
    // Triangular: finite iff √3 w/4 ≤ R < w/2 (√3/4 = 0.4330…).
    let edge = 3f64.sqrt() / 4.0;
    assert_eq!(
        LorentzGas::triangular(1.0, 0.43).unwrap().horizon(),
        corridor(0.5 * 3f64.sqrt() - 0.86)
    );
    assert!(
        LorentzGas::triangular(1.0, edge)
            .unwrap()
            .horizon()
            .is_finite()
    );
    assert!(
        LorentzGas::triangular(2.0, 0.9)
            .unwrap()
            .horizon()
            .is_finite()
    );
}

#[test]
fn a_disk_that_fills_the_cell_is_refused() {
    for r in [0.5, 0.7] {
        for gas in [LorentzGas::square(1.0, r), LorentzGas::triangular(1.0, r)] {
            assert!(matches!(gas, Err(GeometryError::NoRoom { .. })), "{gas:?}");
        }
    }
    let text = LorentzGas::square(1.0, 0.5).unwrap_err().to_string();
    assert!(text.contains("(0, "), "{text}");
}

#[test]
fn partners_must_be_facing_translates() {
    let square = unit_square();
    let not = |r: Result<SegmentTable, GeometryError>| {
        matches!(r, Err(GeometryError::NotPartners { .. }))
    };
    // Adjacent walls are not parallel; a wall is not its own partner.
    assert!(not(square.clone().with_periodic(0, 1)));
    assert!(not(square.clone().with_periodic(0, 0)));
    // A trapezoid's parallel sides of different lengths are not translates.
    let trapezoid = SegmentTable::polygon(&[
        DVec2::new(0.0, 0.0),
        DVec2::new(2.0, 0.0),
        DVec2::new(1.5, 1.0),
        DVec2::new(0.5, 1.0),
    ])
    .unwrap();
    assert!(not(trapezoid.with_periodic(0, 2)));
    // A curved wall cannot be periodic.
    let cell = LorentzGas::square(1.0, 0.2).unwrap().table().unwrap();
    assert!(matches!(
        cell.with_periodic(4, 0),
        Err(GeometryError::KindOverlap { .. })
    ));
    let holed = SegmentTable::with_holes(
        unit_square().walls().to_vec(),
        vec![vec![Segment::Arc(
            spinball_geometry::ArcSegment::new(DVec2::splat(0.5), 0.2, 0.0, -2.0 * PI).unwrap(),
        )]],
    )
    .unwrap();
    assert!(not(holed.with_periodic(4, 0)));
    // Missing walls.
    assert!(matches!(
        unit_square().with_hole(7),
        Err(GeometryError::NoSuchWall { wall: 7, walls: 4 })
    ));
}

#[test]
fn holes_may_not_overlap_holes_or_periodic_walls() {
    let square = unit_square().with_hole(1).unwrap();
    assert!(matches!(
        square.clone().with_hole(1),
        Err(GeometryError::KindOverlap { .. })
    ));
    assert!(matches!(
        square.clone().with_periodic(1, 3),
        Err(GeometryError::KindOverlap { .. })
    ));
    let periodic = unit_square().with_periodic(0, 2).unwrap();
    assert!(matches!(
        periodic.clone().with_hole(2),
        Err(GeometryError::KindOverlap { .. })
    ));
    // An opening on a periodic wall, or on a hole, is refused too.
    assert!(matches!(
        periodic.with_hole_at(0.5, 0.1),
        Err(GeometryError::KindOverlap { .. })
    ));
    assert!(matches!(
        square.with_hole_at(1.5, 0.1),
        Err(GeometryError::KindOverlap { .. })
    ));
}

#[test]
fn an_opened_stadium_keeps_its_walls_and_parametrisation() {
    let closed = Stadium::new(1.0).unwrap();
    // A hole of length 0.2 in the middle of the right cap (s = 2 + π/2).
    let s = 2.0 + 0.5 * PI;
    let open = SegmentTable::stadium_with_hole(1.0, s, 0.2).unwrap();
    assert!((open.perimeter() - closed.perimeter()).abs() < 1e-12);
    assert!((open.area() - closed.area()).abs() < 1e-12);
    assert_eq!(open.walls().len(), 6);
    assert_eq!(open.wall_kind(2), WallKind::Hole);
    let hit = open.hit_at(s).unwrap();
    assert_eq!(hit.wall, 2);
    assert!((hit.point - DVec2::new(2.0, 0.0)).length() < 1e-12);
    // Same contact as the closed stadium's at the same s.
    let c = closed.hit_at(s + 0.05).unwrap();
    let o = open.hit_at(s + 0.05).unwrap();
    assert!((c.point - o.point).length() < 1e-12 && o.wall == 2);
    // A table with a hole is never the same table as the closed one.
    let closed_segments = SegmentTable::new(open.walls().to_vec())
        .unwrap()
        .with_name(open.name().unwrap());
    assert_ne!(open.shape(), closed_segments.shape());
    assert!(open.shape().unwrap().to_string().contains("1 hole"));
}

#[test]
fn holes_across_a_junction_and_sizes_out_of_range_are_refused() {
    // The bottom flat ends at s = 2: a hole from 1.9 to 2.1 spans two walls.
    assert!(matches!(
        SegmentTable::stadium_with_hole(1.0, 2.0, 0.2),
        Err(GeometryError::OutOfRange { name: "hole", .. })
    ));
    assert!(SegmentTable::circle_with_hole(1.0, 0.0, 7.0).is_err());
    assert!(SegmentTable::circle_with_hole(1.0, 0.0, -0.1).is_err());
    assert!(SegmentTable::sinai_with_hole(2.0, 1.0, 1.0, f64::NAN).is_err());
    assert!(matches!(
        SegmentTable::sinai_with_hole(1.0, 1.0, 1.0, 0.1),
        Err(GeometryError::ObstacleTooLarge { .. })
    ));
}

#[test]
fn the_circle_and_sinai_with_a_hole() {
    let circle = SegmentTable::circle_with_hole(1.0, 0.3, 0.5).unwrap();
    assert_eq!(circle.walls().len(), 3);
    assert_eq!(circle.wall_kind(1), WallKind::Hole);
    // The hole's middle is at polar angle 0.3.
    let hit = circle.hit_at(PI).unwrap();
    assert!((hit.point - DVec2::from_angle(0.3)).length() < 1e-12);
    assert!((circle.perimeter() - 2.0 * PI).abs() < 1e-12);
    // A Sinai table with a hole on its bottom wall (s in [0, 4]).
    let sinai = SegmentTable::sinai_with_hole(2.0, 1.0, 2.0, 0.4).unwrap();
    assert_eq!(sinai.wall_kind(1), WallKind::Hole);
    assert_eq!(sinai.walls().len(), 7);
    let hole = sinai.hit_at(2.0).unwrap();
    assert!((hole.point - DVec2::new(0.0, -2.0)).length() < 1e-12);
    let ends = (sinai.walls()[1].start(), sinai.walls()[1].end());
    assert!(
        (ends.0 - DVec2::new(-0.2, -2.0)).length() < 1e-15,
        "{ends:?}"
    );
    assert!(
        (ends.1 - DVec2::new(0.2, -2.0)).length() < 1e-15,
        "{ends:?}"
    );
}
