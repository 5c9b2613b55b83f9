//! The lane kernels of `spinball-lanes` against the scalar exponents of this
//! crate, `largest_lyapunov` and `lyapunov_spectrum`, on every table, spin
//! law and instruction set this CPU has. (The lane crate's own tests compare
//! its trajectories and tangent maps with `spinball-core` directly; these
//! live here because the lane crate cannot depend on this one.)
//!
//! - Finite differences: the trajectories are bitwise the scalar ones, so
//!   `Σ ln(δ/δ0)` differs from `largest_lyapunov` only by how the product of
//!   the factors is rounded (`dist·(1/δ0)` against `dist/δ0`, one `ln` at the
//!   end against one every `1e±150`): a few ulps per factor, `~1e-13`
//!   relative over these runs.
//! - Exact tangent: the tangent map is bitwise `TangentFrame::apply`; the
//!   scalar normalises the vector every step (rounding), the lanes rescale
//!   by exact powers of two. Where the vector's direction converges
//!   (chaotic orbits) the difference stays at rounding level (`1e-16`); on
//!   regular and mixed orbits it grows slowly (`≤ 5e-11` relative after
//!   5000 collisions in a survey of 40 paper-sampled starts per table and
//!   α). A near-grazing collision is ill conditioned: its tangent map has
//!   entries `~1/(n·v)`, `1e9` for the grazing starts below, and amplifies
//!   any rounding difference in the incoming vector by that much (the
//!   scalar's per-step normalisation rounds, the lanes' powers of two do
//!   not); there the two part by up to `3e-6` relative (seen: rectangle,
//!   α = 1, a ball sliding along the top wall). Tolerances: `1e-10` for
//!   sampled starts, `1e-4` for the grazing ones.
//! - Spectrum: the same tangent map and Gram–Schmidt as the scalar;
//!   differences from the product of `R_ii` only.
//!
//! Start sets include the paper's and the microcanonical samplers, balls
//! shot exactly into corners (rectangle, Sinai box) and junctions
//! (stadium), and near-grazing rays along flat walls and past the Sinai
//! disk; counts are not multiples of any lane count (tails). The tables,
//! laws and starts are `spinball-test-support`'s, which
//! `crates/spinball-lanes/tests/agreement.rs` uses too.

use spinball_analysis::estimators::{
    LyapunovOptions, Method, SpectrumOptions, largest_lyapunov, lyapunov_spectrum,
};
use spinball_core::{Billiard, SpinLaw, State, TangentVector};
use spinball_geometry::{Stadium, Table};
use spinball_lanes::LaneBilliard;
use spinball_test_support::lanes::{
    close, frame_from, ics, lanes_for, laws, scalar_end, special, tables,
};

#[test]
fn finite_differences_match_largest_lyapunov() {
    const COLLISIONS: u64 = 600;
    for table in tables() {
        for law in laws() {
            let ics = ics(&table, &law, 9);
            let starts: Vec<State> = ics.iter().map(|x| x.0).collect();
            let dirs: Vec<TangentVector> = ics.iter().map(|x| x.1).collect();
            let billiard = Billiard::new(table, law);
            let opts = LyapunovOptions::new(COLLISIONS, Method::default());
            let want: Vec<_> = ics
                .iter()
                .map(|(s, _, rng)| {
                    largest_lyapunov(&billiard, *s, &opts, &mut rng.clone()).unwrap()
                })
                .collect();
            for lanes in lanes_for(&table, &law) {
                let got = lanes.lyapunov_fd(&starts, &dirs, 1e-7, COLLISIONS).unwrap();
                for (i, (g, w)) in got.iter().zip(&want).enumerate() {
                    let what = format!("{table} α={} {} ic {i}", law.alpha(), lanes.isa());
                    assert_eq!(g.time.to_bits(), w.time.to_bits(), "time {what}");
                    close(
                        g.log_stretch,
                        w.per_collision * COLLISIONS as f64,
                        1e-12,
                        &what,
                    );
                    assert_eq!(
                        g.end,
                        scalar_end(&table, &law, starts[i], COLLISIONS).0,
                        "{what}"
                    );
                }
            }
        }
    }
}

#[test]
fn exact_tangent_matches_largest_lyapunov() {
    const COLLISIONS: u64 = 600;
    for table in tables() {
        for law in laws() {
            let ics = ics(&table, &law, 9);
            let starts: Vec<State> = ics.iter().map(|x| x.0).collect();
            let dirs: Vec<TangentVector> = ics.iter().map(|x| x.1).collect();
            let billiard = Billiard::new(table, law);
            let opts = LyapunovOptions::new(COLLISIONS, Method::Tangent);
            let want: Vec<_> = ics
                .iter()
                .map(|(s, _, rng)| {
                    largest_lyapunov(&billiard, *s, &opts, &mut rng.clone()).unwrap()
                })
                .collect();
            let sampled = ics.len() - special(&table).len();
            for lanes in lanes_for(&table, &law) {
                let got = lanes.lyapunov_tangent(&starts, &dirs, COLLISIONS).unwrap();
                for (i, (g, w)) in got.iter().zip(&want).enumerate() {
                    let what = format!("{table} α={} {} ic {i}", law.alpha(), lanes.isa());
                    assert_eq!(g.time.to_bits(), w.time.to_bits(), "time {what}");
                    let tol = if i < sampled { 1e-10 } else { 1e-4 };
                    close(
                        g.log_stretch,
                        w.per_collision * COLLISIONS as f64,
                        tol,
                        &what,
                    );
                }
            }
        }
    }
}

#[test]
fn spectrum_matches_lyapunov_spectrum() {
    const COLLISIONS: u64 = 400;
    for table in tables() {
        for law in laws() {
            for qr in [1u32, 5] {
                let ics = ics(&table, &law, 4);
                let starts: Vec<State> = ics.iter().map(|x| x.0).collect();
                let frames: Vec<[TangentVector; 5]> =
                    ics.iter().map(|x| frame_from(&mut x.2.clone())).collect();
                let billiard = Billiard::new(table, law);
                let opts = SpectrumOptions::new(COLLISIONS, Method::Tangent).with_qr_interval(qr);
                let want: Vec<_> = ics
                    .iter()
                    .map(|(s, _, rng)| {
                        lyapunov_spectrum(&billiard, *s, &opts, &mut rng.clone()).unwrap()
                    })
                    .collect();
                for lanes in lanes_for(&table, &law) {
                    let got = lanes.spectrum(&starts, &frames, COLLISIONS, qr).unwrap();
                    for (i, (g, w)) in got.iter().zip(&want).enumerate() {
                        let what =
                            format!("{table} α={} qr {qr} {} ic {i}", law.alpha(), lanes.isa());
                        assert_eq!(g.time.to_bits(), w.time.to_bits(), "time {what}");
                        for (a, b) in g.exponents().iter().zip(w.exponents) {
                            close(a * g.time, b * w.time, 1e-10, &what);
                        }
                    }
                }
            }
        }
    }
}

#[test]
fn long_runs_agree_to_rounding_despite_chaos() {
    // 20 000 collisions of the chaotic stadium: any rounding difference in
    // the trajectory would have grown to O(1) long before the end; the
    // exponents still agree to rounding because the trajectories are the
    // same to the bit.
    const COLLISIONS: u64 = 20_000;
    let table = Table::from(Stadium::new(1.0).unwrap());
    let law = SpinLaw::new(0.5).unwrap();
    let billiard = Billiard::new(table, law);
    let mut ics = ics(&table, &law, 4);
    ics.truncate(8); // sampled starts only (see the module docs on grazing)
    let starts: Vec<State> = ics.iter().map(|x| x.0).collect();
    let dirs: Vec<TangentVector> = ics.iter().map(|x| x.1).collect();
    let lanes = LaneBilliard::new(table, law).unwrap();
    for (method, got) in [
        (
            Method::default(),
            lanes.lyapunov_fd(&starts, &dirs, 1e-7, COLLISIONS).unwrap(),
        ),
        (
            Method::Tangent,
            lanes.lyapunov_tangent(&starts, &dirs, COLLISIONS).unwrap(),
        ),
    ] {
        for (i, (g, (s, _, rng))) in got.iter().zip(&ics).enumerate() {
            let opts = LyapunovOptions::new(COLLISIONS, method);
            let w = largest_lyapunov(&billiard, *s, &opts, &mut rng.clone()).unwrap();
            assert_eq!(g.time.to_bits(), w.time.to_bits());
            close(
                g.exponent(),
                w.exponent,
                1e-9,
                &format!("{} ic {i}", method.name()),
            );
        }
    }
}
