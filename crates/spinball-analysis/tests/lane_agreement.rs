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
//! laws and starts are those of `crates/spinball-lanes/tests/agreement.rs`.

use spinball_analysis::estimators::{
    LyapunovOptions, Method, SpectrumOptions, largest_lyapunov, lyapunov_spectrum,
};
use spinball_core::{
    Billiard, Pcg64, Sampler, SpinLaw, State, TangentVector, ic_rng, random_direction,
};
use spinball_geometry::{Circle, DVec2, Rectangle, Sinai, Stadium, Table};
use spinball_lanes::{Isa, LaneBilliard};

fn tables() -> Vec<Table> {
    vec![
        Circle::unit().into(),
        Circle::new(0.6).unwrap().into(),
        Rectangle::square().into(),
        Rectangle::new(1.5, 1.0).unwrap().into(),
        Stadium::new(1.0).unwrap().into(),
        Stadium::new(0.2).unwrap().into(),
        Stadium::new(4.0).unwrap().into(),
        Sinai::new(2.0, 1.0).unwrap().into(),
        Sinai::new(1.0, 0.3).unwrap().into(),
    ]
}

fn laws() -> Vec<SpinLaw> {
    vec![
        SpinLaw::specular(),
        SpinLaw::new(0.4).unwrap(),
        SpinLaw::new(1.0).unwrap(),
        SpinLaw::extended(3.0).unwrap(),
    ]
}

/// Starts that hit corners, junctions and grazing angles, with speed `s`
/// and spin `u` (then on the energy shell of the law, whatever it is).
fn special(table: &Table) -> Vec<State> {
    let st =
        |x: f64, y: f64, vx: f64, vy: f64| State::new(DVec2::new(x, y), DVec2::new(vx, vy), 0.3);
    match table {
        Table::Rectangle(r) => {
            let (l, h) = (r.l(), r.h());
            vec![
                // Exact ties dy|v_x| = dx|v_y|: corners (l, h) and (-l, -h).
                st(l - 1.0, h - 1.0, 0.6, 0.6),
                st(1.0 - l, 1.0 - h, -0.6, -0.6),
                st(l - 0.5, 1.0 - h, 0.5, -0.5),
                // Grazing along the top wall.
                st(0.0, h * (1.0 - 1e-12), 0.8, 1e-9),
            ]
        }
        Table::Stadium(s) => {
            let a = s.a();
            vec![
                // Into the junctions (±a, ±1).
                st(0.0, 0.0, 0.5 * a, 0.5),
                st(0.0, 0.0, -0.5 * a, -0.5),
                // Almost along a flat wall, into a cap near the junction.
                st(0.0, 1.0 - 1e-12, 0.8, 1e-9),
                st(0.0, -1.0 + 1e-9, -0.8, 1e-12),
            ]
        }
        Table::Sinai(s) => {
            let (l, r) = (s.l(), s.r());
            let m = 0.5 * (l + r);
            vec![
                // Box corners by exact ties.
                st(m, m, 0.6, 0.6),
                st(-m, m, -0.6, 0.6),
                // Grazing the disk.
                st(-m, r * (1.0 - 1e-10), 0.8, 0.0),
                st(-m, r * (1.0 + 1e-10), 0.8, 0.0),
                st(r * (1.0 - 1e-12), m, 0.0, -0.8),
            ]
        }
        Table::Circle(c) => {
            let r = c.radius();
            vec![
                st(0.0, 0.0, 0.8, 0.1),
                // Whispering gallery: nearly tangent.
                st(r * (1.0 - 1e-9), 0.0, 0.0, 0.8),
            ]
        }
    }
}

/// Initial conditions: `n` from each sampler (the ensembles' draw: state,
/// then the direction from the same stream) plus the special ones (the last
/// `special(table).len()`). Returns the state, the direction, and the stream
/// as the scalar call must see it (positioned after the state).
fn ics(table: &Table, law: &SpinLaw, n: u64) -> Vec<(State, TangentVector, Pcg64)> {
    let mut out = Vec::new();
    for (k, sampler) in [Sampler::Paper, Sampler::Microcanonical]
        .into_iter()
        .enumerate()
    {
        for i in 0..n {
            let mut rng = ic_rng(100 + k as u64, i);
            let start = sampler.sample(table, law, &mut rng);
            let scalar_rng = rng.clone();
            let dir = random_direction(&mut rng);
            out.push((start, dir, scalar_rng));
        }
    }
    for (i, s) in special(table).into_iter().enumerate() {
        let mut rng = ic_rng(7, i as u64);
        let scalar_rng = rng.clone();
        let dir = random_direction(&mut rng);
        out.push((s, dir, scalar_rng));
    }
    out
}

fn lanes_for(table: &Table, law: &SpinLaw) -> Vec<LaneBilliard> {
    Isa::available()
        .into_iter()
        .map(|isa| {
            LaneBilliard::new(*table, *law)
                .unwrap()
                .with_isa(isa)
                .unwrap()
        })
        .collect()
}

fn scalar_end(table: &Table, law: &SpinLaw, start: State, collisions: u64) -> (State, f64) {
    let billiard = Billiard::new(*table, *law);
    let mut ball = billiard.launch(start).unwrap();
    let mut time = 0.0;
    for _ in 0..collisions {
        time += billiard.step(&mut ball).unwrap().time();
    }
    (*ball.state(), time)
}

fn close(a: f64, b: f64, rel: f64, what: &str) {
    assert!(
        (a - b).abs() <= rel * (1.0 + b.abs()),
        "{what}: lanes {a} vs scalar {b} (difference {:e})",
        a - b
    );
}

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

/// The scalar spectrum's initial frame: five random directions from the
/// stream, then modified Gram–Schmidt (as `spinball_analysis`'s private
/// `random_frame`, which redraws in the never-seen dependent case).
fn frame_from(rng: &mut Pcg64) -> [TangentVector; 5] {
    let mut v: [TangentVector; 5] = std::array::from_fn(|_| random_direction(rng));
    for i in 0..5 {
        for j in 0..i {
            let p = v[i].dot(&v[j]);
            v[i] = v[i] - v[j] * p;
        }
        let n = v[i].norm();
        assert!(n > 1e-6);
        v[i] = v[i] * (1.0 / n);
    }
    v
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
