//! The test harness that holds every lane table to its scalar cast.
//!
//! Each table's tests call [`check`]: random rays from inside the table,
//! from the wall just hit in a random inward direction, and grazing along
//! it, plus the table's special rays (corners, junctions, tangents), each
//! cast by the lane table on one `f64` lane and by [`Boundary::cast`].

use rand::{Rng, SeedableRng};
use rand_pcg::Pcg64;
use spinball_geometry::{Boundary, DVec2, Hit};

use super::Geom;

/// The lane cast (one `f64` lane) against the scalar cast: same wall,
/// bitwise the same time, point and normal (`==`, so up to the sign of
/// a zero); NaN time exactly where the scalar has no hit.
pub(super) fn agree<T: Boundary, G: Geom>(table: &T, g: &G, o: DVec2, v: DVec2) {
    let h = g.cast::<f64>(o.x, o.y, v.x, v.y);
    match table.cast(o, v) {
        Some(Hit {
            time,
            point,
            normal,
            curvature,
            wall,
            ..
        }) => {
            let what = format!("from {o:?} along {v:?}");
            assert_eq!(h.wall, f64::from(wall), "wall {what}");
            assert_eq!(h.time, time, "time {what}");
            assert_eq!((h.px, h.py), (point.x, point.y), "point {what}");
            assert_eq!((h.nx, h.ny), (normal.x, normal.y), "normal {what}");
            assert_eq!(h.curvature, curvature, "curvature {what}");
        }
        None => assert!(h.time.is_nan(), "no scalar hit from {o:?} along {v:?}"),
    }
}

/// Random rays from inside and from the walls, plus the given special ones.
pub(super) fn check<T: Boundary, G: Geom>(table: &T, g: &G, special: &[(DVec2, DVec2)]) {
    check_n(table, g, special, 20_000);
}

/// [`check`] with `n` random rays.
pub(super) fn check_n<T: Boundary, G: Geom>(
    table: &T,
    g: &G,
    special: &[(DVec2, DVec2)],
    n: usize,
) {
    for &(o, v) in special {
        agree(table, g, o, v);
    }
    let mut rng = Pcg64::seed_from_u64(11);
    for _ in 0..n {
        let o = table.sample_interior(&mut rng, 1.0);
        let v = DVec2::from_angle(rng.random::<f64>() * std::f64::consts::TAU)
            * (0.1 + rng.random::<f64>());
        agree(table, g, o, v);
        // From the wall just hit, in a random inward direction.
        if let Some(hit) = table.cast(o, v) {
            let w =
                DVec2::from_angle(rng.random::<f64>() * std::f64::consts::PI).rotate(hit.tangent());
            agree(table, g, hit.point, w);
            // Grazing: almost along the wall.
            let eps = 10f64.powi(-rng.random_range(3..16));
            agree(table, g, hit.point, hit.tangent() + hit.normal * eps);
            agree(table, g, hit.point, -hit.tangent() + hit.normal * eps);
        }
    }
}

pub(super) fn d(x: f64, y: f64) -> DVec2 {
    DVec2::new(x, y)
}
