//! Error against run time: work–precision sets, error budgets and plans for
//! a target total error (docs/ACCURACY.md is the report built from it).
//!
//! ```text
//! cargo run --release --example work_precision -- [--quick | --paper] [--out DIR]
//!     [--threads N] [--seed S]
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
//! Writes into `--out` (default `out/work_precision`): `work_precision.png`
//! (error against wall time; bias against T; SEM against N; planned time to
//! a target), `work_precision.csv` (one row per point) and
//! `work_precision.json` (references, points, pilots, plans, the paper's
//! sizes placed on the chart).

use std::process::ExitCode;

use serde_json::json;
use spinball_analysis::{Budget, Engine, Method, Planner, Reference, work_precision};
use spinball_core::SpinLaw;
use spinball_plot::{
    Csv, Grid, Legend, LineKind, LinePlot, Series, optional, palette, run_figure, template,
};

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

fn label(method: Method, engine: Engine) -> String {
    match method {
        Method::FiniteDifference { delta0 } => format!("FD δ0={delta0:e}, {}", engine.name()),
        Method::Tangent => format!("tangent, {}", engine.name()),
    }
}

fn main() -> ExitCode {
    run_figure(NAME, ABOUT, |args, report| {
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
        let ref_ics: u64 = args.pick(256, 16_000, 100_000);
        let ref_t = args.pick(
            vec![500, 1_000, 2_000, 4_000],
            vec![2_500, 5_000, 10_000, 20_000, 40_000],
            vec![10_000, 20_000, 50_000, 100_000],
        );
        let pilot_ics: u64 = args.pick(32, 256, 1_000);
        let pilot_t = args.pick(
            vec![250, 500, 1_000, 2_000],
            vec![1_000, 2_000, 4_000, 8_000],
            vec![2_500, 5_000, 10_000, 20_000],
        );
        let all_methods: Vec<Method> = DELTAS
            .iter()
            .map(|&d| Method::FiniteDifference { delta0: d })
            .chain([Method::Tangent])
            .collect();
        let mut csv = Csv::new(&[
            "table",
            "alpha",
            "method",
            "delta0",
            "engine",
            "ics",
            "collisions",
            "wall_time_s",
            "ns_per_step",
            "mean",
            "sem",
            "error",
            "error_sem",
            "rel_error",
        ]);
        let (mut wp, mut bias_t, mut sem_n, mut to_target) = (
            LinePlot::with_axes(
                "Stadium a = 1, α = 0.5: error against wall time",
                "wall time (s)",
                "√(Δ² + SEM²) / λ_ref",
            )
            .log_x(true)
            .log_y(true),
            LinePlot::with_axes(
                "Finite-time bias |λ_T − λ_ref| / λ_ref (tangent)",
                "T (collisions)",
                "relative bias",
            )
            .log_x(true)
            .log_y(true),
            LinePlot::with_axes(
                "Statistical error SEM / λ_ref (tangent, lanes)",
                "N (initial conditions)",
                "relative SEM",
            )
            .log_x(true)
            .log_y(true),
            LinePlot::with_axes(
                "Stadium a = 1, α = 0.5: planned wall time to a total error",
                "target relative total error",
                "predicted wall time (s)",
            )
            .log_x(true)
            .log_y(true),
        );
        let mut scenes = Vec::new();
        for (k, &(spec, alpha)) in SCENES.iter().enumerate() {
            let scene = template(args, spec)?.with_law(SpinLaw::new(alpha)?);
            let name = format!("{spec} α={alpha}");
            let reference = Reference::measure(
                &scene.clone().with_seed(args.seed + 1).with_ics(ref_ics),
                &ref_t,
            )?;
            let (lam, regime) = (reference.value, reference.bias.regime);
            println!(
                "{name}: reference λ = {:.6} ± {:.1e} ({}, {:.2} s)",
                lam.value,
                lam.sem,
                regime.name(),
                reference.wall_time_s
            );
            let (methods, engines) = if k == 0 {
                (all_methods.clone(), vec![Engine::Lanes, Engine::Scalar])
            } else {
                (
                    vec![Method::default(), Method::Tangent],
                    vec![Engine::Lanes],
                )
            };
            let points = work_precision(&scene, &reference, &methods, &engines, &budgets)?;
            for p in &points {
                let d0 = optional(p.method.delta0());
                csv.row(&[
                    &spec,
                    &alpha,
                    &p.method.name(),
                    &d0,
                    &p.engine.name(),
                    &p.budget.ics,
                    &p.budget.collisions,
                    &p.wall_time_s,
                    &p.ns_per_step,
                    &p.estimate.value,
                    &p.estimate.sem,
                    &p.error.value,
                    &p.error.sem,
                    &p.rel_error,
                ]);
            }
            let rel = |m: f64| m / lam.value.abs();
            let color = palette(k);
            let columns = reference.bias.checkpoints.iter().zip(&reference.bias.means);
            bias_t = bias_t.series(
                Series::new(
                    name.clone(),
                    columns.map(|(&t, m)| (t as f64, rel((m.value - lam.value).abs()))),
                )
                .color(color),
            );
            let tangent = points
                .iter()
                .filter(|p| p.method == Method::Tangent && p.engine == Engine::Lanes);
            sem_n = sem_n.series(
                Series::new(
                    name.clone(),
                    tangent.map(|p| (p.budget.ics as f64, rel(p.estimate.sem))),
                )
                .color(color),
            );
            let pilot_scene = scene.clone().with_seed(args.seed + 2).with_ics(pilot_ics);
            let planner = Planner::pilot(&pilot_scene, &methods, &pilot_t)?;
            let mut plans = Vec::new();
            for target in TARGETS {
                for plan in planner.plans(target)? {
                    match plan {
                        Ok(p) => {
                            println!(
                                "  {:>6}% with {:<22}: {:>8} ICs x {:>8} collisions, predicted {:.3} s",
                                100.0 * target,
                                label(p.method, p.engine),
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
            // The paper's sizes on the chart: 10⁵ × 10⁵ and the 10⁶-IC run at 5·10⁴.
            let paper: Vec<_> = planner.pilots.iter().map(|p| {
                let at = |n: f64, t: f64| json!({"ics": n, "collisions": t, "predicted_rel_error": p.predicted_error(n, t) / lam.value.abs(), "predicted_wall_s": n * t * p.seconds_per_step});
                let sizes = json!({"method": p.method, "engine": p.engine, "paper_1e5x1e5": at(1e5, 1e5), "campaign_1e6x5e4": at(1e6, 5e4)});
                println!("  paper's sizes with {}: {sizes}", label(p.method, p.engine));
                sizes
            }).collect();
            if k == 0 {
                for (i, (&m, &e)) in methods
                    .iter()
                    .flat_map(|m| engines.iter().map(move |e| (m, e)))
                    .enumerate()
                {
                    let curve = points
                        .iter()
                        .filter(|p| p.method == m && p.engine == e)
                        .map(|p| (p.wall_time_s, p.rel_error));
                    let kind = if e == Engine::Scalar {
                        LineKind::Dashed
                    } else {
                        LineKind::Solid
                    };
                    wp = wp.series(
                        Series::new(label(m, e), curve)
                            .kind(kind)
                            .color(palette(i / 2)),
                    );
                }
                for (i, pilot) in planner.pilots.iter().enumerate() {
                    let curve = TARGETS.iter().filter_map(|&t| {
                        planner
                            .plans(t)
                            .ok()?
                            .into_iter()
                            .nth(i)?
                            .ok()
                            .map(|p| (t, p.predicted_wall_s))
                    });
                    to_target = to_target.series(
                        Series::new(label(pilot.method, pilot.engine), curve).color(palette(i)),
                    );
                }
            }
            scenes.push(json!({"table": spec, "alpha": alpha, "reference": reference, "points": points, "pilots": planner.pilots, "plans": plans, "paper_sizes": paper}));
        }
        let guide = |n: f64| (n, 1.0 / n.sqrt());
        sem_n = sem_n.series(
            Series::new("∝ 1/√N", [guide(10.0), guide(1e5)])
                .line_only()
                .kind(LineKind::Dashed)
                .color(palette(7)),
        );
        let grid = Grid::new(2, 2)
            .panel(wp.legend(Legend::LowerLeft))
            .panel(bias_t.legend(Legend::LowerLeft))
            .panel(sem_n.legend(Legend::LowerLeft))
            .panel(to_target.legend(Legend::UpperRight));
        report.png(
            &format!("{NAME}.png"),
            &grid,
            args.pick((1400, 1100), (1800, 1400), (1800, 1400)),
        )?;
        report.csv(&format!("{NAME}.csv"), &csv)?;
        report.json(&format!("{NAME}.json"), &json!({"mode": args.mode.to_string(), "seed": args.seed, "budgets": budgets, "scenes": scenes}))?;
        Ok(())
    })
}
