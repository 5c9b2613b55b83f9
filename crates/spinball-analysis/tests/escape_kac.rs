//! The escape runs of open tables against the Kac prediction of the
//! invariant measure: the two halves of escape analysis (the ensembles of
//! `open`, the statistics of `escape`) checked together on a real hole.

use std::f64::consts::PI;

use spinball_analysis::escape::{KacPrediction, KacRatio, Survival};
use spinball_analysis::open::{Budget, OpenEnsemble};
use spinball_analysis::phase_space::{invariant_starts, state_on_section};
use spinball_analysis::run::Threads;
use spinball_core::{Billiard, SpinLaw, State};
use spinball_geometry::SegmentTable;
use spinball_test_support::normal::Normal;

/// The stadium (a = 1, unit caps) with a hole of arc length `h` centred on
/// its right cap (Birkhoff s = 2 + π/2).
fn stadium(h: f64) -> SegmentTable {
    SegmentTable::stadium_with_hole(1.0, 2.0 + PI / 2.0, h).unwrap()
}

/// Mean number of map iterations to the hole (collisions before the
/// escape, plus the hit on the hole itself) of `starts`, against Kac.
fn kac_ratio(table: SegmentTable, h: f64, starts: Vec<State>, budget: u64) -> KacRatio {
    let kac = KacPrediction::for_table(&table, h, 0.0).unwrap();
    let n = starts.len() as u64;
    let records = OpenEnsemble::new(Billiard::new(table, SpinLaw::specular()))
        .with_starts(starts)
        .with_indices(0..n)
        .with_threads(Threads::Fixed(2))
        .escape_times(Budget::collisions(budget))
        .unwrap();
    let counts: Vec<u64> = records.iter().map(|r| r.collisions + 1).collect();
    let censored: Vec<bool> = records.iter().map(|r| r.censored).collect();
    kac.compare(
        Survival::by_collisions(&counts, &censored)
            .unwrap()
            .mean_escape(),
    )
}

#[test]
fn balls_entering_through_the_hole_leave_after_kacs_mean() {
    // Kac's lemma, exact for any hole of an ergodic map (the stadium at
    // α = 0): balls entering through the hole, drawn from the invariant
    // measure on it (s uniform on the hole, sin θ uniform), hit it again
    // after |∂Q|/h iterations on average. h = 0.5; 20 000 balls, censored
    // at 10⁵ collisions (the bouncing-ball tail P(N > n) ∝ n⁻² leaves a
    // bias of order 10⁻⁵ there). Within 4 SE: the n⁻² tail makes the SE
    // itself noisy.
    let h = 0.5;
    let table = stadium(h);
    let law = SpinLaw::specular();
    let s0 = 2.0 + PI / 2.0 - h / 2.0;
    let mut rng = Normal(2024);
    let starts = (0..20_000)
        .map(|_| {
            let s = s0 + rng.uniform() * h;
            let v = 2.0 * rng.uniform() - 1.0;
            state_on_section(&table, &law, s, v, 0.0).unwrap()
        })
        .collect();
    let r = kac_ratio(table, h, starts, 100_000);
    assert!(r.deviation().abs() < 4.0, "{r:?}");
    assert!(r.ratio_sem < 0.02, "{r:?}");
}

#[test]
fn the_mean_escape_from_anywhere_approaches_kac_as_the_hole_shrinks() {
    // Balls drawn from the invariant measure of the whole section take
    // longer than Kac's |∂Q|/h on average for a finite hole (a ball
    // started on the hole leaves at once only a share h/|∂Q| of the time;
    // the slow bouncing-ball orbits weigh more), and the excess vanishes
    // as h → 0 (the escape law becomes exponential with rate μ(hole)).
    // 8000 balls per hole, censored at 2·10⁵ collisions. Measured (seed
    // 11): ratio to Kac 1.58 ± 0.14, 1.30 ± 0.07, 1.15 ± 0.04 at h = 0.4,
    // 0.2, 0.1: the excess is linear in h (≈ 1.5 h). Checked: it falls
    // as h halves, and halves with h within 3 combined SE.
    let law = SpinLaw::specular();
    let ratios: Vec<KacRatio> = [0.4, 0.2, 0.1]
        .into_iter()
        .map(|h| {
            let table = stadium(h);
            let starts = invariant_starts(&table, &law, 11, 0..8_000).unwrap();
            kac_ratio(table, h, starts, 200_000)
        })
        .collect();
    for r in &ratios {
        eprintln!(
            "ratio {:.4} ± {:.4} (measured {:.2} of predicted {:.2})",
            r.ratio, r.ratio_sem, r.measured.mean, r.predicted
        );
    }
    let excess: Vec<f64> = ratios.iter().map(|r| r.ratio - 1.0).collect();
    assert!(excess[0] > excess[1] && excess[1] > excess[2], "{excess:?}");
    for k in 0..2 {
        let se = (ratios[k].ratio_sem.powi(2) / 4.0 + ratios[k + 1].ratio_sem.powi(2)).sqrt();
        assert!(
            (excess[k + 1] - excess[k] / 2.0).abs() < 3.0 * se,
            "excess {excess:?} does not halve with h (SE {se})"
        );
    }
}
