//! The paper's Datseris–Hupe–Fleischmann test: if `λ ∝ 1/f_ch` (DH scaling),
//! the product `λ · f_ch` is the same at every α. Stadium (a = 1) and Sinai
//! (L = 2, R = 1).
//!
//! ```text
//! cargo run --release --example fig_dh_scaling -- [--quick | --paper] [--out DIR]
//!     [--threads N] [--seed S]
//! ```
//!
//! | mode      | α grid              | ensemble per α                                        |
//! |-----------|---------------------|-------------------------------------------------------|
//! | `--quick` | 0, 0.5, 1           | 64 ICs × 2000 collisions                              |
//! | default   | 0, 0.1, …, 1 (11)   | batches of 200 until SEM ≤ 1% of λ (1000..20000) × 10⁴ |
//! | `--paper` | 0, 0.05, …, 1 (21)  | 10⁵ ICs × 5·10⁴ collisions                            |
//!
//! Left: `λ · f_ch` ± SEM (error propagated with the covariance of the two
//! means, `spinball_analysis::dhf_product`), with the constant DH predicts
//! (the α = 0 value) dashed. Right: the measured `λ(α)/λ(0)` against the DH
//! prediction `f_ch(0)/f_ch(α)`.
//!
//! Writes `dh_scaling.png`, `dh_scaling.csv` and `dh_scaling.json`.

#[allow(dead_code)]
mod sweep_support;

use std::process::ExitCode;
use std::time::Instant;

use serde_json::json;
use spinball_analysis::{Measurement, dhf_product, normalised};
use spinball_plot::{Grid, Legend, LineKind, LinePlot, Plot, Series, palette};
use sweep_support::{
    ALPHA_LABEL, BoxError, Cli, Job, Plan, main_with, report_done, run_jobs, template, unit_grid,
    write_results,
};

const NAME: &str = "fig_dh_scaling";
const ABOUT: &str = "Datseris–Hupe–Fleischmann test: λ·f_ch vs α for the stadium and Sinai tables (paper appendix, Fig. dh_scaling).";

const TABLES: [(&str, &str); 2] = [
    ("stadium:a=1", "stadium a = 1"),
    ("sinai:L=2,R=1", "Sinai L = 2, R = 1"),
];

fn main() -> ExitCode {
    let cli = Cli::parse(NAME, ABOUT);
    main_with(NAME, || run(&cli))
}

fn run(cli: &Cli) -> Result<(), BoxError> {
    let start = Instant::now();
    let alphas = cli.pick(vec![0.0, 0.5, 1.0], unit_grid(11), unit_grid(21));
    let plan = cli.pick(
        Plan::fixed(64, 2_000),
        Plan::until(0.01, 200, 1_000, 20_000, 10_000),
        Plan::fixed(100_000, 50_000),
    );
    println!("{NAME} ({} mode): {}", cli.mode(), plan.describe());
    let jobs = TABLES
        .iter()
        .map(|(spec, label)| {
            Ok(Job {
                label: label.to_string(),
                sweep: plan.sweep(template(cli, spec)?, &alphas)?,
            })
        })
        .collect::<Result<Vec<_>, BoxError>>()?;
    let curves = run_jobs(cli, jobs)?;

    let mut product = LinePlot::new()
        .title("DH test: λ · f_ch (constant if λ ∝ 1/f_ch)")
        .x_label(ALPHA_LABEL)
        .y_label("λ · f_ch (per unit time)")
        .y_range(0.0, 0.6)
        .legend(Legend::UpperRight);
    let mut ratio = LinePlot::new()
        .title("λ(α)/λ(0): measured vs DH prediction f_ch(0)/f_ch(α)")
        .x_label(ALPHA_LABEL)
        .y_label("ratio to α = 0")
        .y_range(0.0, 1.8)
        .legend(Legend::UpperRight);
    let mut summary = Vec::new();
    println!("\n  table                alpha   lambda*f_ch         lambda/lambda0   f0/f (DH)");
    for (i, c) in curves.iter().enumerate() {
        let color = palette(i);
        let dhf: Vec<Measurement> = c.estimates.iter().map(dhf_product).collect();
        let measured = normalised(&c.estimates);
        let f0 = Measurement::new(
            c.estimates[0].chaotic_fraction,
            c.estimates[0].chaotic_fraction_sem,
        );
        let predicted: Vec<Measurement> = c
            .estimates
            .iter()
            .map(|e| f0.ratio(Measurement::new(e.chaotic_fraction, e.chaotic_fraction_sem)))
            .collect();
        for (((e, p), m), d) in c.estimates.iter().zip(&dhf).zip(&measured).zip(&predicted) {
            println!(
                "  {:<20} {:>5.3}   {:.4} ± {:.4}    {:.4} ± {:.4}   {:.4}",
                c.label, e.alpha, p.value, p.sem, m.value, m.sem, d.value
            );
        }
        let alphas = c.alphas();
        product = product
            .series(
                Series::new(
                    format!("{} ± SEM", c.label),
                    alphas.iter().zip(&dhf).map(|(&a, p)| (a, p.value)),
                )
                .errors(dhf.iter().map(|p| p.sem))
                .color(color),
            )
            .series(
                Series::new(
                    format!("DH: λ(0)·f_ch(0), {}", c.label),
                    alphas.iter().map(|&a| (a, dhf[0].value)),
                )
                .line_only()
                .kind(LineKind::Dashed)
                .color(color),
            );
        ratio = ratio
            .series(
                Series::new(
                    format!("{}: measured λ(α)/λ(0)", c.label),
                    alphas.iter().zip(&measured).map(|(&a, m)| (a, m.value)),
                )
                .errors(measured.iter().map(|m| m.sem))
                .color(color),
            )
            .series(
                Series::new(
                    format!("{}: DH f_ch(0)/f_ch(α)", c.label),
                    alphas.iter().zip(&predicted).map(|(&a, m)| (a, m.value)),
                )
                .kind(LineKind::Dashed)
                .color(color),
            );
        let last = dhf.last().expect("a point");
        summary.push(json!({
            "label": c.label,
            "dhf_alpha0": dhf[0],
            "dhf_alpha1": last,
            "dhf_ratio_0_to_1": dhf[0].ratio(*last),
            "points": alphas.iter().zip(&dhf).zip(&measured).zip(&predicted).map(|(((a, p), m), d)| json!({
                "alpha": a, "dhf_product": p, "lambda_ratio": m, "dh_prediction": d,
            })).collect::<Vec<_>>(),
        }));
        println!(
            "  {}: lambda*f_ch falls from {:.4} to {:.4}, a factor {:.2}",
            c.label,
            dhf[0].value,
            last.value,
            dhf[0].value / last.value
        );
    }
    let png = cli.output("dh_scaling.png")?;
    Grid::new(1, 2)
        .panel(product)
        .panel(ratio)
        .save_png(&png, 1500, 640)?;

    let settings = json!({
        "method": "fd",
        "sampler": "paper",
        "threshold": spinball_analysis::CHAOS_THRESHOLD,
        "alphas": alphas,
        "plan": plan.json(),
    });
    let (csv, json_path) =
        write_results(cli, "dh_scaling", &curves, settings, json!({"dh": summary}))?;
    report_done(cli, &[&csv, &json_path, &png], start);
    Ok(())
}
