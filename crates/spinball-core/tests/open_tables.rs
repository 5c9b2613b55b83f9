//! Dynamics on open and periodic tables: escapes through holes, crossings
//! of periodic walls with the cell counted exactly, and the circle with a
//! hole against its exactly computable escape law.

use std::f64::consts::{PI, TAU};

use spinball_core::{Ball, Billiard, Cell, Event, Sampler, SpinLaw, State, StepError};
use spinball_geometry::{Boundary, DVec2, LorentzGas, SegmentTable};

#[test]
fn a_table_without_holes_never_reports_an_escape() {
    let law = SpinLaw::new(0.4).unwrap();
    let stadium = SegmentTable::stadium_with_hole(1.0, 1.0, 0.2).unwrap();
    let closed = SegmentTable::new(stadium.walls().to_vec()).unwrap();
    let cell = LorentzGas::triangular(1.0, 0.45).unwrap().table().unwrap();
    for table in [closed, cell] {
        let billiard = Billiard::new(&table, law);
        for seed in 0..4 {
            let start = Sampler::Paper.initial_state(&table, &law, seed, 0);
            let mut ball = billiard.launch(start).unwrap();
            for _ in 0..20_000 {
                let event = billiard.advance(&mut ball).unwrap();
                assert!(!matches!(event, Event::Escape(_)), "{event:?}");
            }
        }
    }
}

#[test]
fn a_ball_reaching_a_hole_escapes_and_step_says_so() {
    let law = SpinLaw::new(0.4).unwrap();
    let table = SegmentTable::circle_with_hole(1.0, 0.0, 0.4).unwrap();
    let billiard = Billiard::new(&table, law);
    // Straight at the hole from the centre.
    let start = State::new(DVec2::ZERO, DVec2::new(2.0, 0.0), 0.7);
    let mut ball = billiard.launch(start).unwrap();
    let Event::Escape(exit) = billiard.advance(&mut ball).unwrap() else {
        panic!("escape expected")
    };
    assert_eq!(exit.wall, 1);
    assert!((exit.point - DVec2::X).length() < 1e-15);
    assert!((exit.time - 0.5).abs() < 1e-15);
    assert!(exit.v_par.abs() < 1e-15 && exit.spin == 0.7);
    // `step` refuses to collide there and leaves the ball as it was.
    let mut ball = billiard.launch(start).unwrap();
    let err = billiard.step(&mut ball).unwrap_err();
    assert!(
        matches!(err, StepError::Escaped(e) if e.wall == 1),
        "{err:?}"
    );
    assert_eq!(*ball.state(), start);
}

/// The escape of one initial condition from the unit circle with a hole of
/// angular size `size` centred at polar angle 0, computed exactly: the
/// contact advances along the circle by the central angle of each chord,
/// `2 acos(|v∥|/|v|)` in the direction of `v∥`, and each collision is the
/// spin law applied to `(v∥, u)` (in a circle the tangential velocity on
/// arriving equals that on leaving the previous contact, so nothing else
/// enters). Returns `(collisions, time, v∥, u)` at the exit, or `None` if
/// there is no exit within `budget` collisions, or if a contact falls within
/// `margin` of the hole's edge (where rounding could decide either way).
fn circle_exit(
    law: &SpinLaw,
    start: &State,
    size: f64,
    budget: u64,
    margin: f64,
) -> Option<Option<(u64, f64, f64, f64)>> {
    let (p, v) = (start.position, start.velocity);
    let t1 = (-p.dot(v)
        + (p.dot(v).powi(2) + v.length_squared() * (1.0 - p.length_squared())).sqrt())
        / v.length_squared();
    let q = p + v * t1;
    let mut psi = q.y.atan2(q.x);
    let tangent = DVec2::new(-q.y, q.x);
    let (mut a, mut speed, mut u) = (v.dot(tangent), v.length(), start.spin);
    let mut time = t1;
    for n in 0..=budget {
        // Angular distance of the contact from the hole's centre.
        let off = (psi + PI).rem_euclid(TAU) - PI;
        if (off.abs() - 0.5 * size).abs() < margin {
            return None;
        }
        if off.abs() < 0.5 * size {
            return Some(Some((n, time, a, u)));
        }
        if n == budget {
            break;
        }
        // Collide in a frame where the wall's tangent is +x, its normal +y.
        let vn = (speed * speed - a * a).max(0.0).sqrt();
        let (out, u_out) = law.collide(DVec2::new(a, -vn), u, DVec2::X);
        (a, speed, u) = (out.x, out.length(), u_out);
        let c = (a.abs() / speed).min(1.0);
        psi += a.signum() * 2.0 * c.acos();
        time += 2.0 * (1.0 - c * c).sqrt() / speed;
    }
    Some(None)
}

#[test]
fn the_circle_with_a_hole_matches_its_exact_escape_law() {
    // Per initial condition: the collision count is exact (integers), the
    // escape time and exit (v∥, u) agree to 1e-9 (the simulated contacts
    // drift from the exact ones by rounding, ~1e-13 over 2000 collisions;
    // contacts within 1e-9 of the hole's edge are left out, since there
    // rounding decides). At α = 0 the incidence is conserved and the
    // contact advances by one fixed arc; at α > 0 the spin law alternates
    // the tangential velocity between two values (the law is a half-turn,
    // an involution), so the contact advances alternately by two arcs.
    let size = 0.3;
    let budget = 2000;
    let table = SegmentTable::circle_with_hole(1.0, 0.0, size).unwrap();
    for alpha in [0.0, 0.4, 1.0] {
        let law = SpinLaw::new(alpha).unwrap();
        let billiard = Billiard::new(&table, law);
        let (mut compared, mut escaped) = (0, 0);
        for i in 0..300 {
            let start = Sampler::Paper.initial_state(&table, &law, 11, i);
            let Some(exact) = circle_exit(&law, &start, size, budget, 1e-9) else {
                continue;
            };
            compared += 1;
            let mut ball = billiard.launch(start).unwrap();
            let (mut collisions, mut time) = (0u64, 0.0);
            let got = loop {
                if collisions == budget + 1 {
                    break None;
                }
                let event = billiard.advance(&mut ball).unwrap();
                time += event.time();
                match event {
                    Event::Collision(_) => collisions += 1,
                    Event::Escape(exit) => break Some(exit),
                    Event::Crossing(c) => panic!("no periodic walls: {c:?}"),
                }
            };
            match (exact, got) {
                (Some((n, t, a, u)), Some(exit)) => {
                    escaped += 1;
                    assert_eq!(collisions, n, "α = {alpha}, IC {i}");
                    assert!(
                        (time - t).abs() < 1e-9 * t.max(1.0),
                        "α = {alpha}, IC {i}: {time} vs {t}"
                    );
                    assert!((exit.v_par - a).abs() < 1e-9, "α = {alpha}, IC {i}");
                    assert!((exit.spin - u).abs() < 1e-9, "α = {alpha}, IC {i}");
                }
                (None, None) => {}
                (e, g) => panic!("α = {alpha}, IC {i}: exact {e:?}, simulated {g:?}"),
            }
        }
        assert!(compared >= 290, "α = {alpha}: only {compared} compared");
        assert!(escaped >= 200, "α = {alpha}: only {escaped} escaped");
    }
}

#[test]
fn the_cell_after_ten_million_crossings_is_exact() {
    // A ball flying along the corridor y = 0.1 of the square Lorentz gas
    // (disks of radius 0.3 at the cells' centres: the corridor is
    // y < 0.2) crosses one cell per unit time and never collides.
    let table = LorentzGas::square(1.0, 0.3).unwrap().table().unwrap();
    let billiard = Billiard::new(&table, SpinLaw::new(0.5).unwrap());
    let mut ball = billiard
        .launch(State::new(DVec2::new(0.5, 0.1), DVec2::new(1.0, 0.0), 0.2))
        .unwrap();
    let n: i64 = 10_000_000;
    for _ in 0..n {
        let event = billiard.advance(&mut ball).unwrap();
        assert!(matches!(event, Event::Crossing(_)), "{event:?}");
    }
    assert_eq!(ball.cell(), Cell::new(n, 0));
    assert_eq!(ball.position(), DVec2::new(0.0, 0.1));
    assert_eq!(billiard.unwrapped(&ball), DVec2::new(n as f64, 0.1));
    // And down a vertical corridor, x = 0.05.
    let mut ball = billiard
        .launch(State::new(
            DVec2::new(0.05, 0.5),
            DVec2::new(0.0, -3.0),
            0.0,
        ))
        .unwrap();
    for _ in 0..1_000_000 {
        billiard.advance(&mut ball).unwrap();
    }
    assert_eq!(ball.cell(), Cell::new(0, -1_000_000));
    assert_eq!(billiard.unwrapped(&ball), DVec2::new(0.05, -999_999.0));
}

#[test]
fn step_on_a_periodic_table_is_advance_without_the_crossings() {
    // `step` flies through periodic walls: its collisions are advance's
    // collisions, its flight times the sums of the flights between them,
    // and both balls end in the same cell at the same state.
    for table in [
        LorentzGas::square(1.0, 0.2).unwrap().table().unwrap(),
        LorentzGas::triangular(1.0, 0.44).unwrap().table().unwrap(),
    ] {
        let law = SpinLaw::new(0.4).unwrap();
        let billiard = Billiard::new(&table, law);
        let start = Sampler::Paper.initial_state(&table, &law, 5, 0);
        let mut stepped = billiard.launch(start).unwrap();
        let mut advanced: Ball = stepped;
        let mut crossings = 0u64;
        for _ in 0..5000 {
            let c = billiard.step(&mut stepped).unwrap();
            let mut time = 0.0;
            loop {
                let event = billiard.advance(&mut advanced).unwrap();
                time += event.time();
                match event {
                    Event::Collision(d) => {
                        assert_eq!(d.wall(), c.wall());
                        assert_eq!(d.point(), c.point());
                        break;
                    }
                    Event::Crossing(_) => crossings += 1,
                    Event::Escape(e) => panic!("{e:?}"),
                }
            }
            assert!(
                (time - c.time()).abs() <= 1e-12 * time,
                "{time} vs {}",
                c.time()
            );
            assert_eq!(advanced, stepped);
        }
        assert!(crossings > 1000, "{crossings}");
        let e0 = billiard.energy(&start);
        assert!((billiard.energy(stepped.state()) - e0).abs() < 1e-14 * e0);
        assert!(table.contains(stepped.position()));
    }
}
