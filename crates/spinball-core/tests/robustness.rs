//! No escape, no NaN, no stall: random initial conditions for 1e6 collisions
//! on every table (1e8 in an ignored test), and the hard cases one by one:
//! exact corner hits, stadium junctions, grazing hits on caps and on the
//! Sinai disk, balls moving exactly along a wall, balls starting on a wall,
//! and a non-convex table built from segments (the mushroom).

mod common;

use std::f64::consts::PI;

use common::{ALPHAS, law, paper_tables, signed_distance};
use spinball_core::{
    Ball, Billiard, Boundary, Collision, MAX_ZERO_TIME_RUN, Sampler, State, StepError,
};
use spinball_geometry::{DVec2, Table};
use spinball_test_support::mushroom;

/// Checks every collision of a run: finite state and flight time, the
/// contact where the straight flight says it is (no teleport), the ball on
/// or inside the walls, and, for the Sinai table, a flight that did not pass
/// through the obstacle.
struct Guard<'a> {
    table: &'a Table,
    prev: State,
    scale: f64,
    time: f64,
    worst_outside: f64,
}

impl<'a> Guard<'a> {
    fn new(table: &'a Table, start: State) -> Self {
        Guard {
            table,
            prev: start,
            scale: table.length_scale(),
            time: 0.0,
            worst_outside: 0.0,
        }
    }
}

impl spinball_core::Observer for Guard<'_> {
    fn observe(&mut self, c: &Collision, after: &State) {
        let t = c.time();
        assert!(t.is_finite() && t >= 0.0, "{}: flight time {t}", self.table);
        assert!(
            common::finite(after),
            "{}: non-finite state {after:?}",
            self.table
        );
        // The contact lies on the straight flight from the previous contact:
        // rounding of x + v t is ε(|x| + |v| t); the snap onto the wall moves
        // it by a few ulps of the size. 1e-12 of (size + distance flown).
        let flown = self.prev.velocity.length() * t;
        let ray = self.prev.position + self.prev.velocity * t;
        assert!(
            (ray - c.point()).length() <= 1e-12 * (self.scale + flown),
            "{}: contact {:?} is off the flight line ({:?})",
            self.table,
            c.point(),
            ray
        );
        // On the wall: at most a few ulps of the size outside (64 ε is the
        // tables' own tolerance; we allow 1e-12 of the size).
        let d = signed_distance(self.table, after.position);
        self.worst_outside = self.worst_outside.max(-d);
        assert!(
            d >= -1e-12 * self.scale,
            "{}: outside by {:e}",
            self.table,
            -d
        );
        assert!(
            self.table.contains(after.position),
            "{}: {:?}",
            self.table,
            after.position
        );
        if let Table::Sinai(s) = self.table {
            // Closest approach of the flight segment to the disk centre.
            let closest = common::closest_to_origin(self.prev.position, after.position);
            assert!(
                closest >= s.r() * (1.0 - 1e-12),
                "{}: flew through the disk ({closest})",
                self.table
            );
        }
        self.time += t;
        self.prev = *after;
    }
}

/// Run `n` collisions from `start` under the guard; returns the flight time.
fn guarded_run(billiard: &Billiard<Table>, start: State, n: u64) -> f64 {
    let table = billiard.table();
    let mut ball = billiard
        .launch(start)
        .unwrap_or_else(|e| panic!("{table}: {e}"));
    let mut guard = Guard::new(table, start);
    let run = billiard
        .run(&mut ball, n, &mut guard)
        .unwrap_or_else(|e| panic!("{table} from {start:?}: {e}"));
    assert_eq!(run.collisions, n);
    // Energy is kept (see energy.rs for the ulp-level statement).
    let e0 = start.energy(billiard.law());
    assert!((billiard.energy(ball.state()) - e0).abs() <= 1e-14 * e0);
    guard.time
}

#[test]
fn random_initial_conditions_never_escape() {
    // The four paper tables, both samplers, α in {0, 0.3, 1, 5}: 1e6
    // collisions each (32e6 in all).
    for table in paper_tables() {
        for alpha in ALPHAS {
            let billiard = Billiard::new(table, law(alpha));
            for (k, sampler) in [Sampler::Paper, Sampler::Microcanonical]
                .into_iter()
                .enumerate()
            {
                let start = sampler.initial_state(&table, billiard.law(), 1234, k as u64);
                let time = guarded_run(&billiard, start, 1_000_000);
                assert!(time > 0.0);
            }
        }
    }
}

#[test]
fn other_shapes_never_escape() {
    // Thin and long stadiums, small and large obstacles, a flat rectangle:
    // 1e5 collisions each, random α ∈ {0.4, 5}.
    for spec in [
        "stadium:a=0.2",
        "stadium:a=4",
        "sinai:L=2,R=0.3",
        "sinai:L=2,R=1.5",
        "sinai:L=1,R=0.99",
        "rectangle:L=10,H=0.1",
        "circle:R=1000",
    ] {
        let table: Table = spec.parse().unwrap();
        for alpha in [0.4, 5.0] {
            let billiard = Billiard::new(table, law(alpha));
            let start = Sampler::Microcanonical.initial_state(&table, billiard.law(), 99, 0);
            guarded_run(&billiard, start, 100_000);
        }
    }
}

#[test]
#[ignore = "long: 1e8 collisions per table, 4e8 in all (about a minute in the test profile)"]
fn hundred_million_collisions_never_escape() {
    for table in paper_tables() {
        let billiard = Billiard::new(table, law(0.5));
        let start = Sampler::Paper.initial_state(&table, billiard.law(), 4321, 0);
        guarded_run(&billiard, start, 100_000_000);
    }
}

/// A state aimed from `from` at `to` with speed `speed` and spin `spin`.
fn aim(from: DVec2, to: DVec2, speed: f64, spin: f64) -> State {
    State::new(from, (to - from).normalize() * speed, spin)
}

/// `n` guarded collisions from `start`: `Some(flight time)`, or `None` if
/// the ball got stuck (the only error accepted: a run of zero-time
/// collisions, `StepError::Stuck`, which an exactly tangent velocity at a
/// curved wall produces).
fn run_or_stuck(billiard: &Billiard<Table>, start: State, n: u64) -> Option<f64> {
    let table = billiard.table();
    let mut ball = billiard.launch(start).unwrap();
    let mut guard = Guard::new(table, start);
    match billiard.run(&mut ball, n, &mut guard) {
        Ok(_) => Some(guard.time),
        Err(StepError::Stuck { collisions, .. }) => {
            assert_eq!(collisions, MAX_ZERO_TIME_RUN + 1);
            None
        }
        Err(e) => panic!("{table} from {start:?}: {e}"),
    }
}

/// 1e4 guarded collisions for each α; returns the flight time at each α.
fn keep_going(table: &Table, start_for: impl Fn(f64) -> State) -> Vec<f64> {
    ALPHAS
        .iter()
        .map(|&alpha| {
            let billiard = Billiard::new(*table, law(alpha));
            guarded_run(&billiard, start_for(alpha), 10_000)
        })
        .collect()
}

#[test]
fn exact_corner_hits() {
    // Rectangle 1.5 × 1, aimed exactly at the corner (1.5, 1) (the path from
    // (0.5, 0) along (1, 1) meets x = 1.5 and y = 1 at the same time, exactly).
    // Documented rule: the two walls in turn, lower id (right, 1) first, the
    // second with zero flight time; at α = 0 this reverses the velocity.
    let table: Table = "rectangle:L=1.5,H=1".parse().unwrap();
    let start = State::new(DVec2::new(0.5, 0.0), DVec2::new(0.6, 0.6), 0.3);
    let billiard = Billiard::new(table, law(0.0));
    let mut ball = billiard.launch(start).unwrap();
    let a = billiard.step(&mut ball).unwrap();
    let b = billiard.step(&mut ball).unwrap();
    assert_eq!((a.wall(), b.wall()), (1, 2));
    assert_eq!(a.point(), DVec2::new(1.5, 1.0));
    assert_eq!((b.point(), b.time()), (DVec2::new(1.5, 1.0), 0.0));
    assert!((ball.velocity() + start.velocity).length() <= 1e-15);
    assert_eq!(ball.spin(), start.spin);
    // With spin the corner is two ordinary collisions in a row, and the ball
    // goes on. All four tables' corners, each α, 1e4 collisions.
    for corner in [
        DVec2::new(1.5, 1.0),
        DVec2::new(-1.5, 1.0),
        DVec2::new(-1.5, -1.0),
        DVec2::new(1.5, -1.0),
    ] {
        let times = keep_going(&table, |_| aim(DVec2::new(0.1, 0.2), corner, 0.8, 0.4));
        assert!(times.iter().all(|&t| t > 0.0));
    }
    // The diagonal of the square goes corner to corner forever at α = 0.
    let square: Table = "rectangle".parse().unwrap();
    keep_going(&square, |_| {
        State::new(DVec2::ZERO, DVec2::new(0.5, 0.5), 0.1)
    });
    // Sinai box corners, on lines that miss the disk.
    let sinai: Table = "sinai:L=2,R=1".parse().unwrap();
    for (from, corner) in [
        (DVec2::new(1.5, 0.0), DVec2::new(2.0, 2.0)),
        (DVec2::new(-1.5, 1.5), DVec2::new(-2.0, -2.0)),
        (DVec2::new(0.0, -1.5), DVec2::new(2.0, -2.0)),
        (DVec2::new(-1.2, 1.6), DVec2::new(-2.0, 2.0)),
    ] {
        let times = keep_going(&sinai, |_| aim(from, corner, 0.9, -0.3));
        assert!(times.iter().all(|&t| t > 0.0));
        let billiard = Billiard::new(sinai, law(0.0));
        let mut ball = billiard.launch(aim(from, corner, 0.9, 0.0)).unwrap();
        let c = billiard.step(&mut ball).unwrap();
        assert_eq!(c.point(), corner, "aimed at {corner:?}");
    }
}

#[test]
fn stadium_junctions() {
    // Aimed exactly at the flat–cap junctions (±a, ±1): the documented rule
    // gives the flat wall (the tangent is continuous there, so the collision
    // is the same either way).
    for spec in ["stadium:a=1", "stadium:a=0.2", "stadium:a=4"] {
        let table: Table = spec.parse().unwrap();
        let Table::Stadium(s) = table else {
            unreachable!()
        };
        let a = s.a();
        for (from, junction) in [
            (DVec2::ZERO, DVec2::new(a, 1.0)),
            (DVec2::new(0.3, -0.2), DVec2::new(-a, 1.0)),
            (DVec2::new(-0.1, 0.5), DVec2::new(-a, -1.0)),
            (DVec2::new(a + 0.5, 0.0), DVec2::new(a, -1.0)),
        ] {
            let times = keep_going(&table, |_| aim(from, junction, 0.7, 0.5));
            assert!(times.iter().all(|&t| t > 0.0));
            let billiard = Billiard::new(table, law(0.3));
            let mut ball = billiard.launch(aim(from, junction, 0.7, 0.5)).unwrap();
            let c = billiard.step(&mut ball).unwrap();
            assert!(
                (c.point() - junction).length() <= 1e-15 * a.max(1.0),
                "{spec}: {:?}",
                c.point()
            );
            assert!(
                c.wall() == 0 || c.wall() == 2,
                "{spec}: the flat wall takes the junction"
            );
        }
    }
}

#[test]
fn grazing_hits() {
    let stadium: Table = "stadium:a=1".parse().unwrap();
    // On the right cap at angle 0.3, moving along the wall turned inward by
    // 1e-9 rad: a whispering-gallery creep of chords ~2e-9 long. At 1e-9
    // rounding turns the velocity exactly tangent within a few collisions
    // at some α (0 and 0.3: the contact's v·n computes to 0), after which
    // every collision takes zero time: that is reported as
    // `StepError::Stuck` (issue 9), never an `Ok` run that stopped moving.
    let p = DVec2::new(1.0, 0.0) + DVec2::from_angle(0.3);
    let along = DVec2::from_angle(0.3 + 0.5 * PI);
    for turn in [1e-9, 1e-6, 1e-3] {
        let v = DVec2::from_angle(turn).rotate(along);
        for alpha in ALPHAS {
            let billiard = Billiard::new(stadium, law(alpha));
            match run_or_stuck(&billiard, State::new(p, v * 0.9, 0.2), 10_000) {
                Some(t) => assert!(t > 0.0),
                None => assert_eq!(turn, 1e-9, "stuck at turn {turn}, α = {alpha}"),
            }
        }
    }
    // From just below the top flat wall, horizontally into the cap: the cap
    // is met near its top at a grazing angle ~√(2e-12).
    keep_going(&stadium, |_| {
        State::new(DVec2::new(0.0, 1.0 - 1e-12), DVec2::new(0.8, 0.0), -0.3)
    });
    // Exactly horizontal through the middle and half way up.
    for y in [0.0, 0.5, -0.999_999] {
        let times = keep_going(&stadium, |_| {
            State::new(DVec2::new(0.2, y), DVec2::new(-0.8, 0.0), 0.1)
        });
        assert!(times.iter().all(|&t| t > 0.0));
    }

    // The Sinai disk (r = 1), met from (−1.5, y) moving +x: y just inside r
    // (a grazing hit on the disk), exactly r (tangent: it passes by, the
    // contact is measure-zero), just outside r (a near miss).
    let sinai: Table = "sinai:L=2,R=1".parse().unwrap();
    for (y, first_wall) in [
        (1.0 - 1e-12, 4),
        (1.0, 1),
        (1.0 + 1e-12, 1),
        (1.0 - 1e-6, 4),
    ] {
        let start = State::new(DVec2::new(-1.5, y), DVec2::new(0.9, 0.0), 0.2);
        let billiard = Billiard::new(sinai, law(0.5));
        let mut ball = billiard.launch(start).unwrap();
        assert_eq!(
            billiard.step(&mut ball).unwrap().wall(),
            first_wall,
            "y = {y}"
        );
        let times = keep_going(&sinai, |_| start);
        assert!(times.iter().all(|&t| t > 0.0));
    }
}

#[test]
fn moving_along_a_wall() {
    // Rectangle: along the bottom wall, bouncing between the side walls.
    let rect: Table = "rectangle".parse().unwrap();
    let times = keep_going(&rect, |_| {
        State::new(DVec2::new(0.0, -1.0), DVec2::new(0.7, 0.0), 0.3)
    });
    assert!(times.iter().all(|&t| t > 0.0));

    // Stadium: exactly along a flat wall into a junction. The cap is tangent
    // there, so the ray leaves the table at once: the contact is a collision
    // with zero normal velocity (v⊥ = 0) at the junction. The law still
    // trades v∥ and u (paper eqs. 1, 3), so what follows depends on α:
    // usually the ball stays at the junction, flipping between zero-time
    // contacts for ever (the limit of an ever finer whispering-gallery
    // creep), and sometimes the exchange sends it back along the wall. The
    // first is `StepError::Stuck` (issue 9: a run that stopped moving is not
    // an `Ok`); the second goes on. Never a NaN or an escape.
    let stadium: Table = "stadium:a=1".parse().unwrap();
    for alpha in ALPHAS {
        let billiard = Billiard::new(stadium, law(alpha));
        let start = State::new(DVec2::new(0.0, 1.0), DVec2::new(0.8, 0.0), 0.3);
        if let Some(t) = run_or_stuck(&billiard, start, 10_000) {
            assert!(t > 0.0);
        }
    }
    for alpha in [0.0, 0.3, 5.0] {
        let billiard = Billiard::new(stadium, law(alpha));
        let start = State::new(DVec2::new(0.5, -1.0), DVec2::new(-0.8, 0.0), 0.0);
        if let Some(t) = run_or_stuck(&billiard, start, 10_000) {
            assert!(t > 0.0);
        }
    }
    // The one case that cannot go on: a thin ring (α = 1, β = 0) without spin
    // arriving with v⊥ = 0 gives all its velocity to the spin
    // (v∥' = −u = 0, u' = −v∥) and comes to rest on the wall. Energy is kept
    // (½ α u'² = ½ |v|²), and the next step reports that no wall lies ahead
    // (an error, never a NaN or a flight to infinity).
    let billiard = Billiard::new(stadium, law(1.0));
    let mut ball = billiard
        .launch(State::new(
            DVec2::new(0.5, -1.0),
            DVec2::new(-0.8, 0.0),
            0.0,
        ))
        .unwrap();
    let c = billiard.step(&mut ball).unwrap();
    assert_eq!((c.wall(), c.point()), (3, DVec2::new(-1.0, -1.0)));
    assert_eq!(ball.velocity().length(), 0.0);
    assert!((ball.spin() - 0.8).abs() <= 1e-15);
    assert!(matches!(
        billiard.step(&mut ball),
        Err(spinball_core::StepError::NoWall { .. })
    ));
}

#[test]
fn starting_on_a_wall() {
    // On the wall moving in (the usual state after a collision), and on the
    // wall moving out (a zero-time collision first), for each table.
    let cases: [(&str, DVec2, DVec2); 8] = [
        ("circle", DVec2::new(1.0, 0.0), DVec2::new(-0.6, 0.3)),
        ("circle", DVec2::new(0.0, -1.0), DVec2::new(0.2, -0.7)),
        ("rectangle", DVec2::new(1.0, 1.0), DVec2::new(-0.6, -0.3)),
        ("rectangle", DVec2::new(1.0, 0.3), DVec2::new(0.6, 0.3)),
        ("stadium:a=1", DVec2::new(1.0, 1.0), DVec2::new(0.5, 0.5)),
        (
            "stadium:a=1",
            DVec2::new(-1.0 - 0.6, -0.8),
            DVec2::new(-0.5, 0.1),
        ),
        ("sinai:L=2,R=1", DVec2::new(1.0, 0.0), DVec2::new(0.6, 0.2)),
        ("sinai:L=2,R=1", DVec2::new(0.0, -1.0), DVec2::new(0.3, 0.6)),
    ];
    for (spec, p, v) in cases {
        let table: Table = spec.parse().unwrap();
        let times = keep_going(&table, |_| State::new(p, v, -0.2));
        assert!(times.iter().all(|&t| t > 0.0), "{spec} from {p:?}");
    }
}

#[test]
fn a_non_convex_table_from_segments() {
    // The mushroom is not convex: from the shoulders (y = 0, |x| > 0.3) the
    // ball can move towards the line of a stem wall from behind it. Every
    // contact must be on the flight line (no jump to a wall it never
    // reached) and inside the mushroom, for 1e5 collisions from several ICs.
    let m = mushroom();
    let inside = |p: DVec2| {
        let tol = 1e-12;
        let cap = p.y >= -tol && p.length() <= 1.0 + tol;
        let stem = p.x.abs() <= 0.3 + tol && p.y >= -1.0 - tol && p.y <= tol;
        cap || stem
    };
    for alpha in [0.0, 0.4, 5.0] {
        let billiard = Billiard::new(m.clone(), law(alpha));
        for index in 0..4 {
            let start = Sampler::Microcanonical.initial_state(&m, billiard.law(), 5, index);
            let mut ball = billiard.launch(start).unwrap();
            let mut prev = start;
            let mut shoulder_hits = 0;
            let mut check = |c: &Collision, after: &State| {
                let ray = prev.position + prev.velocity * c.time();
                assert!(
                    (ray - c.point()).length() <= 1e-12 * (1.0 + prev.velocity.length() * c.time()),
                    "alpha {alpha}: contact {:?} off the flight line from {:?} (ray {ray:?})",
                    c.point(),
                    prev.position
                );
                assert!(inside(after.position), "{:?}", after.position);
                shoulder_hits += usize::from(c.wall() == 2 || c.wall() == 4);
                prev = *after;
            };
            billiard.run(&mut ball, 100_000, &mut check).unwrap();
            assert!(shoulder_hits > 0);
        }
    }
    // The specific case: leaving the right shoulder up and to the right, the
    // stem's right wall (x = 0.3, facing −x) is behind the ball; the cap is
    // the next wall.
    let hit = m
        .cast(DVec2::new(0.54, 0.0), DVec2::new(0.75, 0.57))
        .unwrap();
    assert_eq!(hit.wall, 3);
    assert!(hit.time > 0.1);
    // And Ball::new + step from there agrees.
    let billiard = Billiard::new(m, law(0.4));
    let mut ball = Ball::new(
        State::new(DVec2::new(0.54, 0.0), DVec2::new(0.75, 0.57), 0.1),
        billiard.law(),
    )
    .unwrap();
    assert_eq!(billiard.step(&mut ball).unwrap().wall(), 3);
}
