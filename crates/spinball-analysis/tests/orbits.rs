//! Periodic orbits and their stability against closed forms
//! (docs/PHASE_SPACE.md, "Periodic orbits and their stability").

use std::f64::consts::{PI, TAU};

use spinball_analysis::AnalysisError;
use spinball_analysis::orbits::{
    BirkhoffPoint, NewtonOptions, PeriodicOrbit, SearchOptions, StabilityClass, find_orbit,
    follow_in_alpha, periodic_orbits,
};
use spinball_analysis::phase_space::state_on_section;
use spinball_core::{Billiard, SpinLaw};
use spinball_geometry::{
    ArcSegment, Boundary, DVec2, LineSegment, Segment, SegmentTable, Sinai, Stadium,
};

/// Pair trace of a period-2 orbit along a common normal of two walls of
/// signed curvatures `k1`, `k2` a length `l` apart (derived in
/// docs/PHASE_SPACE.md): `2(α² − 2α(k1+k2)l − 6α + 2k1k2l² + 2(k1+k2)l + 1)/(1+α)²`.
fn closed_form_trace(alpha: f64, k1: f64, k2: f64, l: f64) -> f64 {
    let k = k1 + k2;
    2.0 * (alpha * alpha - 2.0 * alpha * k * l - 6.0 * alpha
        + 2.0 * k1 * k2 * l * l
        + 2.0 * k * l
        + 1.0)
        / ((1.0 + alpha) * (1.0 + alpha))
}

fn period_two<B: Boundary>(table: B, alpha: f64) -> (Billiard<B>, Vec<PeriodicOrbit>) {
    let billiard = Billiard::new(table, SpinLaw::new(alpha).unwrap());
    // Normal seeds that close through a corner of the Sinai box are refused
    // (and counted as failed), so no count is asserted here.
    let (orbits, _) = periodic_orbits(&billiard, 2, &SearchOptions::default()).unwrap();
    (billiard, orbits)
}

/// The orbit through the point at arc length `s`.
fn through(orbits: &[PeriodicOrbit], s: f64) -> &PeriodicOrbit {
    orbits
        .iter()
        .find(|o| o.points.iter().any(|p| (p.s - s).abs() < 1e-9))
        .unwrap_or_else(|| panic!("no orbit through s = {s}: {orbits:?}"))
}

/// The orbit between walls `walls` (for a family: the one member found).
fn on_walls(orbits: &[PeriodicOrbit], walls: [u32; 2]) -> &PeriodicOrbit {
    let found: Vec<_> = orbits.iter().filter(|o| o.walls == walls).collect();
    assert_eq!(found.len(), 1, "{orbits:?}");
    found[0]
}

/// Sinai box `[−L, L]²`: the bottom wall's middle is at `s = L` (the box
/// runs counter-clockwise from `(−L, −L)`); the disk's point `(0, −R)` is
/// a quarter of its circumference clockwise from `(R, 0)`.
fn sinai_axis(l: f64, r: f64) -> (f64, f64) {
    (l, 8.0 * l + 0.5 * PI * r)
}

#[test]
fn point_particle_period_two_multipliers_match_closed_forms() {
    // α = 0: T = 2 + 4l(k1 + k2) + 4l²k1k2, multipliers T/2 ± √(T²/4 − 1).
    for (l, r) in [(2.0, 1.0), (2.0, 0.5)] {
        let (_, orbits) = period_two(Sinai::new(l, r).unwrap(), 0.0);
        let (s_box, s_disk) = sinai_axis(l, r);
        let orbit = through(&orbits, s_box);
        assert!(orbit.points.iter().any(|p| (p.s - s_disk).abs() < 1e-9));
        let t = 2.0 + 4.0 * (l - r) / r;
        let lambda = 0.5 * t + (0.25 * t * t - 1.0).sqrt();
        let st = &orbit.stability;
        assert!(
            (st.pair_trace - t).abs() < 1e-12 * t,
            "{} vs {t}",
            st.pair_trace
        );
        assert!((st.multipliers[1].re - lambda).abs() < 1e-12 * lambda);
        assert!((st.multipliers[2].re - 1.0 / lambda).abs() < 1e-12);
        assert_eq!(
            st.class,
            StabilityClass::Hyperbolic {
                multiplier: st.multipliers[1].re
            }
        );
    }
    for a in [1.0, 0.5] {
        let (_, orbits) = period_two(Stadium::new(a).unwrap(), 0.0);
        // The long axis: from the right cap's middle (s = 2a + π/2).
        let orbit = through(&orbits, 2.0 * a + 0.5 * PI);
        let l = 2.0 * a + 2.0;
        let t = 2.0 - 8.0 * l + 4.0 * l * l;
        assert!((orbit.stability.pair_trace - t).abs() < 1e-12 * t);
        // The bouncing ball through the centre: parabolic, T = 2.
        let bounce = on_walls(&orbits, [0, 2]);
        assert_eq!(
            bounce.stability.class,
            StabilityClass::Parabolic { sign: 1 }
        );
    }
}

#[test]
fn spinning_period_two_traces_match_the_closed_form() {
    for alpha in [0.05, 0.2, 0.4, 0.7, 1.0] {
        for (l, r) in [(2.0, 1.0), (2.0, 0.5)] {
            let (_, orbits) = period_two(Sinai::new(l, r).unwrap(), alpha);
            let t = closed_form_trace(alpha, 1.0 / r, 0.0, l - r);
            let got = through(&orbits, sinai_axis(l, r).0).stability.pair_trace;
            assert!(
                (got - t).abs() < 1e-11 * t.abs().max(1.0),
                "α {alpha}: {got} vs {t}"
            );
        }
        for a in [1.0, 0.5] {
            let (_, orbits) = period_two(Stadium::new(a).unwrap(), alpha);
            let t = closed_form_trace(alpha, -1.0, -1.0, 2.0 * a + 2.0);
            let got = through(&orbits, 2.0 * a + 0.5 * PI).stability.pair_trace;
            assert!((got - t).abs() < 1e-11 * t, "α {alpha}: {got} vs {t}");
        }
    }
}

#[test]
fn bouncing_ball_monodromy_rotates_by_four_arctan_sqrt_alpha() {
    for alpha in [1e-4, 0.01, 0.1, 0.3, 0.5, 0.8, 0.99] {
        let (_, orbits) = period_two(Stadium::new(1.0).unwrap(), alpha);
        let st = &on_walls(&orbits, [0, 2]).stability;
        let expected = 4.0 * alpha.sqrt().atan() / TAU;
        match st.class {
            StabilityClass::Elliptic { rotation } => {
                assert!(
                    (rotation - expected).abs() < 1e-12,
                    "α {alpha}: {rotation} vs {expected}"
                );
            }
            other => panic!("α {alpha}: {other:?}"),
        }
        assert!(st.residue > 0.0 && st.residue < 1.0);
    }
}

#[test]
fn monodromy_has_determinant_one_and_a_unit_multiplier() {
    // Even period at α > 0 and α = 0: det 1, the family's multiplier 1.
    for alpha in [0.0, 0.3, 1.0] {
        for orbits in [
            period_two(Stadium::new(1.0).unwrap(), alpha).1,
            period_two(Sinai::new(2.0, 1.0).unwrap(), alpha).1,
        ] {
            assert!(!orbits.is_empty());
            for o in &orbits {
                let st = &o.stability;
                assert!((st.determinant - 1.0).abs() < 1e-12, "{st:?}");
                assert!(st.unit_residual.abs() < 1e-12, "{st:?}");
            }
        }
    }
    // Odd period at α > 0: det −1 and the multiplier −1 (found from a grid).
    let billiard = Billiard::new(Stadium::new(1.0).unwrap(), SpinLaw::new(0.3).unwrap());
    let options = SearchOptions {
        normal_samples: 0,
        grid: [24, 8, 2],
        ..SearchOptions::default()
    };
    let (orbits, _) = periodic_orbits(&billiard, 3, &options).unwrap();
    assert!(!orbits.is_empty());
    for o in &orbits {
        assert!(
            (o.stability.determinant + 1.0).abs() < 1e-9,
            "{:?}",
            o.stability
        );
        assert!(o.stability.unit_residual.abs() < 1e-12, "{:?}", o.stability);
    }
}

/// The largest distance, over the orbit's points, between the state after
/// `periods` periods of `Billiard::step` and the orbit.
fn drift<B: Boundary>(billiard: &Billiard<B>, orbit: &PeriodicOrbit, periods: u32) -> f64 {
    let p0 = orbit.points[0];
    let state =
        state_on_section(billiard.table(), billiard.law(), p0.s, p0.v_par, p0.spin).unwrap();
    let mut ball = billiard.launch(state).unwrap();
    let mut worst: f64 = 0.0;
    for _ in 0..periods {
        for k in 1..=orbit.period as usize {
            let c = billiard.step(&mut ball).unwrap();
            let want = orbit.points[k % orbit.period as usize];
            let after = ball.state();
            let got =
                BirkhoffPoint::new(c.hit.s(), after.velocity.dot(c.hit.tangent()), after.spin);
            let ds = (got.s - want.s)
                .abs()
                .min(billiard.table().perimeter() - (got.s - want.s).abs());
            worst = worst
                .max(ds)
                .max((got.v_par - want.v_par).abs())
                .max((got.spin - want.spin).abs());
        }
    }
    worst
}

#[test]
fn orbits_close_and_an_elliptic_one_stays_for_ten_thousand_periods() {
    for alpha in [0.0, 0.3] {
        let (billiard, orbits) = period_two(Sinai::new(2.0, 0.5).unwrap(), alpha);
        for o in &orbits {
            assert!(o.residual <= 1e-12);
            assert!(drift(&billiard, o, 1) <= 1e-12, "{o:?}");
        }
    }
    // Grid starts, period 4, on the stadium at α = 0.
    let billiard = Billiard::new(Stadium::new(1.0).unwrap(), SpinLaw::specular());
    let options = SearchOptions {
        normal_samples: 0,
        grid: [16, 8, 1],
        ..SearchOptions::default()
    };
    let (orbits, _) = periodic_orbits(&billiard, 4, &options).unwrap();
    assert!(!orbits.is_empty());
    for o in &orbits {
        assert!(drift(&billiard, o, 1) <= 1e-12, "{o:?}");
    }
    // Sinai L = 2, R = 1 at α = 0.5: the axis orbit is elliptic (T = −2/3).
    let (billiard, orbits) = period_two(Sinai::new(2.0, 1.0).unwrap(), 0.5);
    let orbit = through(&orbits, 2.0);
    assert!(orbit.stability.class.is_elliptic());
    assert!(drift(&billiard, orbit, 10_000) <= 1e-8);
}

#[test]
fn stability_changes_where_the_closed_form_says() {
    // Sinai: T = 2 at α = l/(l + 4R), l = L − R; T = −2 at α = 1.
    // A grid in twelfths: neither crossing (1/5, 3/7) lies on it.
    let alphas: Vec<f64> = (0..=12).map(|i| f64::from(i) / 12.0).collect();
    for (l, r) in [(2.0, 1.0), (2.0, 0.5)] {
        let (_, orbits) = period_two(Sinai::new(l, r).unwrap(), 0.0);
        let orbit = through(&orbits, sinai_axis(l, r).0);
        let table = Sinai::new(l, r).unwrap();
        let c = follow_in_alpha(&table, orbit, &alphas, 1e-10, &NewtonOptions::default()).unwrap();
        let up = c.changes.iter().find(|ch| ch.crossing == 2.0).unwrap();
        let exact = (l - r) / (l - r + 4.0 * r);
        assert!(up.error <= 1e-10);
        assert!(
            (up.alpha - exact).abs() <= up.error + 1e-12,
            "{up:?} vs {exact}"
        );
        assert!(matches!(up.before, StabilityClass::Hyperbolic { .. }));
        assert!(up.after.is_elliptic());
        assert_eq!(c.orbits.len(), alphas.len());
        // T + 2 = 4(α − 1)(α − 1 − l/R)/(1+α)²: parabolic at α = 1 itself.
        let down = c.changes.iter().find(|ch| ch.crossing == -2.0).unwrap();
        assert_eq!((down.alpha, down.error), (1.0, 0.0));
        assert_eq!(c.changes.len(), 2);
    }
    // Stadium long axis: T − 2 = 4(l² − 2l + α(2l − 4))/(1+α)² > 0: no change.
    for a in [1.0, 0.5] {
        let table = Stadium::new(a).unwrap();
        let (_, orbits) = period_two(Stadium::new(a).unwrap(), 0.0);
        let orbit = through(&orbits, 2.0 * a + 0.5 * PI);
        let c = follow_in_alpha(&table, orbit, &alphas, 1e-10, &NewtonOptions::default()).unwrap();
        assert!(c.changes.is_empty(), "{:?}", c.changes);
        assert!(c.orbits.iter().all(|o| o.stability.pair_trace > 2.0));
    }
}

#[test]
fn a_segment_stadium_gives_the_built_in_multipliers() {
    let p = DVec2::new;
    let line = |a, b| LineSegment::new(a, b).map(Segment::Line).unwrap();
    let table = SegmentTable::new(vec![
        line(p(-1.0, -1.0), p(1.0, -1.0)),
        Segment::Arc(ArcSegment::new(p(1.0, 0.0), 1.0, -0.5 * PI, PI).unwrap()),
        line(p(1.0, 1.0), p(-1.0, 1.0)),
        Segment::Arc(ArcSegment::new(p(-1.0, 0.0), 1.0, 0.5 * PI, PI).unwrap()),
    ])
    .unwrap();
    for alpha in [0.0, 0.4] {
        let (_, orbits) = period_two(&table, alpha);
        let long = through(&orbits, 2.0 + 0.5 * PI);
        let t = closed_form_trace(alpha, -1.0, -1.0, 4.0);
        assert!((long.stability.pair_trace - t).abs() < 1e-11 * t);
    }
}

#[test]
fn newton_failure_carries_its_residual() {
    let billiard = Billiard::new(Stadium::new(1.0).unwrap(), SpinLaw::new(0.5).unwrap());
    let options = NewtonOptions {
        max_iterations: 2,
        ..NewtonOptions::default()
    };
    match find_orbit(&billiard, BirkhoffPoint::new(1.3, 0.41, 0.2), 5, &options) {
        Err(AnalysisError::NotClosed {
            period,
            iterations,
            residual,
            tolerance,
        }) => {
            assert_eq!(period, 5);
            assert!(iterations <= 2);
            assert!(residual.is_finite() && residual > tolerance);
        }
        other => panic!("{other:?}"),
    }
    // Off the shell: refused, not run.
    assert!(matches!(
        find_orbit(
            &billiard,
            BirkhoffPoint::new(1.0, 0.9, 1.0),
            2,
            &NewtonOptions::default()
        ),
        Err(AnalysisError::InvalidOption { .. })
    ));
}
