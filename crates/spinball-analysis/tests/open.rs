//! Ensembles on open and periodic tables: escape and displacement records,
//! their censoring and reproducibility, and λ on the unfolded Sinai table.

use spinball_analysis::estimators::Method;
use spinball_analysis::open::{Budget, EscapeRecord, OpenEnsemble};
use spinball_analysis::run::{Engine, Ensemble, Shard, Threads};
use spinball_core::{Billiard, SpinLaw};
use spinball_geometry::{Boundary, LorentzGas, SegmentTable, Sinai};

fn stadium_with_hole() -> SegmentTable {
    // A hole of arc length 0.3 in the middle of the right cap.
    SegmentTable::stadium_with_hole(1.0, 2.0 + 0.5 * std::f64::consts::PI, 0.3).unwrap()
}

/// The records of `ensemble` run in `n` shards, concatenated in order.
fn escapes_in_shards(
    ensemble: &OpenEnsemble<SegmentTable>,
    n: u64,
    budget: Budget,
) -> Vec<EscapeRecord> {
    (0..n)
        .flat_map(|k| {
            ensemble
                .clone()
                .with_shard(Shard::new(k, n).unwrap())
                .escape_times(budget)
                .unwrap()
        })
        .collect()
}

#[test]
fn escape_records_are_bitwise_the_same_on_any_threads_and_shards() {
    let law = SpinLaw::new(0.4).unwrap();
    let ensemble = OpenEnsemble::new(Billiard::new(stadium_with_hole(), law))
        .with_seed(7)
        .with_indices(0..200);
    let budget = Budget::collisions(300);
    let one = ensemble
        .clone()
        .with_threads(Threads::Fixed(1))
        .escape_times(budget)
        .unwrap();
    let two = ensemble
        .clone()
        .with_threads(Threads::Fixed(2))
        .escape_times(budget)
        .unwrap();
    assert_eq!(one, two);
    let shards = escapes_in_shards(&ensemble, 3, budget);
    assert_eq!(one, shards);
    // One record per initial condition, in order; some escape, some are
    // censored (a hole of 0.3 in a perimeter of 4 + 2π: the mean escape
    // takes about 34 collisions, so 300 leave a few inside).
    assert_eq!(one.len(), 200);
    assert!(one.iter().enumerate().all(|(i, r)| r.index == i as u64));
    let censored = one.iter().filter(|r| r.censored).count();
    assert!(censored < 100, "{censored}");
    for r in &one {
        if r.censored {
            assert_eq!(r.collisions, 300);
            assert!(r.exit.is_none());
        } else {
            let exit = r.exit.unwrap();
            assert_eq!(exit.wall, 2);
            assert!(r.collisions < 300 && r.time > 0.0);
        }
    }
}

#[test]
fn a_ball_still_inside_is_censored_never_dropped() {
    let law = SpinLaw::new(0.0).unwrap();
    // No hole: every record is censored at the budget.
    let closed = SegmentTable::new(stadium_with_hole().walls().to_vec()).unwrap();
    let records = OpenEnsemble::new(Billiard::new(closed, law))
        .with_indices(0..20)
        .escape_times(Budget::collisions(1000))
        .unwrap();
    assert_eq!(records.len(), 20);
    assert!(records.iter().all(|r| r.censored && r.collisions == 1000));
    // A time budget: censored at exactly that time.
    let records = OpenEnsemble::new(Billiard::new(stadium_with_hole(), law))
        .with_indices(0..50)
        .escape_times(Budget::time(5.0))
        .unwrap();
    assert_eq!(records.len(), 50);
    for r in &records {
        assert!(r.time <= 5.0);
        assert_eq!(r.censored, r.exit.is_none());
        if r.censored {
            assert_eq!(r.time, 5.0);
        }
    }
    assert!(records.iter().any(|r| r.censored) && records.iter().any(|r| !r.censored));
    // Budgets that run nothing are refused.
    let e = OpenEnsemble::new(Billiard::new(stadium_with_hole(), law));
    assert!(e.escape_times(Budget::collisions(0)).is_err());
    assert!(e.escape_times(Budget::time(f64::NAN)).is_err());
}

#[test]
fn displacements_are_bitwise_the_same_on_any_threads_and_shards() {
    let table = LorentzGas::triangular(1.0, 0.45).unwrap().table().unwrap();
    let law = SpinLaw::new(0.5).unwrap();
    let ensemble = OpenEnsemble::new(Billiard::new(table, law))
        .with_seed(3)
        .with_indices(0..64);
    let times = [1.0, 10.0, 100.0, 1000.0];
    let one = ensemble
        .clone()
        .with_threads(Threads::Fixed(1))
        .displacements(&times)
        .unwrap();
    let two = ensemble
        .clone()
        .with_threads(Threads::Fixed(2))
        .displacements(&times)
        .unwrap();
    assert_eq!(one, two);
    let mut shards = Vec::new();
    for k in 0..4 {
        shards.extend(
            ensemble
                .clone()
                .with_shard(Shard::new(k, 4).unwrap())
                .displacements(&times)
                .unwrap(),
        );
    }
    assert_eq!(one, shards);
    // The speed bounds the displacement (|v| ≤ |V| = 1 for the paper
    // sampler), and by t = 1000 most balls have crossed many cells. (Not
    // all: at α = 0.5 a ball can rattle in the gap between two disks for
    // the whole run, the rough-ball collision sending it back the way it
    // came; initial condition 0 does, 5697 collisions and no crossing.)
    for r in &one {
        assert_eq!(r.displacement.len(), 4);
        for (d, t) in r.displacement.iter().zip(times) {
            assert!(d.length() <= t * (1.0 + 1e-12), "{d} at {t}");
        }
    }
    let travelled = one.iter().filter(|r| r.crossings > 100).count();
    assert!(travelled > 48, "{travelled}");
    let far = one
        .iter()
        .filter(|r| r.displacement[3].length() > 5.0)
        .count();
    assert!(far > 32, "{far}");
    // Bad checkpoint times and tables with holes are refused.
    assert!(ensemble.displacements(&[]).is_err());
    assert!(ensemble.displacements(&[2.0, 1.0]).is_err());
    let holed = OpenEnsemble::new(Billiard::new(stadium_with_hole(), law));
    assert!(holed.displacements(&[1.0]).is_err());
}

#[test]
fn the_square_lorentz_gas_has_the_lyapunov_exponent_of_the_sinai_cell() {
    // At α = 0 the square Lorentz gas is the Sinai table unfolded: the
    // flat walls' reflections become translations, which leave the
    // tangent map unchanged, so λ per unit time is the same (per
    // collision it is not: the Sinai table counts its wall bounces). Both
    // are ensemble means of finite-time exponents with their SEM; they
    // must agree within 3 combined SEM.
    let law = SpinLaw::new(0.0).unwrap();
    let (l, r) = (1.0, 0.4);
    let run = |e: spinball_analysis::run::LyapunovEstimate| (e.mean(), e.sem());
    // Equal times: the mean free time πA/P is 1.045 in the Sinai table
    // (walls and disk count) and 4.37 in the cell (the disk only).
    let sinai = Ensemble::new(Sinai::new(l, r).unwrap(), law)
        .with_ics(400)
        .with_collisions(4000)
        .with_method(Method::Tangent)
        .with_engine(Engine::Scalar)
        .with_seed(2)
        .run()
        .unwrap();
    let cell = LorentzGas::square(2.0 * l, r).unwrap().table().unwrap();
    assert!(cell.lattice().is_some());
    let periodic = Ensemble::new(cell, law)
        .with_ics(400)
        .with_collisions(960)
        .with_method(Method::Tangent)
        .with_seed(2)
        .run()
        .unwrap();
    // An open table never runs in lanes.
    assert_eq!(periodic.engine(), Engine::Scalar);
    let ((a, sa), (b, sb)) = (run(sinai), run(periodic));
    let sem = (sa * sa + sb * sb).sqrt();
    eprintln!("λ per unit time at α = 0: Sinai {a} ± {sa}, square Lorentz gas {b} ± {sb}");
    assert!(
        (a - b).abs() < 3.0 * sem,
        "Sinai {a} ± {sa}, Lorentz {b} ± {sb}"
    );
    assert!(a > 0.5, "{a}");
    // Finite differences would compare balls in different cells: refused.
    let fd = Ensemble::new(LorentzGas::square(2.0, r).unwrap().table().unwrap(), law)
        .with_ics(4)
        .with_collisions(10)
        .run();
    assert!(fd.is_err(), "{fd:?}");
}

#[test]
fn the_lane_engine_refuses_open_tables() {
    use spinball_lanes::{LaneBilliard, LanesError, has_lane_form};
    let law = SpinLaw::new(0.5).unwrap();
    let closed = SegmentTable::new(stadium_with_hole().walls().to_vec()).unwrap();
    assert!(has_lane_form(&closed));
    for open in [
        stadium_with_hole(),
        LorentzGas::square(1.0, 0.3).unwrap().table().unwrap(),
    ] {
        assert!(!has_lane_form(&open));
        assert!(matches!(
            LaneBilliard::new(open, law),
            Err(LanesError::OpenTable)
        ));
    }
}

#[test]
fn escape_records_are_bitwise_the_same_on_both_engines() {
    let tables = [
        stadium_with_hole(),
        SegmentTable::sinai_with_hole(1.0, 0.4, 3.0, 0.3).unwrap(),
        SegmentTable::circle_with_hole(1.0, 0.3, 0.4).unwrap(),
    ];
    for table in tables {
        // Censored and escaped records compared, on each table.
        let mut counts = [0; 2];
        for alpha in [0.0, 0.4, 1.0] {
            let law = SpinLaw::new(alpha).unwrap();
            let ensemble = OpenEnsemble::new(Billiard::new(table.clone(), law))
                .with_seed(3)
                .with_indices(0..150);
            assert_eq!(ensemble.engine_used(), Engine::Lanes);
            let scalar = ensemble.clone().with_engine(Engine::Scalar);
            assert_eq!(scalar.engine_used(), Engine::Scalar);
            for budget in [
                Budget::collisions(200),
                Budget::time(30.0),
                Budget {
                    collisions: 100,
                    time: 20.0,
                },
            ] {
                let what = format!(
                    "{}, α = {alpha}, {budget:?}",
                    table.name().unwrap_or("table")
                );
                let reference = scalar.escape_times(budget).unwrap();
                let lanes = ensemble
                    .clone()
                    .with_threads(Threads::Fixed(1))
                    .escape_times(budget)
                    .unwrap();
                // `==` on the records, and their times by their bits.
                assert_eq!(lanes, reference, "{what}");
                assert!(
                    lanes
                        .iter()
                        .zip(&reference)
                        .all(|(a, b)| a.time.to_bits() == b.time.to_bits()),
                    "{what}"
                );
                let censored = reference.iter().filter(|r| r.censored).count();
                counts[0] += censored;
                counts[1] += reference.len() - censored;
                let two = ensemble
                    .clone()
                    .with_threads(Threads::Fixed(2))
                    .escape_times(budget)
                    .unwrap();
                assert_eq!(two, reference, "{what}, 2 threads");
                let shards = escapes_in_shards(&ensemble, 2, budget);
                assert_eq!(shards, reference, "{what}, 2 shards");
            }
        }
        assert!(
            counts[0] > 50 && counts[1] > 50,
            "{:?}: {counts:?}",
            table.name()
        );
    }
}

#[test]
fn escape_runs_on_the_scalar_engine_where_the_lanes_cannot() {
    let law = SpinLaw::new(0.4).unwrap();
    // A built-in table (no holes) and a periodic table have no escape
    // lane form: the scalar engine runs them, whatever is asked.
    let stadium = OpenEnsemble::new(Billiard::new(
        spinball_geometry::Stadium::new(1.0).unwrap(),
        law,
    ));
    assert_eq!(stadium.engine_used(), Engine::Scalar);
    let gas = OpenEnsemble::new(Billiard::new(
        LorentzGas::square(1.0, 0.3).unwrap().table().unwrap(),
        law,
    ))
    .with_indices(0..5);
    assert_eq!(gas.engine_used(), Engine::Scalar);
    let records = gas.escape_times(Budget::collisions(50)).unwrap();
    assert!(records.iter().all(|r| r.censored && r.collisions == 50));
}
