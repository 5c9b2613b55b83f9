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
//! means, `spinball_analysis::precision::dhf_product`), with the constant DH predicts
//! (the α = 0 value) dashed. Right: the measured `λ(α)/λ(0)` against the DH
//! prediction `f_ch(0)/f_ch(α)`.
//!
//! Writes `dh_scaling.png`, `dh_scaling.csv` and `dh_scaling.json`.

use std::process::ExitCode;

use serde_json::json;
use spinball_analysis::estimators::CHAOS_THRESHOLD;
use spinball_analysis::precision::{Measurement, dhf_product, normalised};
use spinball_analysis::run::LyapunovEstimate;
use spinball_figures::{
    ALPHA_LABEL, Job, Plan, measured, run_figure, run_jobs, template, unit_grid, write_curves,
};
use spinball_plot::{Grid, LineKind, LinePlot, Series, palette};

const NAME: &str = "fig_dh_scaling";
const ABOUT: &str = "Datseris–Hupe–Fleischmann test: λ·f_ch vs α for the stadium and Sinai tables (paper appendix, Fig. dh_scaling).";

const TABLES: [(&str, &str); 2] = [
    ("stadium:a=1", "stadium a = 1"),
    ("sinai:L=2,R=1", "Sinai L = 2, R = 1"),
];

fn main() -> ExitCode {
    run_figure(NAME, ABOUT, |args, report| {
        let alphas = args.pick(vec![0.0, 0.5, 1.0], unit_grid(11), unit_grid(21));
        let plan = args.pick(
            Plan::fixed(64, 2_000),
            Plan::until(0.01, 200, 1_000, 20_000, 10_000),
            Plan::fixed(100_000, 50_000),
        );
        println!("{NAME} ({} mode): {plan}", args.mode);
        let mut jobs = Vec::new();
        for (spec, label) in TABLES {
            jobs.push(Job::new(label, &plan, template(args, spec)?, &alphas)?);
        }
        let curves = run_jobs(jobs)?;

        let title = "DH test: λ · f_ch (constant if λ ∝ 1/f_ch)";
        let y = "λ · f_ch (per unit time)";
        let mut product = LinePlot::with_axes(title, ALPHA_LABEL, y).y_range(0.0, 0.6);
        let title = "λ(α)/λ(0): measured vs DH prediction f_ch(0)/f_ch(α)";
        let mut ratio = LinePlot::with_axes(title, ALPHA_LABEL, "ratio to α = 0").y_range(0.0, 1.8);
        let mut summary = Vec::new();
        for (i, c) in curves.iter().enumerate() {
            let (color, label) = (palette(i), &c.label);
            let f = |e: &LyapunovEstimate| {
                Measurement::new(e.chaotic_fraction(), e.chaotic_fraction_sem())
            };
            let f0 = f(&c.estimates[0]);
            let dhf = c.points(dhf_product);
            let lambda_ratio: Vec<_> = c
                .alphas()
                .into_iter()
                .zip(normalised(&c.estimates))
                .collect();
            let prediction = c.points(|e| f0.ratio(f(e)));
            let (first, last) = (dhf[0].1, dhf[dhf.len() - 1].1);
            let (a, b) = (first.value, last.value);
            println!(
                "  {label}: lambda*f_ch falls from {a:.4} to {b:.4}, a factor {:.2}",
                a / b
            );
            let constant = c.alphas().into_iter().map(|x| (x, a));
            let constant = Series::new(format!("DH: λ(0)·f_ch(0), {label}"), constant).line_only();
            product = product
                .series(measured(format!("{label} ± SEM"), dhf.clone()).color(color))
                .series(constant.kind(LineKind::Dashed).color(color));
            let measured_label = format!("{label}: measured λ(α)/λ(0)");
            let dh = measured(format!("{label}: DH f_ch(0)/f_ch(α)"), prediction.clone());
            ratio = ratio
                .series(measured(measured_label, lambda_ratio.clone()).color(color))
                .series(dh.kind(LineKind::Dashed).color(color));
            summary.push(json!({
                "label": c.label, "dhf_product": dhf, "dhf_ratio_first_to_last": first.ratio(last),
                "lambda_ratio": lambda_ratio, "dh_prediction": prediction,
            }));
        }
        let grid = Grid::new(1, 2).panel(product).panel(ratio);
        report.png("dh_scaling.png", &grid, (1500, 640))?;
        let extra = json!({"threshold": CHAOS_THRESHOLD, "dh": summary});
        write_curves(report, "dh_scaling", &curves, &extra)?;
        Ok(())
    })
}
