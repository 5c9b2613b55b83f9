//! The escape kernel against the scalar path: on the stadium, the Sinai
//! table, the circle and a square with a hole, for every spin law the
//! crate runs and every instruction set this CPU has, every record
//! (escape time, collisions, exit) is **bitwise** what `Billiard::advance`
//! run until an escape or the budget gives, with budgets in collisions
//! and in time, censored balls included. An open table stays refused by
//! the other kernels.

use std::f64::consts::PI;

use spinball_core::{Ball, Billiard, Event, Exit, SpinLaw, State};
use spinball_geometry::{Boundary, DVec2, LorentzGas, SegmentTable, Stadium};
use spinball_lanes::{Escape, Isa, LaneBilliard, LanesError, has_escape_lane_form, has_lane_form};
use spinball_test_support::lanes::{draw, laws};

/// The tables with holes: the stadium with a hole on the right cap and
/// one on the bottom flat wall, the Sinai table with a hole in its box,
/// the circle with a hole, and a square with a hole (no arcs).
fn tables() -> Vec<(&'static str, SegmentTable)> {
    vec![
        (
            "stadium, cap hole",
            SegmentTable::stadium_with_hole(1.0, 2.0 + 0.5 * PI, 0.3).unwrap(),
        ),
        (
            "stadium, flat hole",
            SegmentTable::stadium_with_hole(1.0, 1.0, 0.4).unwrap(),
        ),
        (
            "sinai",
            SegmentTable::sinai_with_hole(1.0, 0.4, 3.0, 0.3).unwrap(),
        ),
        (
            "circle",
            SegmentTable::circle_with_hole(1.0, 0.3, 0.4).unwrap(),
        ),
        (
            "square",
            SegmentTable::polygon(&[
                DVec2::new(-1.0, -1.0),
                DVec2::new(1.0, -1.0),
                DVec2::new(1.0, 1.0),
                DVec2::new(-1.0, 1.0),
            ])
            .unwrap()
            .with_hole_at(5.0, 0.3)
            .unwrap(),
        ),
    ]
}

/// The scalar record of one ball: `Billiard::advance` until it escapes or
/// the budget is spent (the loop of `spinball-analysis`'s
/// `OpenEnsemble::escape_times`).
fn scalar<B: Boundary>(billiard: &Billiard<B>, start: State, collisions: u64, time: f64) -> Escape {
    let mut ball: Ball = billiard.launch(start).unwrap();
    let mut record = Escape {
        time: 0.0,
        collisions: 0,
        exit: None,
    };
    while record.collisions < collisions {
        let event = billiard.advance(&mut ball).unwrap();
        let t = record.time + event.time();
        if t > time {
            record.time = time;
            break;
        }
        record.time = t;
        match event {
            Event::Collision(_) => record.collisions += 1,
            Event::Crossing(_) => unreachable!("no periodic walls here"),
            Event::Escape(exit) => {
                record.exit = Some(exit);
                break;
            }
        }
    }
    record
}

/// The bits of an exit.
fn exit_bits(e: &Option<Exit>) -> Option<[u64; 7]> {
    e.map(|e| {
        [
            e.time.to_bits(),
            u64::from(e.wall),
            e.point.x.to_bits(),
            e.point.y.to_bits(),
            e.s.to_bits(),
            e.v_par.to_bits(),
            e.spin.to_bits(),
        ]
    })
}

/// `lanes` and `scalar` agree bitwise, record by record.
fn assert_bitwise(lanes: &[Escape], scalar: &[Escape], what: &str) {
    assert_eq!(lanes.len(), scalar.len(), "{what}");
    for (i, (a, b)) in lanes.iter().zip(scalar).enumerate() {
        assert_eq!(
            a.time.to_bits(),
            b.time.to_bits(),
            "{what}, start {i}: time"
        );
        assert_eq!(a.collisions, b.collisions, "{what}, start {i}: collisions");
        assert_eq!(
            exit_bits(&a.exit),
            exit_bits(&b.exit),
            "{what}, start {i}: exit"
        );
    }
}

#[test]
fn escapes_are_bitwise_the_scalar_advance_on_every_table_law_and_instruction_set() {
    // (collisions, time): a collision budget that censors some balls, a
    // time budget, both, and one so short that most are censored.
    let budgets = [
        (300, f64::INFINITY),
        (u64::MAX, 40.0),
        (150, 25.0),
        (3, f64::INFINITY),
    ];
    for (name, table) in tables() {
        assert!(has_escape_lane_form(&table) && !has_lane_form(&table));
        // Censored and escaped balls compared, on each table.
        let mut counts = [0; 2];
        for law in laws() {
            let billiard = Billiard::new(&table, law);
            // 2 × 45 starts (paper and microcanonical samplers): not a
            // multiple of any lane count, so every level runs a tail.
            let starts: Vec<State> = draw(&table, &law, 45, Vec::new())
                .into_iter()
                .map(|(s, _, _)| s)
                .collect();
            for (collisions, time) in budgets {
                let what = format!("{name}, α = {}, budget ({collisions}, {time})", law.alpha());
                let reference: Vec<Escape> = starts
                    .iter()
                    .map(|s| scalar(&billiard, *s, collisions, time))
                    .collect();
                for isa in Isa::available() {
                    let lanes = LaneBilliard::new_open(&table, law)
                        .unwrap()
                        .with_isa(isa)
                        .unwrap();
                    let got = lanes.escape_times(&starts, collisions, time).unwrap();
                    assert_bitwise(&got, &reference, &format!("{what}, {isa}"));
                }
                let threaded = LaneBilliard::new_open(&table, law)
                    .unwrap()
                    .with_threads(3)
                    .unwrap()
                    .escape_times(&starts, collisions, time)
                    .unwrap();
                assert_bitwise(&threaded, &reference, &format!("{what}, 3 threads"));
                if collisions == 3 {
                    // Most balls are still inside after three collisions.
                    let censored = reference.iter().filter(|e| e.is_censored()).count();
                    assert!(censored > reference.len() / 2, "{what}: {censored}");
                }
                let censored = reference.iter().filter(|e| e.is_censored()).count();
                counts[0] += censored;
                counts[1] += reference.len() - censored;
            }
        }
        assert!(counts[0] > 50 && counts[1] > 50, "{name}: {counts:?}");
    }
}

#[test]
fn a_closed_segment_table_censors_every_ball() {
    let table = SegmentTable::new(tables()[0].1.walls().to_vec()).unwrap();
    let law = SpinLaw::new(0.4).unwrap();
    let starts: Vec<State> = draw(&table, &law, 20, Vec::new())
        .into_iter()
        .map(|(s, _, _)| s)
        .collect();
    // `new` takes it (it is closed), and escape runs on it.
    let lanes = LaneBilliard::new(&table, law).unwrap();
    let got = lanes.escape_times(&starts, 500, f64::INFINITY).unwrap();
    assert!(got.iter().all(|e| e.is_censored() && e.collisions == 500));
    // The end times are the plain kernel's.
    let plain = lanes.trajectories(&starts, 500).unwrap();
    for (e, f) in got.iter().zip(&plain) {
        assert_eq!(e.time.to_bits(), f.time.to_bits());
    }
}

#[test]
fn open_tables_stay_refused_by_the_other_kernels() {
    let (_, table) = tables().remove(0);
    let law = SpinLaw::new(0.4).unwrap();
    assert!(matches!(
        LaneBilliard::new(&table, law),
        Err(LanesError::OpenTable)
    ));
    let lanes = LaneBilliard::new_open(&table, law).unwrap();
    let starts: Vec<State> = draw(&table, &law, 5, Vec::new())
        .into_iter()
        .map(|(s, _, _)| s)
        .collect();
    assert!(matches!(
        lanes.trajectories(&starts, 10),
        Err(LanesError::OpenTable)
    ));
    let dirs: Vec<_> = draw(&table, &law, 5, Vec::new())
        .into_iter()
        .map(|(_, d, _)| d)
        .collect();
    assert!(matches!(
        lanes.lyapunov_fd(&starts, &dirs, 1e-7, 10),
        Err(LanesError::OpenTable)
    ));
    assert!(matches!(
        lanes.start_tangent(&starts, &dirs),
        Err(LanesError::OpenTable)
    ));
    // Periodic walls and the built-in tables have no escape lane form.
    let gas = LorentzGas::square(1.0, 0.3).unwrap().table().unwrap();
    assert!(!has_escape_lane_form(&gas));
    assert!(matches!(
        LaneBilliard::new_open(&gas, law),
        Err(LanesError::NoEscapeForm { .. })
    ));
    let stadium = Stadium::new(1.0).unwrap();
    assert!(!has_escape_lane_form(&stadium));
    assert!(matches!(
        LaneBilliard::new(stadium, law)
            .unwrap()
            .escape_times(&starts, 10, 1.0),
        Err(LanesError::NoEscapeForm { .. })
    ));
    // Budgets that run nothing.
    assert!(matches!(
        lanes.escape_times(&starts, 0, 1.0),
        Err(LanesError::InvalidOption { .. })
    ));
    for bad in [0.0, -1.0, f64::NAN] {
        assert!(matches!(
            lanes.escape_times(&starts, 10, bad),
            Err(LanesError::InvalidOption { .. })
        ));
    }
}
