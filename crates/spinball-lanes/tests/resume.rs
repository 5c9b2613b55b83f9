//! A largest-exponent run stopped and resumed is bitwise the run that never
//! stopped: finite differences and exact tangent, on every built-in table
//! and spin law of the agreement tests, on every instruction set this CPU
//! has, with legs that are not multiples of the tangent kernel's
//! renormalisation interval (8) nor of any lane count.

use spinball_core::{SpinLaw, State, TangentVector};
use spinball_geometry::Table;
use spinball_lanes::{LaneBilliard, LanesError, Paused};
use spinball_test_support::lanes::{draw, lanes_for, laws, tables};

/// Leg lengths: 37 + 213 + 650 = 900.
const LEGS: [u64; 3] = [37, 213, 650];

/// Every field of the paused trajectories, bit for bit (`Debug` writes each
/// `f64` exactly, the sign of a zero included) — but with `uncoupled`
/// (exact tangent at α = 0) the tangent vector's spin component masked: at
/// α = 0 the spin takes no part in the dynamics, so `δu` never changes
/// while the vector grows, and the renormalisations shrink it into
/// subnormal numbers (below `1e-300`), where scaling by a power of two is
/// no longer exact and a run renormalised at other collisions keeps other
/// low bits. It enters neither the other components nor, at that size,
/// the vector's length: the stretch stays bitwise (checked unmasked).
fn bits(p: &Result<Vec<Paused>, LanesError>, uncoupled: bool) -> String {
    let Ok(paused) = p else {
        return format!("{p:?}");
    };
    paused
        .iter()
        .map(|x| {
            let mut text = format!("{x:?}");
            if uncoupled {
                let du = x.partner()[4];
                text = text.replace(&format!("{du:?}]"), "δu]");
            }
            format!("{text} {:?}\n", x.stretch())
        })
        .collect()
}

fn check(lanes: &LaneBilliard<Table>, starts: &[State], dirs: &[TangentVector], what: &str) {
    let total: u64 = LEGS.iter().sum();
    for fd in [true, false] {
        let uncoupled = !fd && !lanes.law().is_coupled();
        let start = || {
            {
                if fd {
                    lanes.start_fd(starts, dirs, 1e-7)
                } else {
                    lanes.start_tangent(starts, dirs)
                }
            }
            .unwrap()
        };
        let whole = lanes.resume(&start(), total);
        let mut legs = Ok(start());
        let mut reads = Vec::new();
        for t in LEGS {
            legs = legs.and_then(|p| lanes.resume(&p, t));
            reads.push(legs.clone());
        }
        assert_eq!(
            bits(&legs, uncoupled),
            bits(&whole, uncoupled),
            "{what}, fd {fd}, {}",
            lanes.isa()
        );
        // Each stop reads what a run of that length gives.
        let mut upto = 0;
        for (t, read) in LEGS.iter().zip(&reads) {
            upto += t;
            assert_eq!(
                bits(read, uncoupled),
                bits(&lanes.resume(&start(), upto), uncoupled),
                "{what}, fd {fd}, {} at {upto}",
                lanes.isa()
            );
        }
        // And the public one-shot runs are the same numbers.
        let one_shot = if fd {
            lanes.lyapunov_fd(starts, dirs, 1e-7, total)
        } else {
            lanes.lyapunov_tangent(starts, dirs, total)
        };
        assert_eq!(
            format!("{one_shot:?}"),
            format!(
                "{:?}",
                whole.map(|w| w.iter().map(Paused::stretch).collect::<Vec<_>>())
            ),
            "{what}, fd {fd}"
        );
    }
}

#[test]
fn resumed_runs_are_bitwise_uninterrupted_runs_on_every_instruction_set() {
    for table in tables() {
        for law in laws() {
            let ics = draw(&table, &law, 13, Vec::new());
            let starts: Vec<State> = ics.iter().map(|x| x.0).collect();
            let dirs: Vec<TangentVector> = ics.iter().map(|x| x.1).collect();
            for lanes in lanes_for(&table, &law) {
                check(
                    &lanes,
                    &starts,
                    &dirs,
                    &format!("{table:?}, α {}", law.alpha()),
                );
            }
        }
    }
}

#[test]
fn a_resume_runs_one_method() {
    let table = tables()[4];
    let law = SpinLaw::new(0.5).unwrap();
    let ics = draw(&table, &law, 2, Vec::new());
    let starts: Vec<State> = ics.iter().map(|x| x.0).collect();
    let dirs: Vec<TangentVector> = ics.iter().map(|x| x.1).collect();
    let lanes = LaneBilliard::new(table, law).unwrap();
    let mut mixed = lanes.start_fd(&starts, &dirs, 1e-7).unwrap();
    mixed.extend(lanes.start_tangent(&starts, &dirs).unwrap());
    assert!(matches!(
        lanes.resume(&mixed, 10),
        Err(LanesError::InvalidOption { name: "paused", .. })
    ));
    let mut deltas = lanes.start_fd(&starts, &dirs, 1e-7).unwrap();
    deltas.extend(lanes.start_fd(&starts, &dirs, 1e-8).unwrap());
    assert!(matches!(
        lanes.resume(&deltas, 10),
        Err(LanesError::InvalidOption { name: "paused", .. })
    ));
    let fresh = lanes.start_tangent(&starts, &dirs).unwrap();
    assert!(matches!(
        lanes.resume(&fresh, 0),
        Err(LanesError::InvalidOption {
            name: "collisions",
            ..
        })
    ));
    assert_eq!(fresh[0].stretch().log_stretch, 0.0);
    assert_eq!(fresh[0].collisions(), 0);
}
