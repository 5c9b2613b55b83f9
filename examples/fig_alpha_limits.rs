//! λ(α) of the stadium and the Sinai table from α = 1e-12 to α = 1e12 on a
//! log axis (the extended law beyond α = 1), both methods, with the α = 0
//! value as a dashed line: what happens as α → 0⁺ (the jump of the paper's
//! sampler) and as α → ∞ (spin frozen, `v∥' → −v∥ − 2u`). See
//! docs/STABILITY.md.
//!
//! ```text
//! cargo run --release --example fig_alpha_limits -- [--quick | --paper] [--out DIR]
//!     [--threads N] [--seed S]
//! ```
//!
//! | mode      | α                                        | ensemble                    |
//! |-----------|------------------------------------------|-----------------------------|
//! | `--quick` | 0 and 1e-12, 1e-6, 1e-2, 1, 1e2, 1e6, 1e12 | 16 ICs × 1000 collisions  |
//! | default   | 0 and 10^k, k = −12..=12                 | 200 ICs × 10⁴ collisions    |
//! | `--paper` | 0 and 10^(k/2), k = −24..=24             | 1000 ICs × 10⁴ collisions   |
//!
//! Writes `alpha_limits.png` (one panel per table: tangent and finite
//! differences against α on a log axis, dashed lines at their α = 0 values),
//! `alpha_limits.csv` and `alpha_limits.json`.

use std::process::ExitCode;

use serde_json::json;
use spinball_analysis::estimators::Method;
use spinball_figures::{
    ALPHA_LABEL, Curve, Job, LAMBDA_LABEL, Plan, run_figure, run_jobs, template, write_curves,
};
use spinball_plot::{Grid, Legend, LinePlot, palette};

const NAME: &str = "fig_alpha_limits";
const ABOUT: &str = "λ(α) of the stadium and Sinai tables for α from 1e-12 to 1e12 (extended law), tangent and finite differences.";

const TABLES: [(&str, &str); 2] = [
    ("stadium:a=1", "stadium a = 1"),
    ("sinai:L=2,R=1", "Sinai L = 2, R = 1"),
];

/// `10^(k/per_decade)` for `k` from `-12·per_decade` to `12·per_decade`.
fn log_grid(per_decade: i32) -> Vec<f64> {
    (-12 * per_decade..=12 * per_decade)
        .map(|k| 10f64.powf(f64::from(k) / f64::from(per_decade)))
        .collect()
}

fn main() -> ExitCode {
    run_figure(NAME, ABOUT, |args, report| {
        let alphas = args.pick(
            vec![1e-12, 1e-6, 1e-2, 1.0, 1e2, 1e6, 1e12],
            log_grid(1),
            log_grid(2),
        );
        let plan = args.pick(
            Plan::fixed(16, 1_000),
            Plan::fixed(200, 10_000),
            Plan::fixed(1_000, 10_000),
        );
        println!("{NAME} ({} mode)\n  {plan}", args.mode);
        let methods = [("tangent", Method::Tangent), ("fd", Method::default())];
        let mut jobs = Vec::new();
        for (spec, label) in TABLES {
            for (name, method) in methods {
                let t = template(args, spec)?.with_method(method);
                jobs.push(Job::extended(
                    format!("{label}, {name}"),
                    &plan,
                    t.clone(),
                    &alphas,
                )?);
                jobs.push(Job::extended(
                    format!("{label}, {name}, α = 0"),
                    &plan,
                    t,
                    &[0.0],
                )?);
            }
        }
        let curves = run_jobs(jobs)?;

        let mut grid = Grid::new(1, 2);
        for (t, (_, label)) in TABLES.iter().enumerate() {
            let mut plot = LinePlot::new()
                .title(format!("{label}: λ(α), dashed at α = 0"))
                .x_label(ALPHA_LABEL)
                .y_label(LAMBDA_LABEL)
                .log_x(true)
                .legend(Legend::UpperRight);
            for m in 0..methods.len() {
                let sweep = &curves[4 * t + 2 * m];
                let at_zero = &curves[4 * t + 2 * m + 1];
                plot = plot
                    .series(sweep.lambda_series().color(palette(m)))
                    .hline(at_zero.estimates[0].mean(), "");
            }
            grid = grid.panel(plot);
        }
        report.png("alpha_limits.png", &grid, (1500, 640))?;

        let summary: Vec<_> = curves.iter().map(Curve::summary).collect();
        println!();
        for s in &summary {
            println!("{s}");
        }
        write_curves(
            report,
            "alpha_limits",
            &curves,
            &json!({"summary": summary}),
        )?;
        Ok(())
    })
}
