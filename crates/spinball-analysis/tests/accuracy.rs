//! The error decomposition: the finite-time bias estimator on synthetic
//! series with known answers, on tables with known `λ = 0`, and the
//! planner's predictions against a real run of its plan.
//!
//! Synthetic series use a fixed-seed generator; tolerances are several
//! standard errors. Run with `-- --nocapture` to see the numbers.

use spinball_analysis::estimators::Method;
use spinball_analysis::precision::{
    BiasLaw, BiasRegime, Budget, ErrorBudget, FiniteTimeBias, Planner, Reference, work_precision,
};
use spinball_analysis::run::{Engine, Ensemble, StopReason, StopRule, Threads};
use spinball_core::SpinLaw;
use spinball_geometry::{Circle, Rectangle, Stadium, Table};
use spinball_test_support::Normal;

const CHECKPOINTS: [u64; 5] = [1_000, 2_000, 4_000, 8_000, 16_000];

/// `n` trajectories with `λ_T = λ + c_i g(T) + noise`, `c_i = c (1 + 0.3 ξ)`
/// and a noise of size `sigma/√T` that is a running average: each IC's
/// noise at `2T` shares its first half with `T` (as a real running
/// exponent's does).
fn synthetic(
    law: BiasLaw,
    lambda: f64,
    c: f64,
    sigma: f64,
    n: usize,
    rng: &mut Normal,
) -> Vec<Vec<f64>> {
    (0..n)
        .map(|_| {
            let ci = c * (1.0 + 0.3 * rng.next());
            // Sum of independent increments over each doubling.
            let mut sum = 0.0;
            let mut prev = 0u64;
            CHECKPOINTS
                .iter()
                .map(|&t| {
                    sum += sigma * ((t - prev) as f64).sqrt() * rng.next();
                    prev = t;
                    lambda + ci * law.g(t as f64) + sum / t as f64
                })
                .collect()
        })
        .collect()
}

#[test]
fn inverse_t_bias_is_recovered_with_honest_errors() {
    let (lambda, c) = (0.3, 40.0);
    let mut rng = Normal(7);
    let mut pulls_a = Vec::new();
    let mut pulls_b = Vec::new();
    for _ in 0..40 {
        let rows = synthetic(BiasLaw::InverseT, lambda, c, 0.5, 64, &mut rng);
        let fit = FiniteTimeBias::fit(&CHECKPOINTS, &rows).unwrap();
        let f = fit.inverse_t;
        pulls_a.push((f.limit.value - lambda) / f.limit.sem);
        pulls_b.push((f.coefficient.value - c) / f.coefficient.sem);
        assert!(f.limit.sem > 0.0 && f.coefficient.sem > 0.0);
        // The bias at the last checkpoint is b/T_last.
        assert!((f.bias.value - f.coefficient.value / 16_000.0).abs() < 1e-15);
    }
    // Each estimate within 4 SE, and the pulls have unit spread (the
    // reported SE is the real one, within sampling error of 40 repeats).
    let rms = |p: &[f64]| (p.iter().map(|x| x * x).sum::<f64>() / p.len() as f64).sqrt();
    for p in [&pulls_a, &pulls_b] {
        assert!(p.iter().all(|x| x.abs() < 4.0), "{p:?}");
        assert!((0.7..1.35).contains(&rms(p)), "rms pull {}", rms(p));
    }
    // With 1/T data the regime is 1/T in almost every repeat.
    let rows = synthetic(BiasLaw::InverseT, lambda, c, 0.5, 256, &mut rng);
    let fit = FiniteTimeBias::fit(&CHECKPOINTS, &rows).unwrap();
    assert_eq!(fit.regime, BiasRegime::InverseT, "{fit:?}");
    assert!(fit.inverse_t.consistent());
}

#[test]
fn log_t_decay_is_diagnosed() {
    // A regular orbit: λ = 0, λ_T = c ln T / T, small noise.
    let mut rng = Normal(11);
    let rows = synthetic(BiasLaw::LogTOverT, 0.0, 2.0, 0.02, 128, &mut rng);
    let fit = FiniteTimeBias::fit(&CHECKPOINTS, &rows).unwrap();
    eprintln!(
        "ln T/T data: 1/T chi2 {:.1}, ln T/T chi2 {:.1}",
        fit.inverse_t.chi2, fit.log_t.chi2
    );
    assert_eq!(fit.regime, BiasRegime::LogTOverT);
    assert!(!fit.inverse_t.consistent() && fit.log_t.consistent());
    let f = fit.preferred();
    assert_eq!(f.law, BiasLaw::LogTOverT);
    assert!(f.limit.value.abs() < 4.0 * f.limit.sem, "{:?}", f.limit);
    assert!((f.coefficient.value - 2.0).abs() < 4.0 * f.coefficient.sem);
    // The bias is the whole of λ_T at the last checkpoint.
    let last = fit.last();
    assert!((fit.bias().value - last.value).abs() < 4.0 * fit.bias().sem.hypot(f.limit.sem));
}

/// Circle and rectangle are integrable at every α (paper §IV): `λ = 0`.
/// Read at nested checkpoints, the estimate extrapolates to zero and its
/// finite-time bias accounts for all of `λ_T`, for both methods.
#[test]
fn integrable_tables_extrapolate_to_zero() {
    let tables: [Table; 2] = [
        Circle::unit().into(),
        Rectangle::new(1.0, 1.0).unwrap().into(),
    ];
    for table in tables {
        for method in [Method::Tangent, Method::default()] {
            let ensemble = Ensemble::new(table, SpinLaw::new(0.5).unwrap())
                .with_seed(3)
                .with_ics(48)
                .with_method(method)
                .with_engine(Engine::Scalar)
                .with_threads(Threads::All);
            let (budget, columns) =
                ErrorBudget::measure(&ensemble, &[1_000, 2_000, 4_000, 8_000, 16_000]).unwrap();
            let bias = FiniteTimeBias::from_columns(&columns).unwrap();
            let (f, limit) = (bias.preferred(), bias.limit());
            eprintln!(
                "{table} {}: λ_T = {:.2e} ± {:.1e}, regime {:?}, limit {:.2e} ± {:.1e}, bias {:.2e} ± {:.1e}, chi2 1/T {:.1} lnT/T {:.1}, total {:.2e}",
                method.name(),
                budget.value.value,
                budget.sem,
                bias.regime,
                limit.value,
                limit.sem,
                budget.finite_time_bias.value,
                budget.finite_time_bias.sem,
                bias.inverse_t.chi2,
                bias.log_t.chi2,
                budget.total.value
            );
            // λ_∞ = 0 within 4 of its stated errors (statistical and, where
            // neither law fits, the spread between the laws).
            assert!(
                limit.value.abs() < 4.0 * limit.sem,
                "{table}: limit {limit:?} ({f:?})"
            );
            // Tangent dynamics sees the linear shear of the regular orbits:
            // the diagnosis rejects a chaotic 1/T transient.
            if method == Method::Tangent {
                assert_ne!(bias.regime, BiasRegime::InverseT, "{table}");
            }
            // The total error covers the distance of λ_T from the true 0.
            assert!(
                budget.value.value.abs() < 2.0 * budget.total.value,
                "{table}: {budget:?}"
            );
        }
    }
}

/// The planner's prediction against a real run of its plan: the stop rule
/// on total error stops the planned ensemble within a factor 2 of the
/// planned number of initial conditions (so within a factor 2 of the
/// predicted work in IC-steps), and the error budget measured on that run
/// is within a factor 2 of the predicted total error.
#[test]
fn planner_predicts_the_work_and_error_of_its_plan() {
    let scene = Ensemble::new(Stadium::new(1.0).unwrap(), SpinLaw::new(0.0).unwrap())
        .with_seed(21)
        .with_engine(Engine::Scalar)
        .with_threads(Threads::All);
    let pilot = scene.clone().with_ics(32);
    let planner = Planner::pilot(
        &pilot,
        &[Method::Tangent, Method::default()],
        &[250, 500, 1_000, 2_000],
    )
    .unwrap()
    .with_collision_range(250, 20_000);
    let plan = planner.plan(0.005).unwrap();
    eprintln!("{plan:?}");
    let run = plan
        .ensemble(scene.clone().with_seed(22), 4 * plan.ics)
        .run_until(&plan.stop_rule(8))
        .unwrap();
    eprintln!("stopped after {} ICs: {}", run.n_ics(), run.stop());
    assert_eq!(run.stop(), StopReason::TotalErrorReached);
    let ratio = run.n_ics() as f64 / plan.ics as f64;
    assert!(
        (0.5..2.0).contains(&ratio),
        "ICs {} vs planned {}",
        run.n_ics(),
        plan.ics
    );
    let work = run.total_collisions() as f64 / plan.predicted_ic_steps as f64;
    assert!((0.5..2.0).contains(&work), "work ratio {work}");
    // The budget of the run actually done, from its own checkpoints.
    let t = plan.collisions;
    let measured = plan
        .ensemble(scene.with_seed(22), run.n_ics())
        .with_indices(0..run.n_ics());
    let (budget, _) = ErrorBudget::measure(&measured, &[t / 8, t / 4, t / 2, t]).unwrap();
    let ratio = budget.total.value / plan.predicted_error;
    eprintln!(
        "measured total {:.3e} vs predicted {:.3e}",
        budget.total.value, plan.predicted_error
    );
    assert!((0.5..2.0).contains(&ratio), "{budget:?}");
    // Typed refusals.
    assert!(planner.plan(0.0).is_err());
    assert!(planner.plan(f64::NAN).is_err());
    assert!(matches!(
        planner.clone().with_collision_range(250, 300).plan(1e-6),
        Err(spinball_analysis::AnalysisError::TargetUnreachable { .. })
    ));
}

/// A work–precision set has one point per method, engine and budget, each
/// measured against the reference; the two engines give the same numbers
/// (to rounding) at different costs; inputs that cannot work are refused.
#[test]
fn work_precision_points_and_refusals() {
    let scene = Ensemble::new(Stadium::new(1.0).unwrap(), SpinLaw::new(0.5).unwrap())
        .with_seed(31)
        .with_threads(Threads::All);
    let reference = Reference::measure(
        &scene.clone().with_seed(32).with_ics(64),
        &[250, 500, 1_000, 2_000],
    )
    .unwrap();
    assert_eq!(reference.bias.n_ics, 64);
    let methods = [Method::Tangent, Method::FiniteDifference { delta0: 1e-9 }];
    let engines = [Engine::Lanes, Engine::Scalar];
    let budgets = [Budget::new(8, 500), Budget::new(32, 1_000)];
    let points = work_precision(&scene, &reference, &methods, &engines, &budgets).unwrap();
    assert_eq!(points.len(), 8);
    for (k, p) in points.iter().enumerate() {
        assert_eq!(p.method, methods[k / 4]);
        assert_eq!(p.engine, engines[(k / 2) % 2]);
        assert_eq!(p.budget, budgets[k % 2]);
        let d = p.estimate.value - reference.value.value;
        assert!((p.error.value - d).abs() < 1e-15);
        assert!((p.rel_error - d.hypot(p.estimate.sem) / reference.value.value).abs() < 1e-12);
        assert!(p.wall_time_s >= 0.0 && p.ns_per_step.is_finite());
    }
    for (lanes, scalar) in points[..2].iter().zip(&points[2..4]) {
        assert!((lanes.estimate.value - scalar.estimate.value).abs() < 1e-9);
    }
    assert!(work_precision(&scene, &reference, &[], &engines, &budgets).is_err());
    assert!(work_precision(&scene, &reference, &methods, &[], &budgets).is_err());
    assert!(work_precision(&scene, &reference, &methods, &engines, &[]).is_err());
    let one_ic = [Budget::new(1, 100)];
    assert!(work_precision(&scene, &reference, &methods, &engines, &one_ic).is_err());
    // A total-error stop rule with a bias that is not a number is refused.
    let bad = StopRule::total_error(8, 0.01, f64::NAN);
    assert!(scene.clone().with_ics(64).run_until(&bad).is_err());
    // A budget for a point needs the point's own ensemble.
    let est = scene
        .clone()
        .with_ics(16)
        .with_collisions(400)
        .run()
        .unwrap();
    let other = scene.clone().with_law(SpinLaw::new(0.3).unwrap());
    assert!(ErrorBudget::for_estimate(&other, &est, 8).is_err());
    assert!(ErrorBudget::for_estimate(&scene, &est, 1).is_err());
    let budget = ErrorBudget::for_estimate(&scene, &est, 8).unwrap();
    assert_eq!(
        (budget.sem, budget.n_ics, budget.collisions),
        (est.sem(), 16, 400)
    );
    assert!(budget.total.value >= budget.sem);
}

/// Everything is generic over the table: a user's segment table (an
/// L-shaped room) gets a budget, a reference and a plan like the built-in
/// ones.
#[test]
fn user_tables_get_budgets_and_plans() {
    use spinball_geometry::{DVec2, SegmentTable};
    let p = DVec2::new;
    let room = SegmentTable::polygon(&[
        p(0.0, 0.0),
        p(2.0, 0.0),
        p(2.0, 1.0),
        p(1.0, 1.0),
        p(1.0, 2.0),
        p(0.0, 2.0),
    ])
    .unwrap();
    let scene = Ensemble::new(room, SpinLaw::new(0.5).unwrap())
        .with_seed(41)
        .with_ics(24)
        .with_method(Method::Tangent);
    let checkpoints = [250, 500, 1_000, 2_000];
    let (budget, columns) = ErrorBudget::measure(&scene, &checkpoints).unwrap();
    assert_eq!(columns.len(), 4);
    assert!(budget.total.value.is_finite() && budget.total.value >= budget.sem);
    let reference = Reference::measure(&scene.clone().with_seed(42), &checkpoints).unwrap();
    assert!(reference.value.value.is_finite() && reference.value.sem > 0.0);
    let planner = Planner::pilot(&scene, &[Method::Tangent], &checkpoints).unwrap();
    // Either a plan or a typed refusal (λ of this room may be unresolved),
    // never a number that is not one.
    match planner.plan(0.05) {
        Ok(plan) => assert!(plan.predicted_error.is_finite() && plan.ics >= 16),
        Err(e) => assert!(
            matches!(
                e,
                spinball_analysis::AnalysisError::InvalidOption { .. }
                    | spinball_analysis::AnalysisError::TargetUnreachable { .. }
            ),
            "{e}"
        ),
    }
}
