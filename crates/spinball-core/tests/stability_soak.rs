//! Issue 9: the stability soak. Every table, paper and extreme parameters
//! (sizes 1e±50, speeds 1e±50, thin Sinai channels, long and short
//! stadiums, a 1e12 aspect-ratio rectangle), α from 0 to 1e12, counting per
//! collision: escapes (the ball farther than 1e-9 of the local wall scale
//! outside), flights through the Sinai disk, non-finite states, step errors
//! by kind, the worst energy error `|E − E0|/E0` and the worst `Q` error
//! through a collision `|Q' − Q|` relative to the size of its terms and
//! the speed (`|v∥| + α|u|` before and after, plus `|V|`).
//!
//! ```text
//! # the full soak (1e9 collisions; docs/STABILITY.md has its counts)
//! cargo test --release -p spinball-core --test stability_soak -- --ignored --nocapture
//! # any other total
//! SPINBALL_SOAK_COLLISIONS=100000000 cargo test --release -p spinball-core \
//!     --test stability_soak -- --ignored --nocapture
//! ```
//!
//! The non-ignored test runs the same cases for 2e6 collisions in all.

mod common;

use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};

use spinball_core::{Billiard, Sampler, SpinLaw, State, StepError, ic_rng};
use spinball_geometry::{DVec2, Table};

/// One soak case: a table, α and a speed scale for the sampled states.
#[derive(Clone, Copy, Debug)]
struct Case {
    spec: &'static str,
    alpha: f64,
    speed: f64,
}

/// The tables: the paper's four, and the extremes the issue lists.
const TABLES: [(&str, f64); 16] = [
    ("circle:R=1", 1.0),
    ("rectangle:L=1,H=1", 1.0),
    ("stadium:a=1", 1.0),
    ("sinai:L=2,R=1", 1.0),
    ("sinai:L=2,R=1.999999", 1.0),
    ("sinai:L=2,R=0.00001", 1.0),
    ("stadium:a=1e-9", 1.0),
    ("stadium:a=1e4", 1.0),
    ("stadium:a=1e8", 1.0),
    ("rectangle:L=1e6,H=1e-6", 1.0),
    ("circle:R=1e50", 1e50),
    ("circle:R=1e-50", 1e-50),
    ("sinai:L=2e50,R=1e50", 1e-50),
    ("sinai:L=2e-50,R=1e-50", 1e50),
    ("stadium:a=1", 1e50),
    ("sinai:L=2,R=1", 1e-50),
];

const ALPHAS: [f64; 6] = [0.0, 1e-12, 0.5, 1.0, 1e3, 1e12];

fn cases() -> Vec<Case> {
    TABLES
        .iter()
        .flat_map(|&(spec, speed)| ALPHAS.iter().map(move |&alpha| Case { spec, alpha, speed }))
        .collect()
}

/// What a soak saw.
#[derive(Debug, Default, Clone, Copy)]
struct Counts {
    collisions: u64,
    trajectories: u64,
    escapes: u64,
    through_disk: u64,
    non_finite: u64,
    stuck: u64,
    no_wall: u64,
    other_errors: u64,
    worst_energy: f64,
    worst_q: f64,
    worst_outside: f64,
}

impl Counts {
    fn add(&mut self, o: &Counts) {
        self.collisions += o.collisions;
        self.trajectories += o.trajectories;
        self.escapes += o.escapes;
        self.through_disk += o.through_disk;
        self.non_finite += o.non_finite;
        self.stuck += o.stuck;
        self.no_wall += o.no_wall;
        self.other_errors += o.other_errors;
        self.worst_energy = self.worst_energy.max(o.worst_energy);
        self.worst_q = self.worst_q.max(o.worst_q);
        self.worst_outside = self.worst_outside.max(o.worst_outside);
    }
    fn errors(&self) -> u64 {
        self.stuck + self.no_wall + self.other_errors
    }
}

/// How far `p` is outside the table, relative to the scale of the wall it
/// is outside of (0 inside). Along x of a stadium the coordinates round at
/// `ε (a + 1)`, which is the scale there.
fn outside_by(table: &Table, p: DVec2) -> f64 {
    let rel = |excess: f64, scale: f64| (excess / scale).max(0.0);
    match table {
        Table::Circle(c) => rel(p.length() - c.radius(), c.radius()),
        Table::Rectangle(r) => rel(p.x.abs() - r.l(), r.l()).max(rel(p.y.abs() - r.h(), r.h())),
        Table::Stadium(s) => {
            let dx = (p.x.abs() - s.a()).max(0.0);
            let cap = rel(
                DVec2::new(dx, p.y).length() - 1.0,
                1.0 + f64::EPSILON * s.a(),
            );
            cap.max(rel(p.y.abs() - 1.0, 1.0))
        }
        Table::Sinai(s) => rel(p.x.abs() - s.l(), s.l())
            .max(rel(p.y.abs() - s.l(), s.l()))
            .max(rel(s.r() - p.length(), s.l())),
    }
}

/// Whether the straight flight from `a` to `b` passes through the Sinai disk.
fn through_disk(table: &Table, a: DVec2, b: DVec2) -> bool {
    let Table::Sinai(s) = table else {
        return false;
    };
    common::closest_to_origin(a, b) < s.r() * (1.0 - 1e-9)
}

/// `collisions` collisions of `case`, trajectories of at most `per` each.
fn soak_case(case: Case, collisions: u64, per: u64, seed: u64) -> Counts {
    let table: Table = case.spec.parse().expect("valid spec");
    let law = SpinLaw::extended(case.alpha).expect("finite alpha");
    let billiard = Billiard::new(table, law);
    let mut counts = Counts::default();
    let mut index = 0;
    while counts.collisions < collisions {
        let s = Sampler::Microcanonical.sample(&table, &law, &mut ic_rng(seed, index));
        index += 1;
        let start = State::new(s.position, s.velocity * case.speed, s.spin * case.speed);
        let Ok(mut ball) = billiard.launch(start) else {
            counts.other_errors += 1;
            continue;
        };
        counts.trajectories += 1;
        let e0 = billiard.energy(&start);
        let v0 = (2.0 * e0).sqrt();
        let n = per.min(collisions - counts.collisions);
        let mut prev = start.position;
        for _ in 0..n {
            match billiard.step(&mut ball) {
                Ok(c) => {
                    counts.collisions += 1;
                    let st = ball.state();
                    if !st.to_array().iter().all(|x| x.is_finite()) || !c.time().is_finite() {
                        counts.non_finite += 1;
                        break;
                    }
                    let out = outside_by(&table, st.position);
                    counts.worst_outside = counts.worst_outside.max(out);
                    if out > 1e-9 {
                        counts.escapes += 1;
                    }
                    if through_disk(&table, prev, st.position) {
                        counts.through_disk += 1;
                    }
                    prev = st.position;
                    let de = (billiard.energy(st) - e0).abs() / e0;
                    counts.worst_energy = counts.worst_energy.max(de);
                    // Relative to the size of Q's terms and the speed: at
                    // α = 1e12, αu ~ 1e6 |V| and Q rounds at ε·1e6 |V|; at
                    // near-normal incidence v∥ is small but carries the
                    // rounding of the normal part, ε |V|.
                    let a = case.alpha;
                    let terms = c.v_par_before.abs()
                        + a * c.spin_before.abs()
                        + c.v_par_after.abs()
                        + a * c.spin_after.abs()
                        + v0;
                    let dq = (c.q_after(a) - c.q).abs() / terms;
                    counts.worst_q = counts.worst_q.max(dq);
                }
                Err(StepError::Stuck { .. }) => {
                    counts.stuck += 1;
                    break;
                }
                Err(StepError::NoWall { .. }) => {
                    counts.no_wall += 1;
                    break;
                }
                Err(_) => {
                    counts.other_errors += 1;
                    break;
                }
            }
        }
    }
    counts
}

/// Run every case for `total / cases` collisions on all threads; print a
/// line per case and the totals.
fn soak(total: u64) -> Counts {
    let cases = cases();
    let per_case = total / cases.len() as u64;
    let per_trajectory = (per_case / 4).max(1);
    let next = AtomicUsize::new(0);
    let results = Mutex::new(vec![Counts::default(); cases.len()]);
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    std::thread::scope(|s| {
        for _ in 0..threads {
            s.spawn(|| {
                loop {
                    let i = next.fetch_add(1, Ordering::Relaxed);
                    let Some(&case) = cases.get(i) else { break };
                    let c = soak_case(case, per_case, per_trajectory, 9 + i as u64);
                    results.lock().expect("no panic")[i] = c;
                }
            });
        }
    });
    let results = results.into_inner().expect("no panic");
    let mut total = Counts::default();
    println!(
        "{:<26} {:>8} {:>6} {:>12} {:>5} {:>5} {:>4} {:>5} {:>5} {:>9} {:>9} {:>9}",
        "table",
        "alpha",
        "speed",
        "collisions",
        "traj",
        "esc",
        "disk",
        "nan",
        "err",
        "dE/E",
        "dQ/terms",
        "outside"
    );
    for (case, c) in cases.iter().zip(&results) {
        println!(
            "{:<26} {:>8.0e} {:>6.0e} {:>12} {:>5} {:>5} {:>4} {:>5} {:>5} {:>9.1e} {:>9.1e} {:>9.1e}",
            case.spec,
            case.alpha,
            case.speed,
            c.collisions,
            c.trajectories,
            c.escapes,
            c.through_disk,
            c.non_finite,
            c.errors(),
            c.worst_energy,
            c.worst_q,
            c.worst_outside
        );
        total.add(c);
    }
    println!(
        "TOTAL: {} collisions, {} trajectories, {} escapes, {} through the disk, {} non-finite, {} stuck, {} no wall, {} other errors; worst |dE|/E {:.2e}, worst |dQ|/terms {:.2e}, worst outside {:.2e}",
        total.collisions,
        total.trajectories,
        total.escapes,
        total.through_disk,
        total.non_finite,
        total.stuck,
        total.no_wall,
        total.other_errors,
        total.worst_energy,
        total.worst_q,
        total.worst_outside
    );
    total
}

/// The bounds a soak must meet: nothing escapes, nothing goes non-finite,
/// no step fails; energy to 1e-13 relative (the shell restore keeps it at a
/// few ulps), `Q` through a collision to 1e-14 of its terms.
fn check(c: &Counts) {
    assert_eq!(c.escapes, 0, "{c:?}");
    assert_eq!(c.through_disk, 0, "{c:?}");
    assert_eq!(c.non_finite, 0, "{c:?}");
    assert_eq!(c.errors(), 0, "{c:?}");
    assert!(c.worst_energy < 1e-13, "{c:?}");
    assert!(c.worst_q < 1e-14, "{c:?}");
}

#[test]
fn short_soak_over_every_table_and_alpha() {
    let c = soak(2_000_000);
    assert!(c.collisions >= 1_900_000);
    check(&c);
}

#[test]
#[ignore = "the full soak: 1e9 collisions (SPINBALL_SOAK_COLLISIONS to change); see docs/STABILITY.md"]
fn full_soak() {
    let total = std::env::var("SPINBALL_SOAK_COLLISIONS")
        .ok()
        .and_then(|s| s.parse::<f64>().ok())
        .map_or(1_000_000_000, |x| x as u64);
    let c = soak(total);
    check(&c);
}
