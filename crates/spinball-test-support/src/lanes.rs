//! The tables, spin laws and starts the lane kernels are held to the scalar
//! path with, and the scalar reference runs: one copy for the lane crate's
//! agreement tests (`spinball-lanes/tests/agreement.rs`, trajectories and
//! tangent maps against `spinball-core`) and the analysis crate's
//! (`spinball-analysis/tests/lane_agreement.rs`, exponents against
//! `largest_lyapunov` and `lyapunov_spectrum`).
//!
//! Start sets include the paper's and the microcanonical samplers, balls
//! shot exactly into corners (rectangle, Sinai box) and junctions
//! (stadium), and near-grazing rays along flat walls and past the Sinai
//! disk.

use spinball_core::{
    Billiard, Pcg64, Sampler, SpinLaw, State, TangentVector, ic_rng, random_direction,
};
use spinball_geometry::{Boundary, Circle, DVec2, Rectangle, Sinai, Stadium, Table};
use spinball_lanes::{Isa, LaneBilliard};

/// The built-in tables the lanes are held to the scalar path on: each at
/// the paper's parameters and at others that move its corners and junctions.
pub fn tables() -> Vec<Table> {
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

/// Specular, two physical spin laws and one beyond α = 1.
pub fn laws() -> Vec<SpinLaw> {
    vec![
        SpinLaw::specular(),
        SpinLaw::new(0.4).unwrap(),
        SpinLaw::new(1.0).unwrap(),
        SpinLaw::extended(3.0).unwrap(),
    ]
}

/// Starts that hit corners, junctions and grazing angles, with speed `s`
/// and spin `u` (then on the energy shell of the law, whatever it is).
pub fn special(table: &Table) -> Vec<State> {
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
pub fn ics(table: &Table, law: &SpinLaw, n: u64) -> Vec<(State, TangentVector, Pcg64)> {
    draw(table, law, n, special(table))
}

/// [`ics`] for any table, with its special starts given.
pub fn draw<B: Boundary>(
    table: &B,
    law: &SpinLaw,
    n: u64,
    special: Vec<State>,
) -> Vec<(State, TangentVector, Pcg64)> {
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
    for (i, s) in special.into_iter().enumerate() {
        let mut rng = ic_rng(7, i as u64);
        let scalar_rng = rng.clone();
        let dir = random_direction(&mut rng);
        out.push((s, dir, scalar_rng));
    }
    out
}

/// The lane billiard of `table` and `law` at every instruction set this CPU
/// has.
pub fn lanes_for<B: Boundary + Clone>(table: &B, law: &SpinLaw) -> Vec<LaneBilliard<B>> {
    Isa::available()
        .into_iter()
        .map(|isa| {
            LaneBilliard::new(table.clone(), *law)
                .unwrap()
                .with_isa(isa)
                .unwrap()
        })
        .collect()
}

/// The scalar end state and summed flight time after `collisions`
/// collisions from `start` (`Billiard::step`).
pub fn scalar_end<B: Boundary>(
    table: &B,
    law: &SpinLaw,
    start: State,
    collisions: u64,
) -> (State, f64) {
    let billiard = Billiard::new(table, *law);
    let mut ball = billiard.launch(start).unwrap();
    let mut time = 0.0;
    for _ in 0..collisions {
        time += billiard.step(&mut ball).unwrap().time();
    }
    (*ball.state(), time)
}

/// `a` (the lanes) within `rel` of `b` (the scalar), relative to `1 + |b|`.
pub fn close(a: f64, b: f64, rel: f64, what: &str) {
    assert!(
        (a - b).abs() <= rel * (1.0 + b.abs()),
        "{what}: lanes {a} vs scalar {b} (difference {:e})",
        a - b
    );
}

/// The scalar spectrum's initial frame: five random directions from the
/// stream, then modified Gram–Schmidt (as `spinball_analysis`'s private
/// `random_frame`, which redraws in the never-seen dependent case).
pub fn frame_from(rng: &mut Pcg64) -> [TangentVector; 5] {
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
