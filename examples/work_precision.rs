//! Error against run time: work–precision sets, error budgets and plans for
//! a target total error (docs/ACCURACY.md is the report built from it).
//!
//! ```text
//! cargo run --release --example work_precision -- [--quick | --paper] [--out DIR]
//!     [--threads N] [--seed S] [--repeat N]
//! ```
//!
//! | mode      | reference (tangent, ICs × checkpoints)   | budgets N × T                   |
//! |-----------|------------------------------------------|---------------------------------|
//! | `--quick` | 256 × {500, …, 4000}                     | 16 × 500 … 256 × 2000 (seconds) |
//! | default   | 16 000 × {2500, …, 20 000}               | 64 × 1000 … 16 384 × 20 000     |
//! | `--paper` | 10⁵ × {10⁴, …, 10⁵}                      | … up to 10⁵ × 10⁵ (the paper's) |
//!
//! Scenes: stadium a = 1 and Sinai L = 2, R = 1 at α = 0, 0.5, 1, and the
//! near-integrable stadium a = 0.05 at α = 0.5 (bias dominates). On the
//! first scene (stadium, α = 0.5) every method (finite differences at
//! δ0 = 1e-5, 1e-7, 1e-9, 1e-11 and tangent) runs on both engines; on the
//! others tangent and δ0 = 1e-7 in lanes. The reference of a scene uses
//! seed + 1, so errors are measured against an independent value.
//!
//! Plain against multilevel (`compare_estimators`): on the stadium a = 1
//! at α = 0.5 and 0 and on Sinai L = 2, R = 1 at α = 1 (tangent, lanes),
//! the planner chooses, then both estimators run toward each target
//! (quick: 2%, 1%; otherwise 1%, 0.5%, 0.2%, 0.1%), `--repeat` times
//! (default 3; quick 1) in alternating order on seeds `S + 10, …`, timed in
//! processor seconds; the scene's reference above is the independent
//! value. From the 0.1% runs the cost of 0.01% is predicted from the
//! measured level variances and costs.
//!
//! Writes into `--out` (default `out/work_precision`): `work_precision.png`
//! (error against wall time; bias against T; SEM against N; planned time to
//! a target; plain against multilevel, error against processor time; the
//! multilevel correction variances against run length),
//! `work_precision.csv` (one row per point), `multilevel.csv` (one row per
//! estimator run) and `work_precision.json` (references, points, pilots,
//! plans, the paper's sizes placed on the chart, the estimator
//! comparisons and predictions).

use std::process::ExitCode;

use serde_json::json;
use spinball_analysis::estimators::Method;
use spinball_analysis::precision::{
    Budget, EstimatorComparison, Planner, Reference, compare_estimators, variance_decay,
    work_precision,
};
use spinball_analysis::run::Engine;
use spinball_core::SpinLaw;
use spinball_figures::{
    Csv, ESTIMATOR_COLUMNS, WORK_COLUMNS, bias_vs_t, error_vs_time, estimator_curves,
    estimator_rows, level_variances, method_label, run_figure_with, sem_vs_n, template,
    time_to_target, work_rows,
};
use spinball_plot::{Grid, Legend, LineKind, LinePlot, Series, palette};

const NAME: &str = "work_precision";
const ABOUT: &str = "Work–precision: error against wall time per method and engine, bias against T, SEM against N, and the planned time to a target total error.";
const SCENES: [(&str, f64); 7] = [
    ("stadium:a=1", 0.5),
    ("stadium:a=1", 0.0),
    ("stadium:a=1", 1.0),
    ("sinai:L=2,R=1", 0.0),
    ("sinai:L=2,R=1", 0.5),
    ("sinai:L=2,R=1", 1.0),
    ("stadium:a=0.05", 0.5),
];
const DELTAS: [f64; 4] = [1e-5, 1e-7, 1e-9, 1e-11];
const TARGETS: [f64; 3] = [1e-2, 1e-3, 1e-4];
/// The scenes (indices into `SCENES`) of the plain against multilevel
/// comparison: the two with spin of the targets, and α = 0 where
/// multilevel does not pay.
const ESTIMATOR_SCENES: [usize; 3] = [0, 5, 1];

/// The example's own options.
#[derive(clap::Args, Debug)]
struct Options {
    /// Repeats of each plain against multilevel comparison (medians);
    /// default 3, 1 with --quick.
    #[arg(long)]
    repeat: Option<u64>,
}

fn log_plot(title: &str, x: &str, y: &str) -> LinePlot {
    LinePlot::with_axes(title, x, y).log_x(true).log_y(true)
}

fn main() -> ExitCode {
    run_figure_with(NAME, ABOUT, |args, options: &Options, report| {
        let b = Budget::new;
        let budgets = args.pick(
            vec![b(16, 500), b(64, 1_000), b(256, 2_000)],
            vec![
                b(64, 1_000),
                b(256, 2_500),
                b(1_024, 5_000),
                b(4_096, 10_000),
                b(16_384, 20_000),
            ],
            vec![b(1_000, 10_000), b(10_000, 50_000), b(100_000, 100_000)],
        );
        let (ref_ics, ref_t) = args.pick(
            (256, vec![500, 1_000, 2_000, 4_000]),
            (16_000, vec![2_500, 5_000, 10_000, 20_000]),
            (100_000, vec![10_000, 20_000, 50_000, 100_000]),
        );
        let (pilot_ics, pilot_t) = args.pick(
            (32, vec![250, 500, 1_000, 2_000]),
            (256, vec![1_000, 2_000, 4_000, 8_000]),
            (1_000, vec![2_500, 5_000, 10_000, 20_000]),
        );
        let fd = |d| Method::FiniteDifference { delta0: d };
        let all_methods: Vec<Method> = DELTAS
            .map(fd)
            .into_iter()
            .chain([Method::Tangent])
            .collect();
        let mut csv = Csv::new(&WORK_COLUMNS);
        let main_title = "Stadium a = 1, α = 0.5";
        let mut wp = log_plot(
            &format!("{main_title}: error against wall time"),
            "wall time (s)",
            "√(Δ² + SEM²) / λ_ref",
        );
        let mut bias_t = log_plot(
            "Finite-time bias |λ_T − λ_ref| / λ_ref (tangent)",
            "T (collisions)",
            "relative bias",
        );
        let mut sem_n = log_plot(
            "Statistical error SEM / λ_ref (tangent, lanes)",
            "N (initial conditions)",
            "relative SEM",
        );
        let mut to_target = log_plot(
            &format!("{main_title}: planned wall time to a total error"),
            "target relative total error",
            "predicted wall time (s)",
        );
        let mut scenes = Vec::new();
        let mut references = Vec::new();
        for (k, &(spec, alpha)) in SCENES.iter().enumerate() {
            let scene = template(args, spec)?.with_law(SpinLaw::new(alpha)?);
            let name = format!("{spec} α={alpha}");
            let reference = Reference::measure(
                &scene.clone().with_seed(args.seed + 1).with_ics(ref_ics),
                &ref_t,
            )?;
            let lam = reference.value;
            references.push(lam);
            println!(
                "{name}: reference λ = {:.6} ± {:.1e} ({}, {:.2} s)",
                lam.value,
                lam.sem,
                reference.bias.regime.name(),
                reference.wall_time_s
            );
            // Every method and engine on the first scene, the two usual ones elsewhere.
            let (methods, engines) = if k == 0 {
                (all_methods.clone(), vec![Engine::Lanes, Engine::Scalar])
            } else {
                (
                    vec![Method::default(), Method::Tangent],
                    vec![Engine::Lanes],
                )
            };
            let points = work_precision(&scene, &reference, &methods, &engines, &budgets)?;
            work_rows(&mut csv, spec, alpha, &points);
            bias_t = bias_t.series(bias_vs_t(&name, &reference).color(palette(k)));
            sem_n = sem_n.series(
                sem_vs_n(&name, &points, &reference, Method::Tangent, Engine::Lanes)
                    .color(palette(k)),
            );
            let pilot = scene.clone().with_seed(args.seed + 2).with_ics(pilot_ics);
            let planner = Planner::pilot(&pilot, &methods, &pilot_t)?;
            let mut plans = Vec::new();
            for target in TARGETS {
                for plan in planner.plans(target)? {
                    match plan {
                        Ok(p) => {
                            let what = method_label(p.method, p.engine);
                            println!(
                                "  {:>6}% with {what:<22}: {:>8} ICs x {:>8} collisions, predicted {:.3} s",
                                100.0 * target,
                                p.ics,
                                p.collisions,
                                p.predicted_wall_s
                            );
                            plans.push(json!({"target": target, "plan": p}));
                        }
                        Err(e) => {
                            println!("  {:>6}%: {e}", 100.0 * target);
                            plans.push(json!({"target": target, "unreachable": e.to_string()}));
                        }
                    }
                }
            }
            // The paper's sizes on the chart: 10⁵ × 10⁵, and a 10⁶-IC run at 5·10⁴.
            let paper: Vec<_> = planner.pilots.iter().map(|p| {
                let at = |n: f64, t: f64| json!({"ics": n, "collisions": t, "predicted_rel_error": p.predicted_error(n, t) / lam.value.abs(), "predicted_wall_s": p.predicted_wall_s(n, t)});
                json!({"method": p.method, "engine": p.engine, "paper_1e5x1e5": at(1e5, 1e5), "campaign_1e6x5e4": at(1e6, 5e4)})
            }).collect();
            if k == 0 {
                wp = error_vs_time(wp, &points);
                to_target = time_to_target(to_target, &planner, &TARGETS);
            }
            scenes.push(json!({"table": spec, "alpha": alpha, "reference": reference, "points": points, "pilots": planner.pilots, "plans": plans, "paper_sizes": paper}));
        }
        let repeat = options.repeat.unwrap_or(args.pick(1, 3, 3)).max(1);
        let targets = args.pick(
            vec![2e-2, 1e-2],
            vec![1e-2, 5e-3, 2e-3, 1e-3],
            vec![1e-2, 5e-3, 2e-3, 1e-3],
        );
        let (ml_pilot_ics, smaller) = args.pick((16, 1e-3), (64, 1e-4), (64, 1e-4));
        let mut versus = log_plot(
            "Plain (solid) against multilevel (dashed), tangent, lanes",
            "processor time (s)",
            "stated total error / λ",
        );
        let mut variances = log_plot(
            "Multilevel corrections: variance V_l of λ_Tl − λ_Tl−1",
            "T_l (collisions)",
            "V_l",
        );
        let mut ml_csv = Csv::new(&ESTIMATOR_COLUMNS);
        let mut estimators = Vec::new();
        for (c, &k) in ESTIMATOR_SCENES.iter().enumerate() {
            let (spec, alpha) = SCENES[k];
            let name = format!("{spec} α={alpha}");
            let scene = template(args, spec)?
                .with_law(SpinLaw::new(alpha)?)
                .with_method(Method::Tangent)
                .with_seed(args.seed + 3);
            let planner = Planner::pilot(
                &scene.clone().with_seed(args.seed + 2).with_ics(pilot_ics),
                &[Method::Tangent],
                &pilot_t,
            )?;
            let seeds = args.seed + 10..args.seed + 10 + repeat;
            let mut comparisons: Vec<EstimatorComparison> = Vec::new();
            for &target in &targets {
                let cmp = compare_estimators(
                    &scene,
                    &planner,
                    references[k],
                    target,
                    ml_pilot_ics,
                    seeds.clone(),
                )?;
                println!("{name} {cmp}");
                estimator_rows(&mut ml_csv, spec, alpha, &cmp);
                comparisons.push(cmp);
            }
            let last = comparisons.last().expect("targets");
            let prediction = last.predict(&planner, smaller);
            if let Some(p) = &prediction {
                println!(
                    "{name} {:.3}% predicted (from the {:.2}% runs): T = {}, plain {:.3e} IC-steps {:.0} s, multilevel levels {:?} {:.3e} IC-steps {:.0} s (processor time), plain/multilevel {:.2}",
                    100.0 * p.target_rel,
                    100.0 * last.target_rel,
                    p.collisions,
                    p.plain_ic_steps,
                    p.plain_cpu_s,
                    p.levels,
                    p.multilevel_ic_steps,
                    p.multilevel_cpu_s,
                    p.speedup()
                );
            }
            if let Some(e) = &last.levels {
                let v: Vec<String> = e
                    .levels
                    .iter()
                    .map(|l| format!("T={} V={:.3e}", l.collisions, l.variance))
                    .collect();
                println!(
                    "{name} level variances: {}; V_l ∝ T_l^-β, β = {:.2}",
                    v.join(", "),
                    variance_decay(&e.levels).unwrap_or(f64::NAN)
                );
                variances = variances.series(level_variances(&name, e).color(palette(c)));
            }
            versus = estimator_curves(versus, &name, palette(c), &comparisons);
            estimators.push(json!({"table": spec, "alpha": alpha, "reference": references[k], "comparisons": comparisons, "prediction": prediction, "variance_decay": last.levels.as_ref().and_then(|e| variance_decay(&e.levels))}));
        }
        let inverse_t = |t: f64| (t, 0.5 / t);
        variances = variances.series(
            Series::new("∝ 1/T", [inverse_t(200.0), inverse_t(5e5)])
                .line_only()
                .kind(LineKind::Dashed)
                .color(palette(7)),
        );
        let guide = |n: f64| (n, 1.0 / n.sqrt());
        let guide = Series::new("∝ 1/√N", [guide(10.0), guide(1e5)]).line_only();
        sem_n = sem_n.series(guide.kind(LineKind::Dashed).color(palette(7)));
        let grid = Grid::new(3, 2)
            .panel(wp.legend(Legend::LowerLeft))
            .panel(bias_t.legend(Legend::LowerLeft))
            .panel(sem_n.legend(Legend::LowerLeft))
            .panel(to_target.legend(Legend::UpperRight))
            .panel(versus.legend(Legend::UpperRight))
            .panel(variances.legend(Legend::LowerLeft));
        report.png(
            &format!("{NAME}.png"),
            &grid,
            args.pick((1400, 1600), (1800, 2100), (1800, 2100)),
        )?;
        report.csv(&format!("{NAME}.csv"), &csv)?;
        report.csv("multilevel.csv", &ml_csv)?;
        let doc = json!({"mode": args.mode.to_string(), "seed": args.seed, "budgets": budgets, "scenes": scenes, "estimators": estimators});
        report.json(&format!("{NAME}.json"), &doc)?;
        Ok(())
    })
}
