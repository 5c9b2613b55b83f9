//! Tables built from segments get the same estimates as the built-in ones,
//! through the same public API, and the two engines agree.
//!
//! Reference numbers: the built-in tables, run here with the same method
//! and sizes but an independent seed, so the difference of the two means is
//! a difference of independent estimates and must lie within 3 combined
//! standard errors (a fixed seed makes the test deterministic).

use std::f64::consts::{FRAC_PI_2, PI, TAU};

use spinball_analysis::AnalysisError;
use spinball_analysis::estimators::Method;
use spinball_analysis::run::{Engine, Ensemble, LyapunovEstimate, Starts, StopReason, Threads};
use spinball_core::{Sampler, SpinLaw, State};
use spinball_geometry::{
    ArcSegment, Boundary, DVec2, LineSegment, Segment, SegmentTable, Sinai, Stadium,
};
use spinball_test_support::segment_sinai;

fn line(a: (f64, f64), b: (f64, f64)) -> Segment {
    Segment::Line(LineSegment::new(DVec2::new(a.0, a.1), DVec2::new(b.0, b.1)).unwrap())
}

/// The Bunimovich stadium (flat half-length `a`, unit caps) written as walls.
fn segment_stadium(a: f64) -> SegmentTable {
    SegmentTable::new(vec![
        line((-a, -1.0), (a, -1.0)),
        Segment::Arc(ArcSegment::new(DVec2::new(a, 0.0), 1.0, -FRAC_PI_2, PI).unwrap()),
        line((a, 1.0), (-a, 1.0)),
        Segment::Arc(ArcSegment::new(DVec2::new(-a, 0.0), 1.0, FRAC_PI_2, PI).unwrap()),
    ])
    .unwrap()
}

fn run<B: Boundary + Sync>(table: B, alpha: f64, seed: u64) -> LyapunovEstimate {
    Ensemble::new(table, SpinLaw::new(alpha).unwrap())
        .with_seed(seed)
        .with_ics(480)
        .with_collisions(5_000)
        .with_method(Method::Tangent)
        .run()
        .unwrap()
}

fn within_3_sem(a: &LyapunovEstimate, b: &LyapunovEstimate) {
    let combined = a.sem().hypot(b.sem());
    assert!(
        (a.mean() - b.mean()).abs() < 3.0 * combined,
        "{} vs {}: difference {} > 3 × {combined}",
        a.mean(),
        b.mean(),
        (a.mean() - b.mean()).abs()
    );
    let f = a
        .chaotic_fraction_sem()
        .hypot(b.chaotic_fraction_sem())
        .max(1e-3);
    assert!(
        (a.chaotic_fraction() - b.chaotic_fraction()).abs() < 3.0 * f,
        "chaotic fractions {} vs {}",
        a.chaotic_fraction(),
        b.chaotic_fraction()
    );
}

#[test]
fn exact_geometry_of_segment_tables() {
    let (seg, built) = (segment_stadium(1.0), Stadium::new(1.0).unwrap());
    assert!((seg.area() - built.area()).abs() < 1e-12);
    assert!((seg.perimeter() - built.perimeter()).abs() < 1e-12);
    assert!((seg.curved_length() - built.curved_length()).abs() < 1e-12);
    let (seg, built) = (segment_sinai(2.0, 1.0), Sinai::new(2.0, 1.0).unwrap());
    assert!((seg.area() - built.area()).abs() < 1e-12);
    assert!((seg.curved_length() - TAU).abs() < 1e-12);
    // The provided defaults (a fan of rays) agree with the exact values to
    // the accuracy they promise.
    struct Plain(Stadium);
    impl Boundary for Plain {
        fn cast(&self, o: DVec2, v: DVec2) -> Option<spinball_geometry::Hit> {
            self.0.cast(o, v)
        }
    }
    let plain = Plain(built_stadium());
    assert!((plain.area() / built_stadium().area() - 1.0).abs() < 1e-5);
    assert!((plain.curved_length() / built_stadium().curved_length() - 1.0).abs() < 1e-3);
    assert_eq!(plain.shape(), None);
}

fn built_stadium() -> Stadium {
    Stadium::new(1.0).unwrap()
}

#[test]
fn segment_stadium_matches_the_built_in_stadium() {
    for alpha in [0.0, 0.5] {
        let seg = run(segment_stadium(1.0), alpha, 11);
        let built = run(built_stadium(), alpha, 12);
        assert_eq!(seg.table().shape, segment_stadium(1.0).shape());
        assert_eq!(seg.table().name, "segments(4 walls)");
        within_3_sem(&seg, &built);
    }
}

#[test]
fn segment_sinai_matches_the_built_in_sinai() {
    for alpha in [0.0, 0.5] {
        let seg = run(segment_sinai(2.0, 1.0), alpha, 21);
        let built = run(Sinai::new(2.0, 1.0).unwrap(), alpha, 22);
        within_3_sem(&seg, &built);
    }
}

#[test]
fn a_segment_table_gets_a_full_estimate() {
    let e = run(segment_stadium(1.0), 0.5, 3);
    assert_eq!(e.n_ics(), 480);
    assert_eq!(e.stop(), StopReason::Completed);
    assert!(e.sem() > 0.0 && e.mean().is_finite());
    assert!(e.chaotic_fraction() > 0.0 && e.chaotic_fraction() <= 1.0);
    assert!(e.collision_rate() > 0.0 && e.wall_time_s() > 0.0);
    assert_eq!(e.sampler(), Some(Sampler::Paper));
    assert_eq!(e.method(), Method::Tangent);
}

#[test]
fn both_engines_give_the_same_trajectories_on_segment_tables() {
    for (table, alpha) in [(segment_stadium(1.0), 0.5), (segment_sinai(2.0, 1.0), 0.3)] {
        for method in [Method::Tangent, Method::default()] {
            let e = Ensemble::new(table.clone(), SpinLaw::new(alpha).unwrap())
                .with_seed(4)
                .with_indices(3..203) // a ragged tail in any lane count
                .with_collisions(1_000)
                .with_method(method);
            let lanes = e.clone().with_engine(Engine::Lanes).run().unwrap();
            let scalar = e.with_engine(Engine::Scalar).run().unwrap();
            assert_eq!(scalar.engine(), Engine::Scalar);
            for (l, s) in lanes.trajectories().iter().zip(scalar.trajectories()) {
                assert_eq!((l.index, l.collisions), (s.index, s.collisions));
                assert_eq!(l.time.to_bits(), s.time.to_bits(), "time of IC {}", l.index);
                let tol = 1e-9 * s.exponent.abs().max(1e-3);
                assert!((l.exponent - s.exponent).abs() < tol, "IC {}", l.index);
            }
        }
    }
}

#[test]
fn explicit_states_run_like_drawn_ones_and_fail_alike() {
    let table = segment_stadium(1.0);
    let law = SpinLaw::new(0.4).unwrap();
    let mut states: Vec<State> = (0..40)
        .map(|i| Sampler::Paper.initial_state(&table, &law, 8, i))
        .collect();
    let e = Ensemble::from_states(table.clone(), law, states.clone())
        .with_collisions(800)
        .with_threads(Threads::Fixed(2));
    assert_eq!(e.n_ics(), 40);
    let lanes = e.clone().run().unwrap();
    let scalar = e.clone().with_engine(Engine::Scalar).run().unwrap();
    assert_eq!(lanes.sampler(), None);
    assert_eq!(lanes.n_ics(), 40);
    for (l, s) in lanes.trajectories().iter().zip(scalar.trajectories()) {
        assert_eq!(l.time.to_bits(), s.time.to_bits());
    }
    // Past the end of the list: a clear error, not a panic.
    assert!(matches!(
        e.clone().with_indices(0..41).run(),
        Err(AnalysisError::InvalidOption {
            name: "indices",
            ..
        })
    ));
    // A state outside the table: the same launch error, with the same
    // absolute index, on both engines.
    states[29] = State::new(DVec2::new(5.0, 0.0), DVec2::new(1.0, 0.0), 0.0);
    let bad = Ensemble::from_states(table, law, states).with_indices(10..40);
    let on_lanes = bad.clone().run().unwrap_err();
    let on_scalar = bad.with_engine(Engine::Scalar).run().unwrap_err();
    assert!(
        matches!(on_lanes, AnalysisError::Launch { index: 29, .. }),
        "{on_lanes}"
    );
    assert_eq!(on_lanes, on_scalar);
    assert!(matches!(Starts::from(Sampler::Paper), Starts::Sampled(_)));
}

/// A ring 0.001 wide (a unit disk with a hole of radius 0.999): the paper's
/// draw (positions that stay inside when scaled up by 1/0.99) has no room.
/// Both engines stop with the same typed error instead of retrying forever;
/// the microcanonical draw runs.
#[test]
fn a_ring_too_thin_for_the_paper_draw_is_an_error_on_both_engines() {
    let ring = SegmentTable::with_holes(
        vec![Segment::Arc(
            ArcSegment::new(DVec2::ZERO, 1.0, 0.0, TAU).unwrap(),
        )],
        vec![vec![Segment::Arc(
            ArcSegment::new(DVec2::ZERO, 0.999, 0.0, -TAU).unwrap(),
        )]],
    )
    .unwrap();
    let e = Ensemble::new(ring, SpinLaw::new(0.5).unwrap())
        .with_ics(16)
        .with_collisions(100);
    let on_lanes = e.clone().run().unwrap_err();
    let on_scalar = e.clone().with_engine(Engine::Scalar).run().unwrap_err();
    assert!(matches!(on_lanes, AnalysisError::NoRoom(_)), "{on_lanes}");
    assert_eq!(on_lanes, on_scalar);
    let drawn = e.with_sampler(Sampler::Microcanonical).run().unwrap();
    assert!(drawn.mean().is_finite());
}

/// The mushroom of `docs/tables/mushroom.toml`, every coordinate times `s`.
fn mushroom(s: f64) -> SegmentTable {
    SegmentTable::new(vec![
        line((-0.3 * s, -s), (0.3 * s, -s)),
        line((0.3 * s, -s), (0.3 * s, 0.0)),
        line((0.3 * s, 0.0), (s, 0.0)),
        Segment::Arc(ArcSegment::new(DVec2::ZERO, s, 0.0, PI).unwrap()),
        line((-s, 0.0), (-0.3 * s, 0.0)),
        line((-0.3 * s, 0.0), (-0.3 * s, -s)),
    ])
    .unwrap()
}

/// The tangent method measures its vector in units (positions over the
/// table's unit length, velocities over the speed), so the same dynamics
/// on a table scaled by `2^20` (exactly: the sampler draws the scaled
/// positions, the trajectories are the same scaled) give the same exponent
/// per collision. Measured in the plain 5-D norm, the positions outweighed
/// the velocities at the end and every trajectory gained `ln 2^20 ≈ 13.9`,
/// `0.0069` per collision over 2000 collisions; in units each differs by
/// an O(1) start-up term, `~5e-4` here, averaged over 64 starts.
#[test]
fn the_tangent_exponent_per_collision_does_not_depend_on_the_tables_scale() {
    let law = SpinLaw::new(0.5).unwrap();
    let per_collision = |s: f64, engine: Engine| {
        Ensemble::new(mushroom(s), law)
            .with_seed(3)
            .with_ics(64)
            .with_collisions(2_000)
            .with_method(Method::Tangent)
            .with_engine(engine)
            .run()
            .unwrap()
            .per_collision_mean()
    };
    let scale = 2f64.powi(20);
    for engine in [Engine::Lanes, Engine::Scalar] {
        let (unit, scaled) = (per_collision(1.0, engine), per_collision(scale, engine));
        assert!(
            (unit - scaled).abs() < 0.002,
            "{engine:?}: {unit} at scale 1, {scaled} at scale 2^20"
        );
    }
}
