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
//! `lyapunov.json`.

#[allow(dead_code)]
mod sweep_support;

use std::process::ExitCode;
use std::time::Instant;

use serde_json::json;
use spinball_analysis::{Measurement, linspace};
use spinball_plot::{Grid, Legend, LinePlot, Plot, Series, palette};
use sweep_support::{
    ALPHA_LABEL, BoxError, Cli, Job, LAMBDA_LABEL, PAPER_SINAI, PAPER_STADIUM, Plan, report_done,
    run_jobs, template, unit_grid, write_results,
};

const NAME: &str = "fig_lyapunov";
const ABOUT: &str = "λ(α) for the circle, rectangle, stadium and Sinai tables with SEM error bars (paper Fig. lyap_sweep).";

/// Table spec and legend label.
const TABLES: [(&str, &str); 4] = [
    ("circle:R=1", "circle R = 1"),
    ("rectangle:L=1,H=1", "rectangle L = H = 1"),
    ("stadium:a=1", "stadium a = 1"),
    ("sinai:L=2,R=1", "Sinai L = 2, R = 1"),
];

fn main() -> ExitCode {
    let cli = Cli::parse(NAME, ABOUT);
    match run(&cli) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("{NAME}: {e}");
            ExitCode::FAILURE
        }
    }
}

fn run(cli: &Cli) -> Result<(), BoxError> {
    let start = Instant::now();
    let chaotic_alphas = cli.pick(vec![0.0, 0.5, 1.0], unit_grid(21), linspace(0.0, 1.0, 50));
    let integrable_alphas = cli.pick(vec![0.0, 1.0], unit_grid(11), linspace(0.0, 1.0, 50));
    let chaotic = cli.pick(
        Plan::fixed(48, 2_000),
        Plan::until(0.01, 200, 400, 20_000, 10_000),
        Plan::fixed(100_000, 50_000),
    );
    let integrable = cli.pick(
        Plan::fixed(16, 2_000),
        Plan::fixed(100, 50_000),
        Plan::fixed(100_000, 50_000),
    );
    println!(
        "{NAME} ({} mode)\n  stadium, Sinai: {}\n  circle, rectangle: {}",
        cli.mode(),
        chaotic.describe(),
        integrable.describe()
    );

    let jobs = TABLES
        .iter()
        .enumerate()
        .map(|(i, (spec, label))| {
            let (plan, alphas) = if i < 2 {
                (&integrable, &integrable_alphas)
            } else {
                (&chaotic, &chaotic_alphas)
            };
            Ok(Job {
                label: label.to_string(),
                sweep: plan.sweep(template(cli, spec)?, alphas)?,
            })
        })
        .collect::<Result<Vec<_>, BoxError>>()?;
    let curves = run_jobs(cli, jobs)?;

    let paper = |label: &str, points: [(f64, f64); 5], color| {
        Series::new(label, points)
            .markers_only()
            .marker_radius(7)
            .color(color)
    };
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
        .legend(Legend::Hidden);
    for (i, c) in curves.iter().enumerate() {
        linear = linear.series(c.lambda_series().color(palette(i)));
        log = log.series(c.lambda_series().color(palette(i)));
    }
    linear = linear
        .series(paper("paper: stadium", PAPER_STADIUM, palette(6)))
        .series(paper("paper: Sinai", PAPER_SINAI, palette(4)));
    log = log.hline(1e-4, "");
    let png = cli.output("lyapunov.png")?;
    Grid::new(1, 2)
        .panel(linear)
        .panel(log)
        .save_png(&png, 1500, 640)?;

    let settings = json!({
        "method": "fd",
        "sampler": "paper",
        "chaotic_tables": {"alphas": chaotic_alphas, "plan": chaotic.json()},
        "integrable_tables": {"alphas": integrable_alphas, "plan": integrable.json()},
    });
    let summary: Vec<_> = curves
        .iter()
        .map(|c| {
            let first = Measurement::lambda(&c.estimates[0]);
            let last = Measurement::lambda(c.estimates.last().expect("a point"));
            json!({
                "label": c.label,
                "lambda_alpha0": first,
                "lambda_alpha1": last,
                "relative_drop": 1.0 - last.value / first.value,
                "max_lambda": c.estimates.iter().map(|e| e.mean).fold(f64::MIN, f64::max),
            })
        })
        .collect();
    println!();
    for c in &curves {
        let (first, last) = (&c.estimates[0], c.estimates.last().expect("a point"));
        println!(
            "{}: lambda(0) = {:.5} ± {:.5}, lambda(1) = {:.5} ± {:.5}, drop {:.1}%",
            c.label,
            first.mean,
            first.sem,
            last.mean,
            last.sem,
            100.0 * (1.0 - last.mean / first.mean)
        );
    }
    let (csv, json_path) = write_results(
        cli,
        "lyapunov",
        &curves,
        settings,
        json!({"summary": summary}),
    )?;
    report_done(cli, &[&csv, &json_path, &png], start);
    Ok(())
}
