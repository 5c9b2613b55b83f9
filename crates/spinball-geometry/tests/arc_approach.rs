//! `ArcSegment::approach` and `land`: an arc's flight time as an undivided
//! fraction over `|v|²`, which roots count (a root behind the ball only on
//! the circle to rounding), the coverage test at the arc's ends, and the
//! landed contact.

use std::f64::consts::{FRAC_PI_2, PI, TAU};

use proptest::prelude::*;
use spinball_geometry::{ArcSegment, DVec2};

fn d(x: f64, y: f64) -> DVec2 {
    DVec2::new(x, y)
}

/// The right half of the unit circle, concave (the ball inside).
fn right_cap() -> ArcSegment {
    ArcSegment::new(DVec2::ZERO, 1.0, -FRAC_PI_2, PI).unwrap()
}

const SLACK: f64 = 1e-12;

#[test]
fn concave_exit_ahead_is_a_fraction_over_the_speed_squared() {
    // From the centre along +x at speed 2: the exit (1, 0) after t = 1/2.
    let a = right_cap()
        .approach(DVec2::ZERO, d(2.0, 0.0), SLACK)
        .unwrap();
    assert_eq!(a.speed, 4.0);
    assert_eq!(a.dist / a.speed, 0.5);
    // From outside the circle moving towards it: in through the left half
    // (not part of the arc), out through the right half at (1, 0), t = 4.
    let a = right_cap()
        .approach(d(-3.0, 0.0), d(1.0, 0.0), SLACK)
        .unwrap();
    assert_eq!(a.dist / a.speed, 4.0);
}

#[test]
fn a_root_behind_counts_only_on_the_circle() {
    let cap = right_cap();
    // Clear of the circle and moving away: both roots behind, no hit (the
    // old cast landed it at time 0 projected onto the circle).
    assert_eq!(cap.approach(d(3.0, 0.0), d(1.0, 0.0), SLACK), None);
    assert_eq!(cap.approach(d(3.0, 0.5), d(1.0, 0.2), SLACK), None);
    // On the circle to rounding and moving out: the wall at once.
    let p = DVec2::from_angle(0.3);
    let a = cap
        .approach(p * (1.0 + 4.0 * f64::EPSILON), p, SLACK)
        .unwrap();
    assert_eq!(a.dist, 0.0);
    // A convex arc (an obstacle, the ball outside): from inside its
    // circle there is no hit; from outside moving in, the entry.
    let bump = ArcSegment::new(DVec2::ZERO, 1.0, FRAC_PI_2, -PI).unwrap();
    assert!(!bump.is_concave());
    assert_eq!(bump.approach(d(0.0, 0.5), d(-1.0, 0.0), SLACK), None);
    // (It runs clockwise from +π/2 to −π/2: the right half.)
    let a = bump.approach(d(3.0, 0.0), d(-1.0, 0.0), SLACK).unwrap();
    assert_eq!(a.dist / a.speed, 2.0);
    assert_eq!(bump.approach(d(-3.0, 0.0), d(1.0, 0.0), SLACK), None);
}

#[test]
fn contacts_past_the_arc_ends_are_rejected_beyond_the_slack() {
    let cap = right_cap();
    // Rays from the centre to the circle at an angle φ past the end at
    // +π/2: the chord test measures φ (times the radius) against the slack.
    for (past, hit) in [(1e-6, false), (1e-9, false), (1e-14, true), (-1e-6, true)] {
        let v = DVec2::from_angle(FRAC_PI_2 + past);
        assert_eq!(
            cap.approach(DVec2::ZERO, v, SLACK).is_some(),
            hit,
            "{past} past the end"
        );
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(512))]

    /// A random arc of a random circle and a ray from inside (concave) or
    /// outside (convex): where `approach` finds the arc, the landed contact
    /// is on the circle and on the ray, the normal unit and pointing into
    /// the table, and `cast` returns the same.
    #[test]
    fn landed_contacts_are_on_the_circle_and_the_ray(
        cx in -5.0f64..5.0, cy in -5.0f64..5.0, r in 0.1f64..10.0,
        start in 0.0f64..TAU, sweep in 0.1f64..TAU, concave in any::<bool>(),
        rho in 0.0f64..0.99, theta in 0.0f64..TAU, dir in 0.0f64..TAU, speed in 0.1f64..3.0,
    ) {
        let (centre, sweep) = (d(cx, cy), if concave { sweep } else { -sweep });
        let arc = ArcSegment::new(centre, r, start, sweep).unwrap();
        // Inside the circle for a concave arc, outside (up to 3r) for a convex one.
        let reach = if concave { rho } else { 1.01 + 2.0 * rho };
        let origin = centre + DVec2::from_angle(theta) * (reach * r);
        let v = DVec2::from_angle(dir) * speed;
        if let Some(a) = arc.approach(origin, v, SLACK) {
            prop_assert!(a.dist >= 0.0 && a.speed > 0.0);
            prop_assert_eq!(a.speed, v.length_squared());
            let time = a.dist / a.speed;
            let (point, normal) = arc.land(origin, v, time);
            prop_assert!(((point - centre).length() - r).abs() <= 8.0 * f64::EPSILON * (r + centre.length()));
            prop_assert!((origin + v * time - point).length() <= 1e-12 * (r + centre.length() + 1.0));
            prop_assert!((normal.length() - 1.0).abs() <= 4.0 * f64::EPSILON);
            // Into the table: towards the centre on a concave wall.
            let inward = (centre - point).dot(normal);
            let into_table = if concave { inward > 0.0 } else { inward < 0.0 };
            prop_assert!(into_table, "normal {:?} at {:?}", normal, point);
            // Met from the table side.
            prop_assert!(v.dot(normal) <= 0.0);
            let hit = arc.cast(origin, v, SLACK).unwrap();
            prop_assert_eq!((hit.time, hit.point, hit.normal), (time, point, normal));
        } else {
            prop_assert_eq!(arc.cast(origin, v, SLACK), None);
        }
    }
}

#[test]
fn chords_along_an_axis_are_exactly_along_it() {
    // The stadium's caps, the mushroom's cap and a quarter circle: ends
    // from `cos` and `sin` of multiples of π/2, whose rounding (about
    // 1e-16) would tilt the chord off the axis.
    let along_y = [
        ArcSegment::new(d(1.0, 0.0), 1.0, -FRAC_PI_2, PI).unwrap(),
        ArcSegment::new(d(-1.0, 0.0), 1.0, FRAC_PI_2, PI).unwrap(),
        ArcSegment::new(DVec2::ZERO, 2.5, FRAC_PI_2, -PI).unwrap(),
    ];
    for a in &along_y {
        assert_eq!(a.chord().x, 0.0, "{a:?}");
        assert_eq!(a.chord().y.abs(), 2.0 * a.radius(), "{a:?}");
    }
    let cap = ArcSegment::new(DVec2::ZERO, 1.0, 0.0, PI).unwrap();
    assert_eq!(cap.chord(), d(-2.0, 0.0));
    // The cap lies to the right of its chord, which runs from +x to −x.
    assert_eq!(cap.chord_side(), -1.0);
    // Rounding is all that is taken off: a chord 1e-9 off the axis, and
    // an oblique one, keep both components.
    let tilted = ArcSegment::new(DVec2::ZERO, 1.0, 1e-9, PI).unwrap();
    assert!(tilted.chord().y != 0.0 && tilted.chord().x < 0.0);
    let quarter = ArcSegment::new(DVec2::ZERO, 1.0, 0.0, FRAC_PI_2).unwrap();
    assert!((quarter.chord() - d(-1.0, 1.0)).length() < 1e-15);
    assert!(!cap.is_full() && ArcSegment::full_circle(DVec2::ZERO, 1.0).unwrap().is_full());
    // The contact test still lands on the right side of the snapped chord:
    // straight up from the centre meets the cap at (0, 1), straight down
    // does not.
    let up = cap.approach(DVec2::ZERO, d(0.0, 1.0), SLACK).unwrap();
    assert_eq!(up.dist / up.speed, 1.0);
    assert_eq!(cap.approach(d(0.0, 0.5), d(0.0, -1.0), SLACK), None);
}
