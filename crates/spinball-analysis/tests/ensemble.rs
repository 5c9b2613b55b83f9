//! Ensembles: bitwise reproducibility across thread counts and index-range
//! splits, the stop rule, and input validation.

use std::time::Duration;

use spinball_analysis::estimators::Method;
use spinball_analysis::run::{
    Ensemble, LyapunovEstimate, StopReason, StopRule, Threads, ftle_trajectories, trajectory_ftle,
};
use spinball_core::{Billiard, Sampler, SpinLaw};
use spinball_geometry::{Boundary, Sinai, Stadium, Table};

fn stadium(alpha: f64) -> Ensemble<Stadium> {
    Ensemble::new(Stadium::new(1.0).unwrap(), SpinLaw::new(alpha).unwrap())
        .with_seed(2024)
        .with_collisions(500)
        .with_threads(Threads::Fixed(1))
}

/// Every number of two estimates, compared by its bits (wall time and stop
/// reason excluded: they describe the run, not the result).
fn assert_same_bits(a: &LyapunovEstimate, b: &LyapunovEstimate) {
    let bits = |e: &LyapunovEstimate| {
        vec![
            e.mean().to_bits(),
            e.sem().to_bits(),
            e.median().to_bits(),
            e.std().to_bits(),
            e.min().to_bits(),
            e.max().to_bits(),
            e.conditional_mean().map_or(u64::MAX, f64::to_bits),
            e.chaotic_fraction().to_bits(),
            e.chaotic_fraction_sem().to_bits(),
            e.per_collision_mean().to_bits(),
            e.collision_rate().to_bits(),
            e.total_time().to_bits(),
            e.n_ics(),
            e.first_index(),
            e.collisions_per_ic(),
        ]
    };
    assert_eq!(bits(a), bits(b));
    assert_eq!(a.trajectories().len(), b.trajectories().len());
    for (x, y) in a.trajectories().iter().zip(b.trajectories()) {
        assert_eq!(x.index, y.index);
        assert_eq!(x.exponent.to_bits(), y.exponent.to_bits());
        assert_eq!(x.per_collision.to_bits(), y.per_collision.to_bits());
        assert_eq!(x.time.to_bits(), y.time.to_bits());
        assert_eq!(x.collisions, y.collisions);
    }
    assert_eq!(
        (
            &a.table(),
            a.alpha().to_bits(),
            &a.method(),
            a.sampler(),
            a.seed()
        ),
        (
            &b.table(),
            b.alpha().to_bits(),
            &b.method(),
            b.sampler(),
            b.seed()
        )
    );
}

#[cfg(feature = "rayon")]
#[test]
fn bitwise_identical_on_one_and_two_threads() {
    for method in [Method::default(), Method::Tangent] {
        let e = stadium(0.5).with_ics(37).with_method(method);
        let one = e.clone().with_threads(Threads::Fixed(1)).run().unwrap();
        let two = e.clone().with_threads(Threads::Fixed(2)).run().unwrap();
        let all = e.with_threads(Threads::All).run().unwrap();
        assert_same_bits(&one, &two);
        assert_same_bits(&one, &all);
    }
}

#[test]
fn merged_splits_equal_one_run() {
    let n = 23;
    let e = stadium(0.5).with_ics(n);
    let whole = e.run().unwrap();
    for k in [2, 3, 11, 20, n - 2] {
        let a = e.clone().with_indices(0..k).run().unwrap();
        let b = e.clone().with_indices(k..n).run().unwrap();
        assert_same_bits(&a.merge(&b).unwrap(), &whole);
        // either order
        assert_same_bits(&b.merge(&a).unwrap(), &whole);
    }
    // three shards
    let a = e.clone().with_indices(0..7).run().unwrap();
    let b = e.clone().with_indices(7..15).run().unwrap();
    let c = e.clone().with_indices(15..n).run().unwrap();
    let merged = a.merge(&b).unwrap().merge(&c).unwrap();
    assert_same_bits(&merged, &whole);
    assert_eq!(
        merged.wall_time_s(),
        a.wall_time_s() + b.wall_time_s() + c.wall_time_s()
    );
}

#[test]
fn trajectories_do_not_depend_on_their_neighbours() {
    let billiard = Billiard::new(Sinai::new(2.0, 1.0).unwrap(), SpinLaw::new(1.0).unwrap());
    let run = ftle_trajectories(
        &billiard,
        Sampler::Paper,
        5,
        10..20,
        300,
        Method::Tangent,
        Threads::Fixed(1),
    )
    .unwrap();
    let single = trajectory_ftle(&billiard, Sampler::Paper, 5, 14, 300, Method::Tangent).unwrap();
    assert_eq!(run[4], single);
    assert_eq!(
        run.iter().map(|t| t.index).collect::<Vec<_>>(),
        (10..20).collect::<Vec<_>>()
    );
}

#[test]
fn merge_rejects_incompatible_parts() {
    let e = stadium(0.5);
    let a = e.clone().with_indices(0..4).run().unwrap();
    let gap = e.clone().with_indices(5..8).run().unwrap();
    assert!(a.merge(&gap).is_err(), "not adjacent");
    let overlap = e.clone().with_indices(2..6).run().unwrap();
    assert!(a.merge(&overlap).is_err(), "overlapping");
    let other_seed = e.clone().with_seed(1).with_indices(4..8).run().unwrap();
    assert!(a.merge(&other_seed).is_err());
    let other_method = e
        .clone()
        .with_method(Method::Tangent)
        .with_indices(4..8)
        .run()
        .unwrap();
    assert!(a.merge(&other_method).is_err());
    let other_alpha = stadium(0.4).with_indices(4..8).run().unwrap();
    assert!(a.merge(&other_alpha).is_err());
    let other_collisions = e.with_collisions(400).with_indices(4..8).run().unwrap();
    assert!(a.merge(&other_collisions).is_err());
}

#[test]
fn stop_rule_target_is_deterministic_and_equals_a_plain_run() {
    // Stadium α = 0.5 is bimodal (std ≈ 0.05 at 500 collisions): a 5% target
    // needs a few batches, not one.
    let e = stadium(0.5).with_ics(10_000);
    let rule = StopRule::new(16, 0.05);
    let first = e.run_until(&rule).unwrap();
    assert_eq!(first.stop(), StopReason::TargetReached);
    assert!(first.sem() <= 0.05 * first.mean().abs());
    assert_eq!(first.n_ics() % 16, 0, "stops at a batch boundary");
    assert!(first.n_ics() > 16, "needed more than one batch");
    // the batch before did not reach the target
    let before = e.clone().with_indices(0..first.n_ics() - 16).run().unwrap();
    assert!(before.sem() > 0.05 * before.mean().abs());
    // same schedule, same answer
    let again = e.run_until(&rule).unwrap();
    assert_same_bits(&first, &again);
    // and the same numbers as a plain run over the indices covered
    let plain = e.clone().with_indices(first.indices()).run().unwrap();
    assert_same_bits(&first, &plain);
}

#[test]
fn stop_rule_min_ics_and_range() {
    let e = stadium(0.0).with_ics(40);
    // α = 0 is uniformly chaotic: a 50% target is met after the first batch
    // unless min_ics holds it back.
    let early = e.run_until(&StopRule::new(8, 0.5)).unwrap();
    assert_eq!(
        (early.stop(), early.n_ics()),
        (StopReason::TargetReached, 8)
    );
    let held = e
        .run_until(&StopRule::new(8, 0.5).with_min_ics(20))
        .unwrap();
    assert_eq!((held.stop(), held.n_ics()), (StopReason::TargetReached, 24));
    // an unreachable target runs out of initial conditions (last batch partial)
    let exhausted = e.run_until(&StopRule::new(16, 0.0)).unwrap();
    assert_eq!(
        (exhausted.stop(), exhausted.n_ics()),
        (StopReason::RangeExhausted, 40)
    );
}

#[test]
fn stop_rule_time_budget() {
    // A zero budget is spent after the first batch.
    let e = stadium(0.0).with_ics(1000);
    let est = e
        .run_until(&StopRule::new(4, 0.0).with_time_budget(Duration::ZERO))
        .unwrap();
    assert_eq!((est.stop(), est.n_ics()), (StopReason::TimeBudget, 4));
    // the target wins when both hold after the same batch
    let est = e
        .run_until(&StopRule::new(4, 1.0).with_time_budget(Duration::ZERO))
        .unwrap();
    assert_eq!(est.stop(), StopReason::TargetReached);
}

#[test]
fn invalid_options_are_errors() {
    let e = stadium(0.5);
    assert!(e.clone().with_ics(1).run().is_err(), "one IC has no SEM");
    assert!(e.clone().with_indices(5..5).run().is_err());
    assert!(e.clone().with_collisions(0).run().is_err());
    assert!(
        e.clone()
            .with_method(Method::FiniteDifference { delta0: -1.0 })
            .run()
            .is_err()
    );
    assert!(e.clone().with_threads(Threads::Fixed(0)).run().is_err());
    assert!(e.clone().with_threshold(f64::NAN).run().is_err());
    assert!(e.run_until(&StopRule::new(1, 0.01)).is_err());
    assert!(stadium(0.5).run_until(&StopRule::new(8, f64::NAN)).is_err());
}

#[test]
fn estimate_carries_its_parameters() {
    let table: Table = "sinai:L=2,R=1".parse().unwrap();
    let est = Ensemble::new(table, SpinLaw::extended(2.0).unwrap())
        .with_seed(9)
        .with_indices(100..104)
        .with_collisions(200)
        .with_sampler(Sampler::Microcanonical)
        .with_threads(Threads::Fixed(1))
        .run()
        .unwrap();
    assert_eq!(est.table().name, "sinai:L=2,R=1");
    assert_eq!(est.table().name.parse::<Table>().unwrap(), table);
    assert_eq!(est.table().shape, table.shape());
    assert_eq!(est.alpha(), 2.0);
    assert_eq!((est.method().name(), est.delta0()), ("fd", Some(1e-7)));
    assert_eq!(est.sampler(), Some(Sampler::Microcanonical));
    assert_eq!((est.seed(), est.first_index(), est.n_ics()), (9, 100, 4));
    assert_eq!(est.indices(), 100..104);
    assert_eq!(est.collisions_per_ic(), 200);
    assert_eq!(est.total_collisions(), 800);
    assert_eq!(est.version(), env!("CARGO_PKG_VERSION"));
    assert_eq!(est.stop(), StopReason::Completed);
    assert!(est.wall_time_s() >= 0.0);
    assert!((est.collision_rate() - 800.0 / est.total_time()).abs() < 1e-12);
    assert_eq!(est.ftle().unwrap().len(), 4);
    assert!(est.to_string().contains("sinai:L=2,R=1"));
}

#[cfg(feature = "serde")]
#[test]
fn estimate_round_trips_through_json() {
    let est = stadium(0.5).with_ics(5).run().unwrap();
    let json = serde_json::to_string(&est).unwrap();
    let back: LyapunovEstimate = serde_json::from_str(&json).unwrap();
    assert_same_bits(&back, &est);
    assert_eq!(back, est);
}
