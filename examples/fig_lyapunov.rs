//! The paper's Fig. "lyap_sweep": λ(α) for the four tables, with SEM error
//! bars (finite-difference Benettin, δ₀ = 1e-7, paper sampler).
//!
//! ```text
//! cargo run --release --example fig_lyapunov -- [--quick | --paper] [--out DIR]
//!     [--threads N] [--seed S]
//! ```
//!
//! | mode      | stadium a = 1, Sinai L = 2 R = 1                         | circle, rectangle L = H = 1   |
//! |-----------|----------------------------------------------------------|-------------------------------|
//! | `--quick` | α ∈ {0, 0.5, 1}, 48 ICs × 2000 collisions                | α ∈ {0, 1}, 16 ICs × 2000     |
//! | default   | 21 α, batches of 200 ICs until SEM ≤ 1% of λ, × 10⁴      | 11 α, 100 ICs × 5·10⁴         |
//! | `--paper` | 50 α, 10⁵ ICs × 5·10⁴ collisions                         | the same                      |
//!
//! The integrable tables run longer trajectories by default because their
//! finite-time exponent decays only like `ln t / t`: the paper's "≲ 10⁻⁴"
//! is a statement about its run length.
//!
//! Writes `lyapunov.png` (linear λ(α) with the paper's values; the same on a
//! log axis, where the integrable tables show), `lyapunov.csv` and
//! `lyapunov.json` (with a summary of each curve: first and last point,
//! drop, smallest and largest λ).

use std::process::ExitCode;

use serde_json::json;
use spinball_analysis::diagnostics;
use spinball_analysis::run::linspace;
use spinball_figures::{
    ALPHA_LABEL, Curve, Job, LAMBDA_LABEL, Plan, paper_markers, run_figure, run_jobs, template,
    unit_grid, write_curves,
};
use spinball_plot::{Grid, Legend, LinePlot, palette};

const NAME: &str = "fig_lyapunov";
const ABOUT: &str = "λ(α) for the circle, rectangle, stadium and Sinai tables with SEM error bars (paper Fig. lyap_sweep).";

/// Table spec, legend label, and whether the table is integrable.
const TABLES: [(&str, &str, bool); 4] = [
    ("circle:R=1", "circle R = 1", true),
    ("rectangle:L=1,H=1", "rectangle L = H = 1", true),
    ("stadium:a=1", "stadium a = 1", false),
    ("sinai:L=2,R=1", "Sinai L = 2, R = 1", false),
];

fn main() -> ExitCode {
    run_figure(NAME, ABOUT, |args, report| {
        let chaotic_alphas = args.pick(vec![0.0, 0.5, 1.0], unit_grid(21), linspace(0.0, 1.0, 50));
        let integrable_alphas = args.pick(vec![0.0, 1.0], unit_grid(11), linspace(0.0, 1.0, 50));
        let chaotic = args.pick(
            Plan::fixed(48, 2_000),
            Plan::until(0.01, 200, 400, 20_000, 10_000),
            Plan::fixed(100_000, 50_000),
        );
        let integrable = args.pick(
            Plan::fixed(16, 2_000),
            Plan::fixed(100, 50_000),
            Plan::fixed(100_000, 50_000),
        );
        println!(
            "{NAME} ({} mode)\n  stadium, Sinai: {chaotic}\n  circle, rectangle: {integrable}",
            args.mode
        );
        let mut jobs = Vec::new();
        for (spec, label, regular) in TABLES {
            let (plan, alphas) = if regular {
                (&integrable, &integrable_alphas)
            } else {
                (&chaotic, &chaotic_alphas)
            };
            jobs.push(Job::new(label, plan, template(args, spec)?, alphas)?);
        }
        let curves = run_jobs(jobs)?;

        let mut linear = LinePlot::new()
            .title("λ(α), four tables (finite differences, mean ± SEM)")
            .x_label(ALPHA_LABEL)
            .y_label(LAMBDA_LABEL)
            .legend(Legend::UpperRight);
        let mut log = LinePlot::new()
            .title("Log axis (dashed: the paper's integrable bound 10⁻⁴)")
            .x_label(ALPHA_LABEL)
            .y_label(LAMBDA_LABEL)
            .log_y(true)
            .y_range(1e-7, 1.0)
            .hline(diagnostics::INTEGRABLE_LAMBDA_BOUND, "")
            .legend(Legend::Hidden);
        for (i, c) in curves.iter().enumerate() {
            linear = linear.series(c.lambda_series().color(palette(i)));
            log = log.series(c.lambda_series().color(palette(i)));
        }
        let linear = linear
            .series(paper_markers(
                "paper: stadium",
                diagnostics::STADIUM_LAMBDA,
                palette(6),
            ))
            .series(paper_markers(
                "paper: Sinai",
                diagnostics::SINAI_LAMBDA,
                palette(4),
            ));
        report.png(
            "lyapunov.png",
            &Grid::new(1, 2).panel(linear).panel(log),
            (1500, 640),
        )?;

        let summary: Vec<_> = curves.iter().map(Curve::summary).collect();
        println!();
        for s in &summary {
            println!("{s}");
        }
        write_curves(report, "lyapunov", &curves, &json!({"summary": summary}))?;
        Ok(())
    })
}
