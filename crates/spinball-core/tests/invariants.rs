//! Invariants of the dynamics along real trajectories: `Q = v∥ − αu` through
//! every collision (flat and curved walls), what happens to `Q` between
//! consecutive collisions, the rectangle's conserved speeds, time reversal,
//! and the circle's (v∥, u) involution.

mod common;

use common::{ALPHAS, collisions, law, paper_tables};
use proptest::prelude::*;
use spinball_core::{Ball, Billiard, Recorder, Sampler, State};
use spinball_geometry::{Circle, DVec2, Rectangle, Stadium, Table};

const EPS: f64 = f64::EPSILON;

#[test]
fn q_survives_every_collision_on_every_table() {
    // Q = v∥ − αu before and after each collision (paper eq. 12), 1e5
    // collisions per table and α. The record's `q` is computed before, and
    // `q_after` from the post-collision components; they may differ by the
    // rounding of v∥ and αu and of the shell restore: 8 ulps of |v| + α|u|.
    // Also per collision: v⊥ flips, so the tangential energy v∥² + αu² is
    // kept on its own (to the same relative accuracy).
    for table in paper_tables() {
        for alpha in ALPHAS {
            let billiard = Billiard::new(table, law(alpha));
            let start = Sampler::Paper.initial_state(&table, billiard.law(), 9, 0);
            let mut ball = billiard.launch(start).unwrap();
            let (mut flat, mut curved) = (0u32, 0u32);
            let mut prev = start;
            let mut check = |c: &spinball_core::Collision, after: &State| {
                let scale = prev.velocity.length() + alpha * prev.spin.abs();
                assert!(
                    (c.q - c.q_after(alpha)).abs() <= 8.0 * EPS * scale,
                    "{table} alpha {alpha}: dQ = {:e} on wall {}",
                    c.q - c.q_after(alpha),
                    c.wall()
                );
                // The record describes the states it sits between.
                let t = c.tangent();
                assert_eq!(c.v_par_before, prev.velocity.dot(t));
                assert_eq!(c.spin_before, prev.spin);
                assert_eq!(c.spin_after, after.spin);
                assert_eq!(c.v_par_after, after.velocity.dot(t));
                assert_eq!(c.q, c.v_par_before - alpha * c.spin_before);
                assert_eq!(after.position, c.point());
                // v⊥ flips (to the shell restore, a few ulps).
                let n = c.hit.normal;
                assert!((after.velocity.dot(n) + prev.velocity.dot(n)).abs() <= 8.0 * EPS);
                let tang = |vp: f64, u: f64| vp * vp + alpha * u * u;
                let before = tang(c.v_par_before, c.spin_before);
                let after_t = tang(c.v_par_after, c.spin_after);
                assert!(
                    (after_t - before).abs() <= 16.0 * EPS * (1.0 + alpha * prev.spin * prev.spin)
                );
                if c.hit.is_curved() {
                    curved += 1;
                } else {
                    flat += 1;
                }
                prev = *after;
            };
            billiard.run(&mut ball, 100_000, &mut check).unwrap();
            // Both kinds of wall were exercised where the table has both.
            match table {
                Table::Circle(_) => assert_eq!(flat, 0),
                Table::Rectangle(_) => assert_eq!(curved, 0),
                _ => assert!(
                    flat > 1000 && curved > 1000,
                    "{table}: {flat} flat, {curved} curved"
                ),
            }
        }
    }
}

#[test]
fn q_between_consecutive_collisions() {
    // The pairs of the paper's appendix C: |ΔQ| = |Q_(n+1) − Q_n| between
    // consecutive collisions, stadium a = 1, α = 0.5, 10^4 collisions.
    //
    // Same wall twice in a row can only be the same cap: a flat wall cannot
    // be hit twice running (the ball leaves it with v·n > 0 and needs v·n < 0
    // to come back on a straight line). On a circular arc a chord meets the
    // wall at the same angle at both ends, so v∥ before the next hit equals
    // v∥ after this one, u is constant in flight, and Q carries over exactly:
    // |ΔQ| at the rounding level (8 ulps of |v| + α|u| ≤ 1.5). A change of
    // wall changes the tangent and Q jumps by O(1).
    //
    // Consecutive tangents are never identical (the same argument: n_(n+1)
    // ≠ n_n). The closest case, flat → opposite flat (t_(n+1) = −t_n, bottom
    // ↔ top), obeys Q_(n+1) + Q_n = −2α u'_n exactly (u' the spin in
    // between), so Q measured with the wall's own tangent is not carried
    // across parallel walls unless α u' = 0.
    let alpha = 0.5;
    let billiard = Billiard::new(Stadium::new(1.0).unwrap(), law(alpha));
    let start = Sampler::Paper.initial_state(billiard.table(), billiard.law(), 4, 0);
    let mut ball = billiard.launch(start).unwrap();
    let mut rec = Recorder::with_states();
    billiard.run(&mut ball, 10_000, &mut rec).unwrap();
    let (mut same_wall, mut transitions, mut big_jumps, mut opposite_flats) = (0, 0, 0, 0);
    for k in 0..rec.collisions.len() - 1 {
        let (c0, c1) = (&rec.collisions[k], &rec.collisions[k + 1]);
        let v = rec.states[k].velocity;
        let u = rec.states[k].spin;
        assert!(v.dot(c0.hit.normal) > 0.0 && v.dot(c1.hit.normal) < 0.0);
        assert_ne!(c0.tangent(), c1.tangent());
        if c0.wall() == c1.wall() {
            same_wall += 1;
            assert!(c0.hit.is_curved());
            assert!(
                (c1.q - c0.q).abs() <= 8.0 * EPS * 1.5,
                "dQ = {:e}",
                c1.q - c0.q
            );
            assert!((c1.v_par_before - c0.v_par_after).abs() <= 8.0 * EPS);
        } else {
            transitions += 1;
            if (c1.q - c0.q).abs() > 1e-6 {
                big_jumps += 1;
            }
        }
        if c0.tangent() == -c1.tangent() {
            opposite_flats += 1;
            assert!((c1.q + c0.q_after(alpha) + 2.0 * alpha * u).abs() <= 8.0 * EPS);
        }
    }
    // Both populations are well represented (measured: about 21% same-cap
    // pairs), and transitions essentially always jump (a jump below 1e-6 is
    // a coincidence of probability ~1e-6 per pair; allow 1%).
    assert!(
        same_wall > 1000 && transitions > 5000,
        "{same_wall} {transitions}"
    );
    assert!(
        big_jumps * 100 >= transitions * 99,
        "{big_jumps} of {transitions}"
    );
    assert!(opposite_flats > 100, "{opposite_flats}");
}

#[test]
fn q_is_a_constant_of_motion_in_the_circle_and_never_carries_over_in_sinai() {
    // The circle has one wall: every pair is a same-wall pair, so Q never
    // changes (rounding accumulates linearly: 1e-11 over 1e5 collisions).
    // In the Sinai table no wall is ever hit twice in a row (flat walls as
    // above; the convex disk sends the ball away): every pair is a transition.
    for alpha in ALPHAS {
        let billiard = Billiard::new(Circle::unit(), law(alpha));
        let start = Sampler::Microcanonical.initial_state(billiard.table(), billiard.law(), 8, 0);
        let mut ball = billiard.launch(start).unwrap();
        let first = billiard.step(&mut ball).unwrap();
        let mut check = |c: &spinball_core::Collision, _: &State| {
            assert!(
                (c.q - first.q).abs() <= 1e-11,
                "alpha {alpha}: {} vs {}",
                c.q,
                first.q
            );
        };
        billiard.run(&mut ball, 100_000, &mut check).unwrap();

        let table: Table = "sinai".parse().unwrap();
        let billiard = Billiard::new(table, law(alpha));
        let mut ball = billiard
            .launch(Sampler::Paper.initial_state(&table, billiard.law(), 8, 0))
            .unwrap();
        let mut last = u32::MAX;
        let mut check = |c: &spinball_core::Collision, _: &State| {
            assert_ne!(c.wall(), last);
            last = c.wall();
        };
        billiard.run(&mut ball, 100_000, &mut check).unwrap();
    }
}

#[test]
fn rectangle_keeps_the_normal_speeds() {
    // In the rectangle every wall is parallel to an axis: a collision with a
    // horizontal wall flips v_y and leaves |v_y| (and so v_y²) alone; one with
    // a vertical wall leaves |v_x| alone. At α = 0 both |v_x| and |v_y| are
    // constants of the motion (integrable); for α > 0 the spin trades with the
    // tangential component only.
    for alpha in ALPHAS {
        let billiard = Billiard::new(Rectangle::new(1.5, 1.0).unwrap(), law(alpha));
        let start = Sampler::Paper.initial_state(billiard.table(), billiard.law(), 6, 0);
        let mut ball = billiard.launch(start).unwrap();
        let mut prev = start.velocity;
        let v0 = start.velocity.abs();
        let mut check = |c: &spinball_core::Collision, after: &State| {
            let v = after.velocity;
            // Shell restore rescales by 1 + O(ε): a few ulps.
            let tol = 4.0 * EPS;
            if c.hit.normal.x == 0.0 {
                assert!((v.y.abs() - prev.y.abs()).abs() <= tol);
            } else {
                assert!((v.x.abs() - prev.x.abs()).abs() <= tol);
            }
            if alpha == 0.0 {
                // Errors add up over the run: 1e-12 after 1e5 collisions.
                assert!((v.abs() - v0).max_element() <= 1e-12);
                assert_eq!(after.spin, start.spin);
            }
            prev = v;
        };
        billiard.run(&mut ball, 100_000, &mut check).unwrap();
    }
}

/// Run `k` collisions from `start`, reverse (v, u) → (−v, −u) (or only v),
/// step back and drift the first flight time: return the final state and
/// the list of walls seen backwards.
fn retrace(billiard: &Billiard<Table>, start: State, k: usize, negate_spin: bool) -> (State, bool) {
    let mut ball = billiard.launch(start).unwrap();
    let forward = collisions(billiard, &mut ball, k);
    let s = *ball.state();
    let spin = if negate_spin { -s.spin } else { s.spin };
    let mut back = Ball::new(State::new(s.position, -s.velocity, spin), billiard.law()).unwrap();
    // The first reversed step meets wall k again at once (the ball sits on it
    // moving in), then walls k−1, ..., 1.
    let backward = collisions(billiard, &mut back, k);
    back.drift(forward[0].time());
    let same_walls = backward
        .iter()
        .zip(forward.iter().rev())
        .all(|(b, f)| b.wall() == f.wall());
    let zero_first = backward[0].time() <= 1e-12;
    (*back.state(), same_walls && zero_first)
}

#[test]
fn reversing_velocity_and_spin_retraces_the_path() {
    // The collision is linear in (v, u) (a half-turn of V = (v, √α u)), so it
    // commutes with T: (x, v, u) → (x, −v, −u), and free flight is
    // reversible: T ∘ step ∘ T = step⁻¹. Spin must be negated with the
    // velocity: u = rω is an angular velocity, odd under time reversal.
    // Tolerance: 1e-9 of the table size after up to 10 collisions each way
    // (chaotic growth of rounding errors over 20 collisions stays far below).
    for table in paper_tables() {
        let scale = 2.0;
        for alpha in ALPHAS {
            let billiard = Billiard::new(table, law(alpha));
            for index in 0..5 {
                let start = Sampler::Paper.initial_state(&table, billiard.law(), 31, index);
                for k in [1, 3, 10] {
                    let (end, walls_ok) = retrace(&billiard, start, k, true);
                    let label = format!("{table} alpha {alpha} ic {index} k {k}");
                    assert!(walls_ok, "{label}: walls not retraced");
                    assert!(
                        (end.position - start.position).length() <= 1e-9 * scale,
                        "{label}: {end:?}"
                    );
                    assert!((end.velocity + start.velocity).length() <= 1e-9, "{label}");
                    assert!((end.spin + start.spin).abs() <= 1e-9, "{label}");
                }
            }
        }
    }
}

#[test]
fn reversing_velocity_alone_does_not_retrace_when_spin_matters() {
    // Without negating u the reversed ball meets the wall with the wrong slip
    // velocity (v∥ + u instead of −(v∥ + u)) and leaves at another angle:
    // after retracing k collisions it ends O(αu) away from the start. At
    // α = 0 the spin is decoupled and either reversal retraces.
    let table: Table = "stadium:a=1".parse().unwrap();
    for alpha in [0.3, 1.0, 5.0] {
        let billiard = Billiard::new(table, law(alpha));
        for index in 0..5 {
            let start = Sampler::Paper.initial_state(&table, billiard.law(), 32, index);
            let mut probe = billiard.launch(start).unwrap();
            billiard.step(&mut probe).unwrap();
            let u = probe.spin();
            let (end, _) = retrace(&billiard, start, 1, false);
            // The position error is about (flight time) × 2α|u|/(1+α) × O(1);
            // assert 1e-6 only where α|u| is at least 1e-3.
            if alpha * u.abs() > 1e-3 {
                let miss = (end.position - start.position).length()
                    + (end.velocity + start.velocity).length();
                assert!(miss > 1e-6, "alpha {alpha} ic {index}: miss {miss:e}");
            }
        }
    }
    let billiard = Billiard::new(table, law(0.0));
    let start = State::new(DVec2::new(0.1, 0.2), DVec2::new(0.6, 0.8), 0.7);
    let (end, ok) = retrace(&billiard, start, 10, false);
    assert!(ok && (end.position - start.position).length() <= 1e-9);
    assert_eq!(end.spin, start.spin);
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 500, ..ProptestConfig::default() })]

    /// In the circle every chord meets the wall at the same angle at both
    /// ends, so v∥ before collision k + 1 equals v∥ after collision k and the
    /// (v∥, u) map is M, with M² = I (paper eq. 7): (v∥, u) before collision
    /// k + 2 equals that before collision k, for every α.
    #[test]
    fn circle_v_par_and_spin_repeat_every_two_collisions(
        alpha in 0.0f64..5.0,
        r in 0.0f64..0.999,
        theta in 0.0f64..std::f64::consts::TAU,
        phi in 0.0f64..std::f64::consts::TAU,
        z in -0.99f64..0.99,
    ) {
        let law = spinball_core::SpinLaw::extended(alpha).unwrap();
        let billiard = Billiard::new(Circle::unit(), law);
        // Energy ½ with a share z² in the spin (as the microcanonical sampler).
        let spin = if alpha > 0.0 { z / alpha.sqrt() } else { 0.0 };
        let speed = if alpha > 0.0 { (1.0 - z * z).sqrt() } else { 1.0 };
        let start = State::new(DVec2::from_angle(theta) * r, DVec2::from_angle(phi) * speed, spin);
        let mut ball = billiard.launch(start).unwrap();
        let cs = collisions(&billiard, &mut ball, 24);
        // Rounding accumulates linearly in this integrable table: 1e-12 over
        // 24 collisions is ~200 ulps of the O(1/√α) spin scale.
        let tol = 1e-12 * (1.0 + spin.abs());
        for k in 0..cs.len() - 2 {
            prop_assert!((cs[k + 2].v_par_before - cs[k].v_par_before).abs() <= tol);
            prop_assert!((cs[k + 2].spin_before - cs[k].spin_before).abs() <= tol);
            prop_assert!((cs[k + 1].v_par_before - cs[k].v_par_after).abs() <= tol);
        }
    }
}
