//! The contract of `Boundary::cast` on random rays (proptest): the first wall
//! ahead, met from the table side, with a unit inward normal, `t × n = +1`,
//! the documented curvature, and a Birkhoff `s` that maps back to the point.

mod common;

use common::{birkhoff_point, signed_distance, tables};
use proptest::prelude::*;
use spinball_geometry::{Boundary, DVec2, Table};

/// The documented signed curvature of each wall: 0 flat, −1/R concave, +1/R convex.
fn documented_curvature(t: &Table, wall: u32) -> f64 {
    match t {
        Table::Circle(c) => -1.0 / c.radius(),
        Table::Rectangle(_) => 0.0,
        Table::Stadium(_) => [0.0, -1.0, 0.0, -1.0][wall as usize],
        Table::Sinai(s) => {
            if wall == 4 {
                1.0 / s.r()
            } else {
                0.0
            }
        }
    }
}

fn check_ray(t: &Table, origin: DVec2, v: DVec2) -> Result<(), TestCaseError> {
    let scale = t.length_scale();
    let hit = t.cast(origin, v);
    prop_assert!(hit.is_some(), "{t}: no wall from {origin:?} along {v:?}");
    let hit = hit.unwrap();
    // Flight time non-negative and the point where the ray says (1e-10 of the
    // size: the roots are computed stably, so only a few ulps are expected;
    // rays here are never closer to tangent than rounding allows to matter).
    prop_assert!(hit.time >= 0.0);
    prop_assert!(
        (origin + v * hit.time - hit.point).length() < 1e-10 * scale,
        "{t}: point {:?} vs ray {:?}",
        hit.point,
        origin + v * hit.time
    );
    // On the wall: snapped contacts are within a few ulps of the size.
    prop_assert!(signed_distance(t, hit.point).abs() < 1e-13 * scale);
    // Unit normal pointing in: a step along n stays inside, a step against it
    // leaves (1e-7 of the size, far above rounding, far below any feature).
    prop_assert!((hit.normal.length() - 1.0).abs() < 4.0 * f64::EPSILON);
    let step = 1e-7 * scale;
    prop_assert!(signed_distance(t, hit.point + hit.normal * step) > 0.0);
    prop_assert!(signed_distance(t, hit.point - hit.normal * step) < 0.0);
    // Met from the table side (the contract), tangent × normal = +z exactly.
    prop_assert!(v.dot(hit.normal) < 0.0);
    prop_assert!((hit.tangent().perp_dot(hit.normal) - 1.0).abs() < 4.0 * f64::EPSILON);
    prop_assert!(hit.tangent().dot(hit.normal).abs() < 1e-16);
    prop_assert_eq!(hit.curvature, documented_curvature(t, hit.wall));
    prop_assert_eq!(hit.is_curved(), hit.curvature != 0.0);
    // The first wall: the flight segment stays inside the table (checked at 64
    // points; in the Sinai table this is what says the ray did not pass
    // through the obstacle). Tolerance: rounding of the positions, 1e-13 scale.
    for k in 1..64 {
        let p = origin + v * (hit.time * k as f64 / 64.0);
        prop_assert!(
            signed_distance(t, p) > -1e-13 * scale,
            "{t}: left the table at {p:?}"
        );
    }
    // The Birkhoff s maps back to this point, wall and normal through the
    // documented parametrisation (1e-12 of the size: atan2 and a few roundings).
    let s = hit.s();
    prop_assert!(s >= 0.0 && s < t.perimeter());
    let (p, n, wall) = birkhoff_point(t, s);
    prop_assert!(
        (p - hit.point).length() < 1e-12 * scale,
        "{t}: s = {s} maps to {p:?}"
    );
    // At a corner the two walls share the point; the wall id and normal are
    // only checked away from corners (1e-9 of the size).
    let (_, _, wm) = birkhoff_point(t, (s - 1e-9 * scale).max(0.0));
    let (_, _, wp) = birkhoff_point(t, (s + 1e-9 * scale) % t.perimeter());
    if wm == wp {
        prop_assert_eq!(hit.wall, wall);
        prop_assert!((hit.normal - n).length() < 1e-12);
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: 2000,
        // Origins are drawn in the box and kept if inside (at least 3 in 4 are).
        max_global_rejects: 20_000,
        ..ProptestConfig::default()
    })]

    /// Random origins (uniform in the box, kept if inside) and directions.
    #[test]
    fn random_casts_obey_the_contract(
        which in 0usize..10,
        fx in 0.0f64..1.0,
        fy in 0.0f64..1.0,
        angle in 0.0f64..std::f64::consts::TAU,
        speed in 0.1f64..10.0,
    ) {
        let t = tables()[which];
        let b = t.aabb();
        let origin = b.min + (b.max - b.min) * DVec2::new(fx, fy);
        prop_assume!(signed_distance(&t, origin) > 1e-9 * t.length_scale());
        check_ray(&t, origin, DVec2::from_angle(angle) * speed)?;
    }

    /// Rays from points on the walls (where every collision starts), in any
    /// direction that points into the table.
    #[test]
    fn casts_from_the_wall_obey_the_contract(
        which in 0usize..10,
        f in 0.0f64..1.0,
        turn in -1.5f64..1.5,
    ) {
        let t = tables()[which];
        let (p, n, _) = birkhoff_point(&t, f * t.perimeter());
        let v = DVec2::from_angle(turn).rotate(n);
        check_ray(&t, p, v)?;
    }
}
