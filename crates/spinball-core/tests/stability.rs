//! Issue 9, core side: speeds f64 cannot run are rejected at launch with
//! their range (F1, F2), the largest accepted sizes and speeds run clean
//! (no pass through the obstacle, energy and Q kept), a ball that stops
//! moving is `StepError::Stuck` (F4), and the collision law reverses the
//! contact point's tangential velocity exactly at every α (item 6).
//! Reproducers are the issue's, literally.

mod common;

use glam::DVec2;
use proptest::prelude::*;
use spinball_core::{
    Billiard, LaunchError, MAX_SPEED, MAX_ZERO_TIME_RUN, MIN_SPEED, Observer, Run, SpinLaw, State,
    StepError,
};
use spinball_geometry::{Boundary, Sinai, Stadium};

fn speed_error(e: LaunchError) {
    match e {
        LaunchError::Speed { min, max, .. } => {
            assert_eq!((min, max), (MIN_SPEED, MAX_SPEED));
            assert!(e.to_string().contains("range"), "{e}");
        }
        other => panic!("expected LaunchError::Speed, got {other:?}"),
    }
}

#[test]
fn f1_subnormal_speed_squares_are_rejected_at_launch() {
    let start = State::new(DVec2::new(0.1, 0.2), DVec2::new(6e-161, 8e-161), 3e-161);
    for alpha in [0.0, 0.5] {
        let law = SpinLaw::new(alpha).unwrap();
        speed_error(
            Billiard::new(Stadium::new(1.0).unwrap(), law)
                .launch(start)
                .unwrap_err(),
        );
        speed_error(
            Billiard::new(Sinai::new(2.0, 1.0).unwrap(), law)
                .launch(start)
                .unwrap_err(),
        );
    }
}

#[test]
fn f2_overflowing_speed_squares_are_rejected_at_launch() {
    let start = State::new(DVec2::new(-1.5, 0.2), DVec2::new(6e153, 8e153), 3e153);
    for alpha in [0.0, 0.5] {
        let billiard = Billiard::new(Sinai::new(2.0, 1.0).unwrap(), SpinLaw::new(alpha).unwrap());
        speed_error(billiard.launch(start).unwrap_err());
    }
}

/// Checks every flight of a Sinai run: never through the disk (closest
/// approach of the chord to the centre ≥ r(1 − 1e-12)), energy and Q kept.
struct DiskGuard {
    r: f64,
    prev: State,
    e0: f64,
    law: SpinLaw,
    worst_energy: f64,
    worst_q: f64,
}

impl Observer for DiskGuard {
    fn observe(&mut self, c: &spinball_core::Collision, after: &State) {
        let closest = common::closest_to_origin(self.prev.position, after.position);
        assert!(closest >= self.r * (1.0 - 1e-12), "through the disk");
        let e = after.energy(&self.law);
        self.worst_energy = self.worst_energy.max((e - self.e0).abs() / self.e0);
        let scale = (2.0 * self.e0).sqrt();
        self.worst_q = self
            .worst_q
            .max((c.q - c.q_after(self.law.alpha())).abs() / scale);
        self.prev = *after;
    }
}

#[test]
fn extreme_accepted_sizes_and_speeds_run_clean() {
    // The corners of the accepted box: sizes 1e±60 with speeds 1e±60, and
    // the F2 geometry at the largest speed. 2e4 collisions each.
    for (l, speed) in [
        (1e60, 0.95e60),
        (1e60, 1.01e-60),
        (2e-60, 0.95e60),
        (2e-60, 1.01e-60),
        (2.0, 0.95e60),
        (2.0, 1.01e-60),
    ] {
        for alpha in [0.0, 0.5] {
            let law = SpinLaw::new(alpha).unwrap();
            let table = Sinai::new(l, 0.5 * l).unwrap();
            let billiard = Billiard::new(table, law);
            let start = State::new(
                DVec2::new(-0.75 * l, 0.1 * l),
                DVec2::new(0.6, 0.8) * speed,
                0.3 * speed,
            );
            let mut ball = billiard.launch(start).unwrap();
            let mut guard = DiskGuard {
                r: table.r(),
                prev: start,
                e0: start.energy(&law),
                law,
                worst_energy: 0.0,
                worst_q: 0.0,
            };
            let run: Run = billiard.run(&mut ball, 20_000, &mut guard).unwrap();
            assert!(run.time.is_finite() && run.time > 0.0);
            assert!(table.contains(ball.position()));
            // Energy to a few ulps (the shell restore), Q at each
            // collision to rounding: the same bounds as at size 1.
            assert!(
                guard.worst_energy < 1e-14,
                "l={l} v={speed}: {}",
                guard.worst_energy
            );
            assert!(guard.worst_q < 1e-13, "l={l} v={speed}: {}", guard.worst_q);
        }
    }
}

#[test]
fn f4_a_ball_moving_along_a_flat_wall_into_the_junction_is_stuck() {
    // Documented rule: a start on a wall moving along it is not rejected;
    // the ball slides to the junction, where the cap is tangent, and every
    // later collision takes zero time: after MAX_ZERO_TIME_RUN of them in a
    // row the step fails with StepError::Stuck (formerly `run(1e6)` returned
    // Ok with total time 1).
    let start = State::new(DVec2::new(0.0, 1.0), DVec2::new(1.0, 0.0), 0.0);
    for alpha in [0.0, 0.5] {
        let billiard = Billiard::new(Stadium::new(1.0).unwrap(), SpinLaw::new(alpha).unwrap());
        let mut ball = billiard.launch(start).unwrap();
        let e = billiard.run(&mut ball, 1_000_000, &mut ()).unwrap_err();
        match e {
            StepError::Stuck {
                position,
                collisions,
                ..
            } => {
                assert_eq!(collisions, MAX_ZERO_TIME_RUN + 1);
                assert!(
                    (position - DVec2::new(1.0, 1.0)).length() < 1e-12,
                    "{position}"
                );
            }
            other => panic!("expected Stuck, got {other:?}"),
        }
        // The ball is left where the failing step started, on the table.
        assert!(billiard.table().contains(ball.position()));
    }
}

#[test]
fn a_corner_is_not_stuck() {
    // The rectangle's exact corner hit takes one zero-time collision and
    // goes on (rule of `Rectangle`): far below the stuck limit.
    let table = spinball_geometry::Rectangle::new(1.5, 1.0).unwrap();
    let billiard = Billiard::new(table, SpinLaw::new(0.5).unwrap());
    let mut ball = billiard
        .launch(State::new(DVec2::new(0.5, 0.0), DVec2::new(0.6, 0.6), 0.3))
        .unwrap();
    let run = billiard.run(&mut ball, 100_000, &mut ()).unwrap();
    assert!(run.time > 1e4);
}

proptest! {
    /// Item 6: with u = rω and t × n = +z, the contact point's tangential
    /// velocity is v∥ + u and the law reverses it exactly:
    /// v∥' + u' = (k − v∥) + (−u − k) = −(v∥ + u) for every α > 0, where k =
    /// 2(v∥ − αu)/(1 + α) cancels. In floating point only the three
    /// roundings of k − v∥, −u − k and their sum remain: the bound is
    /// 4ε(|k| + |v∥| + |u|). α from 1e-12 to 1e12, log-uniform.
    #[test]
    fn contact_velocity_is_reversed_at_every_alpha(
        log_alpha in -12.0f64..12.0,
        v in -10.0f64..10.0,
        u in -10.0f64..10.0,
        angle in 0.0f64..std::f64::consts::TAU,
        vn in -10.0f64..10.0,
    ) {
        let alpha = 10f64.powf(log_alpha);
        let law = SpinLaw::extended(alpha).unwrap();
        // Components form (t = +x exactly).
        let (v1, u1) = law.collide_components(v, u);
        let k = (v - alpha * u) * law.delta();
        let bound = 4.0 * f64::EPSILON * (k.abs() + v.abs() + u.abs());
        prop_assert!(((v1 + u1) + (v + u)).abs() <= bound,
            "α={alpha}: v∥'+u' = {} vs −(v∥+u) = {}", v1 + u1, -(v + u));
        // A wall at any angle: t is unit to rounding, v has a normal part.
        let t = DVec2::from_angle(angle);
        let n = t.perp();
        let vel = t * v + n * vn;
        let (vel1, u2) = law.collide(vel, u, t);
        let (par, par1) = (vel.dot(t), vel1.dot(t));
        let bound = 16.0 * f64::EPSILON * (k.abs() + v.abs() + vn.abs() + u.abs());
        prop_assert!(((par1 + u2) + (par + u)).abs() <= bound,
            "α={alpha}, angle {angle}: {} vs {}", par1 + u2, -(par + u));
        // and the normal velocity is reversed.
        prop_assert!((vel1.dot(n) + vel.dot(n)).abs() <= bound);
    }
}

#[test]
fn the_large_alpha_limit_freezes_the_spin() {
    // α → ∞: infinite rotational inertia. u' = −u − k with
    // k = 2(v∥ − αu)/(1+α) → −2u, so u' → u (the spin never changes) and
    // v∥' = k − v∥ → −v∥ − 2u. At α = 1e12 both hold to 1e-11.
    let law = SpinLaw::extended(1e12).unwrap();
    let (v, u) = (0.7, -0.3);
    let (v1, u1) = law.collide_components(v, u);
    assert!((u1 - u).abs() < 1e-11, "{u1}");
    assert!((v1 - (-v - 2.0 * u)).abs() < 1e-11, "{v1}");
    // α = ½ (a uniform disk) is the no-slip law of Broomhead–Gutkin and
    // Cox–Feres: the contact velocity reversed with I = m r²/2. Here it is
    // the same identity with k = 4(v − u/2)/3.
    let disk = SpinLaw::new(0.5).unwrap();
    let (v2, u2) = disk.collide_components(v, u);
    let k = 4.0 * (v - 0.5 * u) / 3.0;
    assert!((v2 - (k - v)).abs() < 1e-15 && (u2 - (-u - k)).abs() < 1e-15);
}
