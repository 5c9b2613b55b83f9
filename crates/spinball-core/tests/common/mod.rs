//! Shared helpers for the core integration tests.
#![allow(dead_code, unused_imports)]

pub use spinball_test_support::signed_distance;

use spinball_core::{Ball, Billiard, Boundary, Collision, Sampler, SpinLaw, State};
use spinball_geometry::{DVec2, Table};

/// The α values the issue asks every dynamical test to cover: specular, a
/// generic physical value, the thin ring, and the extension beyond 1.
pub const ALPHAS: [f64; 4] = [0.0, 0.3, 1.0, 5.0];

/// The law for any α ≥ 0 (α > 1 through the explicitly named constructor).
pub fn law(alpha: f64) -> SpinLaw {
    if alpha <= 1.0 {
        SpinLaw::new(alpha).expect("physical alpha")
    } else {
        SpinLaw::extended(alpha).expect("finite alpha")
    }
}

/// The paper's four tables (§II.A): unit circle, square L = H = 1, stadium
/// a = 1, Sinai L = 2, R = 1.
pub fn paper_tables() -> Vec<Table> {
    ["circle", "rectangle", "stadium:a=1", "sinai:L=2,R=1"]
        .iter()
        .map(|s| s.parse().expect("valid spec"))
        .collect()
}

/// A launched ball from initial condition `index` of `seed` (paper sampler).
pub fn paper_ball(billiard: &Billiard<Table>, seed: u64, index: u64) -> Ball {
    let s = Sampler::Paper.initial_state(billiard.table(), billiard.law(), seed, index);
    billiard.launch(s).expect("sampled state launches")
}

/// Advance `n` collisions, collecting the records.
pub fn collisions<B: Boundary>(
    billiard: &Billiard<B>,
    ball: &mut Ball,
    n: usize,
) -> Vec<Collision> {
    (0..n).map(|_| billiard.step(ball).expect("step")).collect()
}

/// Every coordinate finite.
pub fn finite(s: &State) -> bool {
    s.to_array().iter().all(|x| x.is_finite())
}

/// Closest approach to the origin (the Sinai disk's centre) of the straight
/// flight from `a` to `b`.
pub fn closest_to_origin(a: DVec2, b: DVec2) -> f64 {
    let ab = b - a;
    let f = if ab.length_squared() > 0.0 {
        (-a.dot(ab) / ab.length_squared()).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (a + ab * f).length()
}
