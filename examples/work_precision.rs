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
use spinball_analysis::estimators::Method;
use spinball_analysis::precision::{Budget, Planner, Reference, work_precision};
use spinball_analysis::run::Engine;
use spinball_core::SpinLaw;
use spinball_figures::{
    Csv, WORK_COLUMNS, bias_vs_t, error_vs_time, method_label, run_figure, sem_vs_n, template,
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

fn log_plot(title: &str, x: &str, y: &str) -> LinePlot {
    LinePlot::with_axes(title, x, y).log_x(true).log_y(true)
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
        for (k, &(spec, alpha)) in SCENES.iter().enumerate() {
            let scene = template(args, spec)?.with_law(SpinLaw::new(alpha)?);
            let name = format!("{spec} α={alpha}");
            let reference = Reference::measure(
                &scene.clone().with_seed(args.seed + 1).with_ics(ref_ics),
                &ref_t,
            )?;
            let lam = reference.value;
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
        let guide = |n: f64| (n, 1.0 / n.sqrt());
        let guide = Series::new("∝ 1/√N", [guide(10.0), guide(1e5)]).line_only();
        sem_n = sem_n.series(guide.kind(LineKind::Dashed).color(palette(7)));
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
        let doc = json!({"mode": args.mode.to_string(), "seed": args.seed, "budgets": budgets, "scenes": scenes});
        report.json(&format!("{NAME}.json"), &doc)?;
        Ok(())
    })
}
