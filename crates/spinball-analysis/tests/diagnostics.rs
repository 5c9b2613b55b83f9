//! The paper's diagnostics (§V, §VI, §VIII and the appendices): wall
//! transitions, `|ΔQ|`, curved share, phase-space separation, collision rate
//! and energy. Fixed seeds; the test profile is optimised.

use std::f64::consts::PI;

use spinball_analysis::AnalysisError;
use spinball_analysis::diagnostics::{
    CollisionRate, SeparationOptions, TransitionRule, collision_rate_summary, energy_trace,
    per_collision_exponent, phase_space_separation, wall_statistics, wall_statistics_ensemble,
};
use spinball_analysis::estimators::{LyapunovOptions, Method, largest_lyapunov};
use spinball_analysis::run::Threads;
use spinball_core::{Billiard, Collision, Sampler, SpinLaw, State, ic_rng};
use spinball_geometry::{Boundary, Circle, Sinai, Stadium};

const SEED: u64 = 2024;

fn law(alpha: f64) -> SpinLaw {
    SpinLaw::new(alpha).unwrap()
}

/// Stadium a = 1, 300 paper-sampler initial conditions × 10⁴ collisions per
/// α (the paper: 1000 × 10⁴). The share of pairs whose tangent line turns is
/// in the paper's band 0.80–0.84 (measured 0.824 at α = 0.5, 0.817 at α = 1;
/// 0.838 and 0.846 at α = 0 and 0.1); the oriented tangent changes at every
/// pair; the wall id changes at 0.78–0.81 of them.
#[test]
fn stadium_transition_fraction_in_paper_band() {
    for alpha in [0.5, 1.0] {
        let billiard = Billiard::new(Stadium::new(1.0).unwrap(), law(alpha));
        let stats = wall_statistics_ensemble(
            &billiard,
            Sampler::Paper,
            SEED,
            0..300,
            10_000,
            Threads::All,
        )
        .unwrap();
        let direction = stats
            .transition_fraction(TransitionRule::Direction)
            .unwrap();
        let wall = stats.transition_fraction(TransitionRule::Wall).unwrap();
        eprintln!(
            "stadium α={alpha}: direction {direction:.4} wall {wall:.4} curved {:.4} ν {:.4}",
            stats.curved_fraction().unwrap(),
            stats.collision_rate().unwrap()
        );
        assert!((0.80..=0.84).contains(&direction), "f_trans = {direction}");
        assert_eq!(
            stats.transition_fraction(TransitionRule::Tangent),
            Some(1.0)
        );
        assert_eq!(stats.same_tangent, 0);
        assert!((0.76..=0.83).contains(&wall), "wall-id fraction {wall}");
        assert_eq!(stats.pairs, 300 * (10_000 - 1));
        assert_eq!(
            stats.pairs,
            stats.same_tangent + stats.reversed_tangent + stats.turned
        );
    }
}

/// Sinai L = 2, R = 1: no two consecutive collisions share a wall or a
/// tangent, so `f_trans = 1` exactly (paper §VI); the direction rule is
/// below 1 because flights between opposite box walls past the disk have
/// parallel tangents.
#[test]
fn sinai_transition_fraction_is_one() {
    let billiard = Billiard::new(Sinai::new(2.0, 1.0).unwrap(), law(0.5));
    let stats = wall_statistics_ensemble(
        &billiard,
        Sampler::Paper,
        SEED,
        0..100,
        10_000,
        Threads::All,
    )
    .unwrap();
    assert_eq!(stats.transition_fraction(TransitionRule::Wall), Some(1.0));
    assert_eq!(
        stats.transition_fraction(TransitionRule::Tangent),
        Some(1.0)
    );
    let direction = stats
        .transition_fraction(TransitionRule::Direction)
        .unwrap();
    eprintln!("sinai: direction rule {direction}");
    assert!((0.85..0.97).contains(&direction));
}

/// `|ΔQ|` (paper appendix "Conserved quantity verification", stadium α = 0.5,
/// 10⁴ collisions): through each collision `Q` is kept to `< 1e-14`; no
/// consecutive pair has the same tangent; between the facing flat walls
/// `ΔQ = −2 v∥` exactly; where the tangent line turns, `|ΔQ|` has a median
/// of order 0.1–1.
#[test]
fn delta_q_populations() {
    let alpha = 0.5;
    let billiard = Billiard::new(Stadium::new(1.0).unwrap(), law(alpha));
    let start = Sampler::Paper.initial_state(billiard.table(), billiard.law(), SEED, 0);
    let stats = wall_statistics(&billiard, start, 10_000).unwrap();
    eprintln!(
        "through collision: max {:e}; reversed: n {} median {:?}; turned: n {} median {:?} max {}",
        stats.dq_collision.max,
        stats.dq_reversed_tangent.count,
        stats.dq_reversed_tangent.median(),
        stats.dq_turned.count,
        stats.dq_turned.median(),
        stats.dq_turned.max
    );
    assert_eq!(stats.dq_collision.count, 10_000);
    assert!(stats.dq_collision.max < 1e-14);
    assert_eq!(stats.dq_same_tangent.count, 0);
    let turned = stats.dq_turned.median().unwrap();
    assert!(
        (0.1..=1.0).contains(&turned),
        "median turned |ΔQ| = {turned}"
    );
    let reversed = stats.dq_reversed_tangent.median().unwrap();
    assert!(
        (0.1..=2.0).contains(&reversed),
        "median reversed |ΔQ| = {reversed}"
    );
    assert!(stats.dq_reversed_tangent.count > 1000);

    // ΔQ = −2 v∥ between facing walls, checked collision by collision.
    let mut ball = billiard.launch(start).unwrap();
    let mut prev: Option<Collision> = None;
    let mut checked = 0;
    billiard
        .run(&mut ball, 10_000, &mut |c: &Collision, _: &State| {
            if let Some(p) = prev
                && p.tangent().dot(c.tangent()) < -1.0 + 1e-12
            {
                let dq = c.q - p.q_after(alpha);
                assert!((dq + 2.0 * p.v_par_after).abs() < 1e-14);
                checked += 1;
            }
            prev = Some(*c);
        })
        .unwrap();
    assert_eq!(checked, stats.reversed_tangent);
}

fn curved_share<B: Boundary + Sync>(table: B, alpha: f64) -> f64 {
    let billiard = Billiard::new(table, law(alpha));
    wall_statistics_ensemble(
        &billiard,
        Sampler::Paper,
        SEED,
        0..100,
        10_000,
        Threads::All,
    )
    .unwrap()
    .curved_fraction()
    .unwrap()
}

/// Share of collisions on curved walls. At α = 0 it is the wall's share of
/// the perimeter (the invariant measure of the ergodic billiard map), which
/// the runs reproduce to 0.01. Against the paper (§IV, §VIII): Sinai R = 1
/// "~30 %" and R = 0.3 "~15 %" agree within 0.03 at α = 0.5; R = 0.8 is in
/// the paper's "26–29 %"; the stadium "~50 %" (0.60 measured, 0.611 theory)
/// and Sinai R = 1.5 "~50 %" (0.37) do not.
#[test]
fn curved_share_matches_perimeter_share_and_paper() {
    let stadium_theory = 2.0 * PI / (4.0 + 2.0 * PI);
    let sinai_theory = |r: f64| 2.0 * PI * r / (16.0 + 2.0 * PI * r);
    let s0 = curved_share(Stadium::new(1.0).unwrap(), 0.0);
    let r1 = curved_share(Sinai::new(2.0, 1.0).unwrap(), 0.0);
    let r15 = curved_share(Sinai::new(2.0, 1.5).unwrap(), 0.0);
    eprintln!(
        "α=0: stadium {s0:.4} ({stadium_theory:.4}), sinai R=1 {r1:.4} ({:.4}), R=1.5 {r15:.4} ({:.4})",
        sinai_theory(1.0),
        sinai_theory(1.5)
    );
    assert!((s0 - stadium_theory).abs() < 0.01);
    assert!((r1 - sinai_theory(1.0)).abs() < 0.01);
    assert!((r15 - sinai_theory(1.5)).abs() < 0.01);

    let half = |r: f64| curved_share(Sinai::new(2.0, r).unwrap(), 0.5);
    let (p10, p03, p08, p15) = (half(1.0), half(0.3), half(0.8), half(1.5));
    let st = curved_share(Stadium::new(1.0).unwrap(), 0.5);
    eprintln!(
        "α=0.5: sinai R=1 {p10:.4} R=0.3 {p03:.4} R=0.8 {p08:.4} R=1.5 {p15:.4}; stadium {st:.4}"
    );
    assert!((p10 - 0.30).abs() < 0.03);
    assert!((p03 - 0.15).abs() < 0.03);
    assert!((0.24..=0.31).contains(&p08));
    // The two paper values that disagree, kept visible.
    assert!((st - 0.50).abs() > 0.05 && (st - stadium_theory).abs() < 0.03);
    assert!((p15 - 0.50).abs() > 0.1);
}

/// Phase-space separation (paper §V.A: 8000 pairs, δ0 = 1e-7, 50 collisions).
/// Stadium: linear growth before saturation, slope ≈ λ per collision from
/// exact tangent runs of the same set-up (within 25 %; measured 0.940 vs
/// 0.936 at α = 0 over collisions 3–12, 0.503 vs 0.552 at α = 0.5 over
/// 5–25). The separation saturates at `ln(size/δ0) ≈ 16` after ~15 (α = 0)
/// or ~35 (α = 0.5) collisions, well inside the paper's 50. Circle α = 0.5:
/// sublinear, like `ln n` (collisions 25–50 add 0.72, collisions 1–25 add
/// 2.70; linear growth would add as much again).
#[test]
fn separation_linear_for_stadium_sublinear_for_circle() {
    for alpha in [0.0, 0.5] {
        let billiard = Billiard::new(Stadium::new(1.0).unwrap(), law(alpha));
        let opts = SeparationOptions {
            seed: SEED,
            ..SeparationOptions::default()
        };
        let sep = phase_space_separation(&billiard, &opts).unwrap();
        assert_eq!(sep.mean.len(), 50);
        assert_eq!(sep.pairs, 8000);
        // λ per collision from a small ensemble of exact runs.
        let mut per = 0.0;
        for i in 0..20 {
            let mut rng = ic_rng(SEED + 1, i);
            let s = Sampler::Paper.sample(billiard.table(), billiard.law(), &mut rng);
            let l = largest_lyapunov(
                &billiard,
                s,
                &LyapunovOptions::new(20_000, Method::Tangent),
                &mut rng,
            )
            .unwrap();
            per += per_collision_exponent(&l) / 20.0;
        }
        let window = if alpha == 0.0 { 3..=12 } else { 5..=25 };
        let fit = sep.fit(window.clone()).unwrap();
        eprintln!(
            "stadium α={alpha}: slope {:.3} over {window:?} vs λ/ν {per:.3}; mean[0,9,19,29,49] = {:.2} {:.2} {:.2} {:.2} {:.2}; sem[49] {:.3}",
            fit.slope,
            sep.mean[0],
            sep.mean[9],
            sep.mean[19],
            sep.mean[29],
            sep.mean[49],
            sep.sem[49]
        );
        assert!(fit.slope > 0.0);
        assert!((fit.slope / per - 1.0).abs() < 0.25);
    }
    let circle = Billiard::new(Circle::unit(), law(0.5));
    let sep = phase_space_separation(
        &circle,
        &SeparationOptions {
            seed: SEED,
            ..SeparationOptions::default()
        },
    )
    .unwrap();
    let early = sep.mean[24] - sep.mean[0];
    let late = sep.mean[49] - sep.mean[24];
    eprintln!(
        "circle: mean[0] {:.3} mean[24] {:.3} mean[49] {:.3}",
        sep.mean[0], sep.mean[24], sep.mean[49]
    );
    // ln(n) growth gives late/early = ln 2 / ln 25 ≈ 0.22; linear growth 1.
    assert!(late < 0.35 * early, "early {early} late {late}");
    assert!(late / 25.0 < 0.05, "late slope {}", late / 25.0);
    assert!(sep.mean[49] < 10.0);
}

/// The separation ensemble does not depend on the thread count.
#[test]
fn separation_is_thread_independent() {
    let billiard = Billiard::new(Stadium::new(1.0).unwrap(), law(0.5));
    let run = |threads| {
        phase_space_separation(
            &billiard,
            &SeparationOptions {
                pairs: 300,
                collisions: 20,
                seed: SEED,
                threads,
                ..SeparationOptions::default()
            },
        )
        .unwrap()
    };
    assert_eq!(run(Threads::Fixed(1)), run(Threads::Fixed(2)));
}

/// Energy (paper appendix "Energy conservation"): `|E_n − E_0| ≤ 1e-14` over
/// 10⁵ collisions in all four tables' chaotic members and the circle.
#[test]
fn energy_trace_stays_at_rounding() {
    fn check<B: Boundary>(table: B, alpha: f64) -> f64 {
        let billiard = Billiard::new(table, law(alpha));
        let start = Sampler::Paper.initial_state(billiard.table(), billiard.law(), SEED, 0);
        let trace = energy_trace(&billiard, start, 100_000, 1_000).unwrap();
        assert_eq!(trace.points.len(), 100);
        assert_eq!(trace.points[99].collisions, 100_000);
        let worst = trace.points.iter().map(|p| p.deviation).fold(0.0, f64::max);
        assert_eq!(worst, trace.max_deviation);
        assert!(trace.max_deviation <= 1e-14, "{}", trace.max_deviation);
        trace.max_deviation
    }
    for alpha in [0.0, 0.4, 1.0] {
        let s = check(Stadium::new(1.0).unwrap(), alpha);
        let n = check(Sinai::new(2.0, 1.0).unwrap(), alpha);
        let c = check(Circle::unit(), alpha);
        eprintln!("α={alpha}: max |ΔE| stadium {s:e} sinai {n:e} circle {c:e}");
    }
}

/// Collision rate and per-collision exponent (paper appendix "Collision
/// rate"): ν of one run, `λ/ν`, and the ensemble summary.
#[test]
fn collision_rate_and_per_collision_exponent() {
    let billiard = Billiard::new(Stadium::new(1.0).unwrap(), law(0.5));
    let results: Vec<_> = (0..20)
        .map(|i| {
            let mut rng = ic_rng(SEED, i);
            let s = Sampler::Paper.sample(billiard.table(), billiard.law(), &mut rng);
            largest_lyapunov(
                &billiard,
                s,
                &LyapunovOptions::new(10_000, Method::Tangent),
                &mut rng,
            )
            .unwrap()
        })
        .collect();
    let r = CollisionRate::of(&results[0]).unwrap();
    assert_eq!(r.collisions, 10_000);
    assert!((r.rate - 10_000.0 / results[0].time).abs() < 1e-12);
    assert!((per_collision_exponent(&results[0]) - results[0].per_collision).abs() < 1e-12);
    let summary = collision_rate_summary(&results).unwrap();
    eprintln!("{summary:?}");
    assert_eq!(summary.n, 20);
    assert!((summary.rate_mean - 0.355).abs() < 0.01);
    assert!(summary.rate_sem > 0.0 && summary.rate_sem < 0.01);
    assert!((summary.per_collision - summary.exponent_mean / summary.rate_mean).abs() < 1e-12);
    assert!(summary.per_collision_sem > 0.0);
    assert!((summary.mean_per_collision - summary.per_collision).abs() < 0.05);
    assert!(matches!(
        collision_rate_summary(&results[..1]),
        Err(AnalysisError::InvalidOption { .. })
    ));
    assert!(CollisionRate::new(0, 1.0).is_err());
    assert!(CollisionRate::new(1, 0.0).is_err());
}

#[test]
fn bad_options_are_errors() {
    let billiard = Billiard::new(Stadium::new(1.0).unwrap(), law(0.5));
    for opts in [
        SeparationOptions {
            pairs: 1,
            ..Default::default()
        },
        SeparationOptions {
            collisions: 0,
            ..Default::default()
        },
        SeparationOptions {
            delta0: -1.0,
            ..Default::default()
        },
    ] {
        assert!(matches!(
            phase_space_separation(&billiard, &opts),
            Err(AnalysisError::InvalidOption { .. })
        ));
    }
    assert!(
        wall_statistics_ensemble(&billiard, Sampler::Paper, 0, 5..5, 10, Threads::All).is_err()
    );
    let start = Sampler::Paper.initial_state(billiard.table(), billiard.law(), 0, 0);
    assert!(energy_trace(&billiard, start, 10, 0).is_err());
    let sep = phase_space_separation(
        &billiard,
        &SeparationOptions {
            pairs: 2,
            collisions: 5,
            ..Default::default()
        },
    )
    .unwrap();
    assert!(sep.fit(0..=3).is_err());
    assert!(sep.fit(2..=2).is_err());
    assert!(sep.fit(1..=6).is_err());
}
