//! Initial-condition samplers ([`docs/PHYSICS.md`](https://github.com/spinball/spinball/blob/main/docs/PHYSICS.md#initial-conditions), "Initial conditions"): the paper's
//! convention and the microcanonical measure, and the per-IC random streams.

mod common;

use common::{ALPHAS, law, paper_tables, signed_distance};
use rand::RngCore;
use spinball_core::{PAPER_SHRINK, PAPER_SPIN_FRACTION, Sampler, ic_rng};
use spinball_geometry::Boundary;

/// ½|v|² + ½αu² = ½ is computed from a unit vector scaled by √(1 − αu²) (or
/// the sphere's z): a handful of roundings of O(1) numbers, so 1e-15.
const ENERGY_TOL: f64 = 1e-15;

#[test]
fn paper_sampler_follows_the_paper_convention() {
    assert_eq!(Sampler::default(), Sampler::Paper);
    assert_eq!((PAPER_SHRINK, PAPER_SPIN_FRACTION), (0.99, 0.5));
    for table in paper_tables() {
        for alpha in ALPHAS {
            let law = law(alpha);
            let u_max = 0.5 / alpha.sqrt();
            let mut largest = 0.0f64;
            for index in 0..2000 {
                let s = Sampler::Paper.initial_state(&table, &law, 100, index);
                assert!(
                    (s.energy(&law) - 0.5).abs() <= ENERGY_TOL,
                    "{table} alpha {alpha}"
                );
                if alpha == 0.0 {
                    assert_eq!(s.spin, 0.0);
                    assert!((s.velocity.length() - 1.0).abs() <= 1e-15);
                } else {
                    assert!(
                        s.spin.abs() <= u_max,
                        "{table} alpha {alpha}: u = {}",
                        s.spin
                    );
                    // |v|² = 1 − αu² ∈ [¾, 1].
                    let v2 = s.velocity.length_squared();
                    assert!((0.75 - 1e-15..=1.0 + 1e-15).contains(&v2));
                }
                largest = largest.max(s.spin.abs());
                // Inside the table shrunk by 0.99 (Sinai: also outside 1.01 r),
                // hence strictly inside the table.
                assert!(
                    table.contains_shrunk(s.position, PAPER_SHRINK),
                    "{table}: {:?}",
                    s.position
                );
                assert!(signed_distance(&table, s.position) > 0.0);
            }
            // The spin range is actually used: with 2000 uniform draws the
            // largest |u| is above 0.99 u_max except with probability 1e-9.
            if alpha > 0.0 {
                assert!(largest > 0.99 * u_max, "{table} alpha {alpha}: {largest}");
            }
        }
    }
}

#[test]
fn microcanonical_sampler_is_uniform_on_the_energy_sphere() {
    // V = (v, √α u) uniform on |V| = 1: by Archimedes' theorem its third
    // component z = √α u is uniform on [−1, 1] (mean 0, variance 1/3).
    // 20000 draws with a fixed seed: the mean within 4 standard errors
    // (σ/√n, σ² = 1/3) and the variance within 4 standard errors of the
    // sample variance (√(Var z²/n), Var z² = 1/5 − 1/9 = 4/45).
    let n = 20_000;
    for table in paper_tables() {
        for alpha in [0.3, 1.0, 5.0] {
            let law = law(alpha);
            let mut zs = Vec::with_capacity(n);
            let mut cos_sum = 0.0;
            for index in 0..n as u64 {
                let s = Sampler::Microcanonical.initial_state(&table, &law, 200, index);
                assert!((s.energy(&law) - 0.5).abs() <= ENERGY_TOL);
                assert!(table.contains(s.position) && signed_distance(&table, s.position) >= 0.0);
                zs.push(alpha.sqrt() * s.spin);
                cos_sum += s.velocity.x / s.velocity.length().max(f64::MIN_POSITIVE);
            }
            let nf = n as f64;
            let mean = zs.iter().sum::<f64>() / nf;
            let var = zs.iter().map(|z| (z - mean).powi(2)).sum::<f64>() / (nf - 1.0);
            assert!(zs.iter().all(|z| z.abs() <= 1.0));
            assert!(
                mean.abs() < 4.0 * (1.0 / 3.0 / nf).sqrt(),
                "{table} alpha {alpha}: mean {mean}"
            );
            assert!(
                (var - 1.0 / 3.0).abs() < 4.0 * (4.0 / 45.0 / nf).sqrt(),
                "{table} alpha {alpha}: variance {var}"
            );
            // The direction of v is uniform: mean cos φ = 0 within 4 SE (σ² = ½).
            assert!((cos_sum / nf).abs() < 4.0 * (0.5 / nf).sqrt());
        }
        // At α = 0 there is no spin and |v| = 1.
        let s = Sampler::Microcanonical.initial_state(&table, &law(0.0), 200, 0);
        assert_eq!(s.spin, 0.0);
        assert!((s.velocity.length() - 1.0).abs() <= 1e-15);
    }
}

#[test]
fn each_initial_condition_has_its_own_reproducible_stream() {
    let draw = |seed, index| {
        let mut rng = ic_rng(seed, index);
        (0..64).map(|_| rng.next_u64()).collect::<Vec<_>>()
    };
    // Same (seed, index): identical stream.
    assert_eq!(draw(7, 3), draw(7, 3));
    // Different index or seed: different streams (64 draws of 64 bits
    // cannot coincide by chance), and no draw shared in the first 64.
    for (a, b) in [
        ((7, 3), (7, 4)),
        ((7, 3), (8, 3)),
        ((0, 0), (0, 1)),
        ((0, 0), (1, 0)),
    ] {
        let (x, y) = (draw(a.0, a.1), draw(b.0, b.1));
        assert_ne!(x, y);
        assert!(
            x.iter().all(|v| !y.contains(v)),
            "{a:?} and {b:?} share a draw"
        );
    }
    // Sampled states follow their stream: repeatable, independent of the
    // order in which initial conditions are drawn.
    let table = paper_tables()[2];
    let law = law(0.5);
    for sampler in [Sampler::Paper, Sampler::Microcanonical] {
        let forward: Vec<_> = (0..50)
            .map(|i| sampler.initial_state(&table, &law, 9, i))
            .collect();
        let backward: Vec<_> = (0..50)
            .rev()
            .map(|i| sampler.initial_state(&table, &law, 9, i))
            .collect();
        for (i, s) in forward.iter().enumerate() {
            assert_eq!(*s, backward[49 - i]);
            assert_eq!(*s, sampler.sample(&table, &law, &mut ic_rng(9, i as u64)));
        }
        assert_ne!(forward[0], forward[1]);
        assert_ne!(forward[0], sampler.initial_state(&table, &law, 10, 0));
    }
}

/// A corridor 0.009 wide and 2 long, bent into an L: no point of it, scaled
/// up by 1/0.99 about its box centre, stays inside, so the paper's draw has
/// no room (it used to retry forever); the microcanonical draw has.
#[test]
fn a_table_without_room_for_the_paper_draw_is_an_error_not_a_hang() {
    use glam::DVec2;
    use spinball_core::SpinLaw;
    use spinball_geometry::{MAX_INTERIOR_DRAWS, SegmentTable};

    let w = 0.009;
    let corridor = SegmentTable::polygon(&[
        DVec2::new(0.0, 0.0),
        DVec2::new(2.0, 0.0),
        DVec2::new(2.0, w),
        DVec2::new(w, w),
        DVec2::new(w, 2.0),
        DVec2::new(0.0, 2.0),
    ])
    .unwrap();
    let law = SpinLaw::new(0.5).unwrap();
    let err = Sampler::Paper
        .try_initial_state(&corridor, &law, 1, 0)
        .unwrap_err();
    assert_eq!(err.sampler, "paper");
    assert_eq!(err.draws, MAX_INTERIOR_DRAWS);
    assert!(err.to_string().contains("microcanonical"), "{err}");
    // The corridor fills ~0.9% of its box: the whole-table draw finds it.
    let s = Sampler::Microcanonical
        .try_initial_state(&corridor, &law, 1, 0)
        .unwrap();
    assert!(corridor.contains(s.position));
    // The fallible draw is the infallible one where there is room.
    assert_eq!(
        Some(s),
        Some(Sampler::Microcanonical.initial_state(&corridor, &law, 1, 0))
    );
}
