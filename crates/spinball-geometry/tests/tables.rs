//! The tables against closed forms and against their own documentation:
//! perimeters, bounding boxes, `contains`, the Birkhoff parametrisation of
//! each table, and the provided (default) trait methods against the exact
//! overrides.

mod common;

use std::f64::consts::PI;

use common::{
    CastOnly, birkhoff_point, in_mushroom, mushroom, segment_point, segment_sinai, signed_distance,
    tables, walls_distance,
};
use rand::{Rng, SeedableRng};
use rand_pcg::Pcg64;
use spinball_geometry::{Boundary, Circle, DVec2, Rectangle, SegmentTable, Sinai, Stadium, Table};

/// Closed-form perimeter from the table's parameters
/// ([`docs/PHYSICS.md`](https://github.com/spinball/spinball/blob/main/docs/PHYSICS.md#the-four-tables), §II.A of the paper).
fn closed_form_perimeter(t: &Table) -> f64 {
    match t {
        Table::Circle(c) => 2.0 * PI * c.radius(),
        Table::Rectangle(r) => 4.0 * (r.l() + r.h()),
        Table::Stadium(s) => 4.0 * s.a() + 2.0 * PI,
        Table::Sinai(s) => 8.0 * s.l() + 2.0 * PI * s.r(),
    }
}

fn exact_box(t: &Table) -> (DVec2, DVec2) {
    match t {
        Table::Circle(c) => (DVec2::splat(-c.radius()), DVec2::splat(c.radius())),
        Table::Rectangle(r) => (DVec2::new(-r.l(), -r.h()), DVec2::new(r.l(), r.h())),
        Table::Stadium(s) => (DVec2::new(-s.a() - 1.0, -1.0), DVec2::new(s.a() + 1.0, 1.0)),
        Table::Sinai(s) => (DVec2::splat(-s.l()), DVec2::splat(s.l())),
    }
}

#[test]
fn perimeters_match_closed_forms() {
    // The overrides are closed forms themselves: agreement to a few ulps.
    for t in tables() {
        let want = closed_form_perimeter(&t);
        assert!(
            (t.perimeter() - want).abs() <= 4.0 * f64::EPSILON * want,
            "{t}: {} vs {want}",
            t.perimeter()
        );
    }
    // Segment tables sum their wall lengths.
    let tri = SegmentTable::polygon(&[
        DVec2::new(0.0, 0.0),
        DVec2::new(3.0, 0.0),
        DVec2::new(0.0, 4.0),
    ])
    .unwrap();
    assert!((tri.perimeter() - 12.0).abs() < 1e-14);
    // Mushroom: stem bottom 0.6, stem sides 2 × 1, shoulders 2 × 0.7, cap π.
    assert!((mushroom().perimeter() - (4.0 + PI)).abs() < 1e-14);
    assert!((segment_sinai(2.0, 1.0).perimeter() - (16.0 + 2.0 * PI)).abs() < 1e-13);
}

#[test]
fn exact_boxes_and_length_scales() {
    for t in tables() {
        let (min, max) = exact_box(&t);
        let b = t.aabb();
        assert_eq!((b.min, b.max), (min, max), "{t}");
        // length_scale is documented as half the box diagonal.
        assert!((t.length_scale() - 0.5 * (max - min).length()).abs() < 1e-15 * t.length_scale());
    }
    // The mushroom box: x in [-1, 1], y in [-1, 1] (stem bottom to cap top).
    let m = mushroom().aabb();
    assert!((m.min - DVec2::new(-1.0, -1.0)).length() < 1e-15);
    assert!((m.max - DVec2::new(1.0, 1.0)).length() < 1e-15);
}

#[test]
fn default_perimeter_and_box_match_exact_overrides() {
    for t in tables() {
        let fan = CastOnly(t);
        let (min, max) = exact_box(&t);
        let size = max - min;
        // Default box: the fan's hull padded by 1% of its size on each side
        // (documented). It must cover the exact box, and exceed it by no more
        // than the pad plus the fan's angular gap (tables here span < 10 units,
        // 2π/4096 × 10 < 0.02, so 2% of the size is a safe bound).
        let b = fan.aabb();
        assert!(b.min.x <= min.x && b.min.y <= min.y, "{t}: {b:?}");
        assert!(b.max.x >= max.x && b.max.y >= max.y, "{t}: {b:?}");
        assert!(
            (min - b.min).max_element() <= 0.02 * size.max_element(),
            "{t}: {b:?}"
        );
        assert!(
            (b.max - max).max_element() <= 0.02 * size.max_element(),
            "{t}: {b:?}"
        );

        // Default perimeter: the polygon through 4096 fan hits. It is only
        // meaningful for tables star-shaped about the reference point (the
        // origin): the Sinai table is not (the origin is inside the obstacle,
        // so the fan never sees it), and is left out.
        let exact = t.perimeter();
        let tol = match t {
            // Chord polygon of a smooth curve (documented: about 1e-6): a chord
            // of length c on a circle of radius R is short by c³/(24R²), so the
            // relative error is at most (c/R)²/24 with c ≤ ρ·2π/4096, ρ the
            // farthest wall point (circle: ρ = R, 1e-7; stadium: ρ = a + 1,
            // 2.5e-6 at a = 4; its flats are exact). Twice that bound.
            Table::Circle(_) => 2.0 * (2.0 * PI / 4096.0_f64).powi(2) / 24.0,
            Table::Stadium(s) => 2.0 * ((s.a() + 1.0) * 2.0 * PI / 4096.0).powi(2) / 24.0,
            // Each corner is cut by one chord of length about ρ·2π/4096 (ρ ≤ 1.8
            // the corner's distance from the centre), losing at most (2 − √2) of
            // it: 4 corners × 0.6 × 2.8e-3 ≈ 7e-3 absolute on a perimeter ≥ 8.
            Table::Rectangle(_) => 1e-3,
            Table::Sinai(_) => continue,
        };
        let got = fan.perimeter();
        assert!(
            got <= exact * (1.0 + 1e-12),
            "{t}: inscribed polygon {got} > {exact}"
        );
        assert!(
            (got - exact).abs() <= tol * exact,
            "{t}: fan perimeter {got} vs exact {exact}"
        );
    }
}

/// A seeded stream of points in the table's box enlarged by 20%, skipping
/// points within `margin` of the wall (where the answer is a rounding choice).
fn points_near<F: Fn(DVec2) -> f64>(
    rng: &mut Pcg64,
    min: DVec2,
    max: DVec2,
    n: usize,
    margin: f64,
    distance: F,
) -> Vec<DVec2> {
    let c = 0.5 * (min + max);
    let half = 0.6 * (max - min);
    let mut out = Vec::with_capacity(n);
    while out.len() < n {
        let p = c + half * DVec2::new(rng.random_range(-1.0..1.0), rng.random_range(-1.0..1.0));
        if distance(p).abs() > margin {
            out.push(p);
        }
    }
    out
}

#[test]
fn contains_overrides_are_exact() {
    // The overrides against the independent signed distance (test helper),
    // away from the walls by 1e-9 of the table size: the overrides' own
    // tolerance is 64 ε times the size, far below that.
    let mut rng = Pcg64::seed_from_u64(11);
    for t in tables() {
        let (min, max) = exact_box(&t);
        let margin = 1e-9 * t.length_scale();
        let pts = points_near(&mut rng, min, max, 20_000, margin, |p| {
            signed_distance(&t, p)
        });
        for p in pts {
            assert_eq!(t.contains(p), signed_distance(&t, p) > 0.0, "{t} at {p:?}");
        }
    }
}

#[test]
fn default_contains_agrees_with_overrides() {
    // The provided chord test through `cast` alone against the exact override,
    // on points farther than 1e-6 of the table size from any wall (the chord
    // test's own tolerance is 1e-9 of the size). Each default call costs a
    // 4096-ray fan (through `length_scale`), so a few hundred points a table.
    let mut rng = Pcg64::seed_from_u64(12);
    for t in tables() {
        let fan = CastOnly(t);
        let (min, max) = exact_box(&t);
        let margin = 1e-6 * t.length_scale();
        for p in points_near(&mut rng, min, max, 300, margin, |p| signed_distance(&t, p)) {
            assert_eq!(fan.contains(p), t.contains(p), "{t} at {p:?}");
        }
    }
}

#[test]
fn segment_tables_contain_what_they_should() {
    // Segment tables use the default `contains`; they override the box, so
    // points are cheap: many of them, against exact membership.
    let mut rng = Pcg64::seed_from_u64(13);
    let m = mushroom();
    let b = m.aabb();
    for p in points_near(&mut rng, b.min, b.max, 20_000, 1e-9, |p| {
        walls_distance(&m, p)
    }) {
        assert_eq!(m.contains(p), in_mushroom(p), "mushroom at {p:?}");
    }
    let built = segment_sinai(2.0, 1.0);
    let sinai = Sinai::new(2.0, 1.0).unwrap();
    let b = built.aabb();
    for p in points_near(&mut rng, b.min, b.max, 20_000, 1e-9, |p| {
        walls_distance(&built, p)
    }) {
        assert_eq!(
            built.contains(p),
            sinai.contains(p),
            "Sinai from segments at {p:?}"
        );
    }
    let square = SegmentTable::polygon(&[
        DVec2::new(-1.0, -1.0),
        DVec2::new(1.0, -1.0),
        DVec2::new(1.0, 1.0),
        DVec2::new(-1.0, 1.0),
    ])
    .unwrap();
    let rect = Rectangle::square();
    for p in points_near(&mut rng, b.min, b.max, 20_000, 1e-9, |p| {
        walls_distance(&square, p)
    }) {
        assert_eq!(square.contains(p), rect.contains(p), "square at {p:?}");
    }
}

/// Cast from just inside the wall point `p` straight at it along `-n`; the hit
/// must be `p` itself.
fn cast_at<B: Boundary>(t: &B, p: DVec2, n: DVec2, scale: f64) -> spinball_geometry::Hit {
    let d = 1e-4 * scale;
    t.cast(p + n * d, -n).expect("a wall straight ahead")
}

#[test]
fn birkhoff_parametrisation_is_as_documented() {
    // Walk each table's boundary at 4000 values of s (midpoints, so no sample
    // sits exactly on a corner), using the parametrisation stated in each
    // table's docs (test helper `birkhoff_point`), and check that casting at
    // the wall point returns that point, that wall, that inward normal and
    // that s. Tolerance 1e-12 of the table size: a handful of roundings of
    // O(size) quantities (plus one atan2 on arcs).
    for t in tables() {
        let per = t.perimeter();
        let scale = t.length_scale();
        let tol = 1e-12 * scale;
        let n = 4000;
        for k in 0..n {
            let sigma = per * (k as f64 + 0.5) / n as f64;
            let (p, normal, wall) = birkhoff_point(&t, sigma);
            let hit = cast_at(&t, p, normal, scale);
            assert_eq!(hit.wall, wall, "{t} at s = {sigma}");
            assert!(
                (hit.point - p).length() < tol,
                "{t} at s = {sigma}: {:?}",
                hit.point
            );
            assert!((hit.normal - normal).length() < 1e-12, "{t} at s = {sigma}");
            let s = hit.s();
            assert!((0.0..per).contains(&s), "{t}: s = {s} outside [0, {per})");
            assert!((s - sigma).abs() < tol, "{t}: s = {s}, expected {sigma}");
            // Birkhoff (s, v∥) for a ball arriving along -n: v∥ = 0.
            let (bs, vpar) = t.birkhoff(&hit, -normal);
            assert_eq!(bs, s);
            assert!(vpar.abs() < 1e-12);
        }
    }
}

#[test]
fn birkhoff_s_is_continuous_across_junctions_and_wraps_once() {
    // At every junction between walls (and at the s = 0 point) the arc length
    // on either side, 1e-9 away, must differ by 2e-9 (continuity), except at
    // s = 0 where it wraps by exactly the perimeter.
    for t in tables() {
        let per = t.perimeter();
        let scale = t.length_scale();
        let junctions: Vec<f64> = match t {
            Table::Circle(_) => vec![],
            Table::Rectangle(r) => vec![
                2.0 * r.l(),
                2.0 * (r.l() + r.h()),
                4.0 * r.l() + 2.0 * r.h(),
            ],
            Table::Stadium(s) => {
                let a = s.a();
                vec![2.0 * a, 2.0 * a + PI, 4.0 * a + PI]
            }
            Table::Sinai(s) => vec![2.0 * s.l(), 4.0 * s.l(), 6.0 * s.l()],
        };
        let eps = 1e-9;
        for j in junctions {
            let (p0, n0, _) = birkhoff_point(&t, j - eps);
            let (p1, n1, _) = birkhoff_point(&t, j + eps);
            let s0 = cast_at(&t, p0, n0, scale).s();
            let s1 = cast_at(&t, p1, n1, scale).s();
            // 1e-12 of the size, as above.
            assert!(
                (s1 - s0 - 2.0 * eps).abs() < 1e-12 * scale,
                "{t} at {j}: {s0} {s1}"
            );
        }
        let (p0, n0, _) = birkhoff_point(&t, per - eps);
        let (p1, n1, _) = birkhoff_point(&t, eps);
        let s0 = cast_at(&t, p0, n0, scale).s();
        let s1 = cast_at(&t, p1, n1, scale).s();
        assert!(s0 < per && s1 >= 0.0, "{t}: {s0} {s1}");
        assert!(
            (s0 + 2.0 * eps - per - s1).abs() < 1e-12 * scale,
            "{t}: {s0} {s1}"
        );
    }
    // The Sinai obstacle: s runs clockwise from (r, 0), so just below (r, 0)
    // is just above 8l and just above (r, 0) is just below the perimeter.
    let t = Table::from(Sinai::new(2.0, 1.0).unwrap());
    let below = DVec2::from_angle(-1e-9);
    let above = DVec2::from_angle(1e-9);
    let sb = cast_at(&t, below, below, 2.0).s();
    let sa = cast_at(&t, above, above, 2.0).s();
    assert!((sb - (16.0 + 1e-9)).abs() < 1e-12, "{sb}");
    assert!((sa - (16.0 + 2.0 * PI - 1e-9)).abs() < 1e-12, "{sa}");
}

#[test]
fn segment_tables_walk_their_walls_in_order() {
    // Documented: wall ids are positions in the outer loop then the holes;
    // s runs along the walls in that order from the start of wall 0.
    for table in [mushroom(), segment_sinai(2.0, 1.0), segment_sinai(1.0, 0.3)] {
        let scale = table.length_scale();
        let mut base = 0.0;
        for (id, w) in table.walls().iter().enumerate() {
            for k in 0..50 {
                let f = (k as f64 + 0.5) / 50.0;
                let (p, n) = segment_point(w, f);
                let hit = cast_at(&table, p, n, scale);
                assert_eq!(hit.wall as usize, id);
                assert!((hit.point - p).length() < 1e-12 * scale);
                assert!((hit.normal - n).length() < 1e-12);
                assert_eq!(hit.curvature, w.curvature());
                assert!((hit.s() - (base + f * w.length())).abs() < 1e-12 * scale);
            }
            base += w.length();
        }
        assert!((base - table.perimeter()).abs() < 1e-12 * scale);
    }
}

#[test]
fn table_specs_round_trip_and_default_to_the_paper() {
    for t in tables() {
        let back: Table = t.to_string().parse().unwrap();
        assert_eq!(back, t);
    }
    let t: Table = "SINAI".parse().unwrap();
    assert_eq!(t, Table::Sinai(Sinai::new(2.0, 1.0).unwrap()));
    let t: Table = " stadium : A = 2 ".parse().unwrap();
    assert_eq!(t, Table::Stadium(Stadium::new(2.0).unwrap()));
    let t: Table = "rectangle:h=0.5".parse().unwrap();
    assert_eq!(t, Table::Rectangle(Rectangle::new(1.0, 0.5).unwrap()));
    let t: Table = "circle".parse().unwrap();
    assert_eq!(t, Table::Circle(Circle::unit()));
    assert_eq!(t.name(), "circle");
}

#[test]
fn corner_and_junction_rules() {
    // Rectangle corner (documented: lower wall id first, then the other wall
    // with zero flight time). Aimed exactly at (l, h) = (1.5, 1): right (1)
    // and top (2) tie at t = 1; right wins.
    let r = Rectangle::new(1.5, 1.0).unwrap();
    let hit = r.cast(DVec2::new(0.5, 0.0), DVec2::new(1.0, 1.0)).unwrap();
    assert_eq!(hit.wall, 1);
    assert_eq!(hit.time, 1.0);
    assert_eq!(hit.point, DVec2::new(1.5, 1.0));
    // Reflected off the right wall the ball still moves into the top wall,
    // which it meets at once.
    let again = r.cast(hit.point, DVec2::new(-1.0, 1.0)).unwrap();
    assert_eq!((again.wall, again.time), (2, 0.0));
    assert_eq!(again.point, DVec2::new(1.5, 1.0));
    // Bottom-left corner: bottom (0) beats left (3).
    let hit = r
        .cast(DVec2::new(-0.5, 0.0), DVec2::new(-1.0, -1.0))
        .unwrap();
    assert_eq!((hit.wall, hit.point), (0, DVec2::new(-1.5, -1.0)));

    // Stadium junction (a, 1): the flat wall takes a crossing of y = 1 with
    // |x| <= a (within 64 ε (a + 1)); just beyond, the cap does. The normal
    // is continuous there: (0, -1) from both sides to rounding.
    let s = Stadium::new(1.0).unwrap();
    let flat = s.cast(DVec2::ZERO, DVec2::new(1.0, 1.0)).unwrap();
    assert_eq!(flat.wall, 2);
    assert_eq!(flat.point, DVec2::new(1.0, 1.0));
    let cap = s.cast(DVec2::ZERO, DVec2::new(1.0 + 1e-9, 1.0)).unwrap();
    assert_eq!(cap.wall, 1);
    assert!((cap.point - DVec2::new(1.0, 1.0)).length() < 1e-8);
    assert!(
        (cap.normal - flat.normal).length() < 1e-4,
        "{:?}",
        cap.normal
    );
    // Just before the junction, the flat wall.
    let before = s.cast(DVec2::ZERO, DVec2::new(1.0 - 1e-9, 1.0)).unwrap();
    assert_eq!(before.wall, 2);
}

#[test]
fn sampled_points_are_inside() {
    // sample_interior draws by rejection from the box: every point inside
    // (exact test helper, margin 0), and with shrink 0.99 inside the table
    // shrunk about the box centre; the draw is uniform, so the share of points
    // with x < centre is ½ within 4 standard errors (√(¼/n)).
    let mut rng = Pcg64::seed_from_u64(21);
    for t in tables() {
        let n = 4000;
        let mut left = 0usize;
        for _ in 0..n {
            let p = t.sample_interior(&mut rng, 1.0);
            assert!(signed_distance(&t, p) >= 0.0, "{t}: {p:?}");
            left += usize::from(p.x < 0.0);
            let q = t.sample_interior(&mut rng, 0.99);
            assert!(t.contains_shrunk(q, 0.99), "{t}: {q:?}");
            assert!(signed_distance(&t, q) > 0.0, "{t}: {q:?}");
        }
        let share = left as f64 / n as f64;
        assert!(
            (share - 0.5).abs() < 4.0 * (0.25 / n as f64).sqrt(),
            "{t}: {share}"
        );
    }
}
