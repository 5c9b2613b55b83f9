//! The paper's chaotic-fraction figure: the share of initial conditions with
//! FTLE > 0.01 against α for the stadium (a = 1) and the Sinai table
//! (L = 2, R = 1), with the band spanned by thresholds 0.001–0.05 shaded.
//!
//! ```text
//! cargo run --release --example fig_chaotic_fraction -- [--quick | --paper] [--out DIR]
//!     [--threads N] [--seed S]
//! ```
//!
//! | mode      | α grid              | ensemble per α                     |
//! |-----------|---------------------|------------------------------------|
//! | `--quick` | 0, 0.5, 1           | 64 ICs × 2000 collisions           |
//! | default   | 0, 0.05, …, 1 (21)  | 2000 ICs × 5·10⁴ collisions        |
//! | `--paper` | 50 values in [0, 1] | 10⁵ ICs × 5·10⁴ collisions         |
//!
//! Error bars are the binomial standard error of the fraction. The right
//! panel shows the width of the threshold band in percentage points (the
//! paper: "less than 1 percentage point"). The default runs the paper's
//! trajectory length (5·10⁴ collisions) because the band depends on it:
//! a regular trajectory's FTLE decays only like `ln t / t`, and sticky
//! chaotic ones take long to leave the band. About 4·10⁹ collisions: ~15 s
//! on two cores with the lane kernels, a few minutes on the scalar path.
//!
//! Writes `chaotic_fraction.png`, `chaotic_fraction.csv` (every field of
//! `SweepRow`, including `chaotic_fraction_band_min/max`) and
//! `chaotic_fraction.json`.

#[allow(dead_code)]
mod sweep_support;

use std::process::ExitCode;
use std::time::Instant;

use serde_json::json;
use spinball_analysis::{THRESHOLD_BAND, linspace};
use spinball_plot::{Grid, Legend, LinePlot, Plot, Series, palette};
use sweep_support::{
    ALPHA_LABEL, BoxError, Cli, Job, Plan, main_with, paper_markers, report_done, run_jobs,
    template, unit_grid, write_results,
};

const NAME: &str = "fig_chaotic_fraction";
const ABOUT: &str = "Chaotic fraction (FTLE > 0.01) vs α for the stadium and Sinai tables, with the 0.001–0.05 threshold band (paper Fig. chaotic_fraction).";

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
    let alphas = cli.pick(vec![0.0, 0.5, 1.0], unit_grid(21), linspace(0.0, 1.0, 50));
    let plan = cli.pick(
        Plan::fixed(64, 2_000),
        Plan::fixed(2_000, 50_000),
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

    let pct = 100.0;
    let mut fraction = LinePlot::new()
        .title("Chaotic fraction (FTLE > 0.01; shaded: thresholds 0.001–0.05)")
        .x_label(ALPHA_LABEL)
        .y_label("chaotic fraction f_ch (%)")
        .legend(Legend::LowerLeft);
    let mut spread = LinePlot::new()
        .title("Width of the threshold band")
        .x_label(ALPHA_LABEL)
        .y_label("max − min of f_ch over thresholds (pp)")
        .hline(1.0, "paper: < 1 percentage point")
        .legend(Legend::UpperLeft);
    println!("\n  table                alpha   f_ch(0.01)      band 0.001-0.05   width/pp");
    for (i, c) in curves.iter().enumerate() {
        let rows = c.rows()?;
        for r in &rows {
            println!(
                "  {:<20} {:>5.3}   {:>5.1} ± {:>3.1}%   {:>5.1}–{:>5.1}%   {:>5.2}",
                c.label,
                r.alpha,
                pct * r.chaotic_fraction,
                pct * r.chaotic_fraction_sem,
                pct * r.chaotic_fraction_band_min,
                pct * r.chaotic_fraction_band_max,
                pct * (r.chaotic_fraction_band_max - r.chaotic_fraction_band_min)
            );
        }
        fraction = fraction.series(
            Series::new(
                format!("{} ± SEM", c.label),
                rows.iter().map(|r| (r.alpha, pct * r.chaotic_fraction)),
            )
            .errors(rows.iter().map(|r| pct * r.chaotic_fraction_sem))
            .band(
                rows.iter().map(|r| pct * r.chaotic_fraction_band_min),
                rows.iter().map(|r| pct * r.chaotic_fraction_band_max),
            )
            .color(palette(i)),
        );
        spread = spread.series(
            Series::new(
                c.label.clone(),
                rows.iter().map(|r| {
                    (
                        r.alpha,
                        pct * (r.chaotic_fraction_band_max - r.chaotic_fraction_band_min),
                    )
                }),
            )
            .color(palette(i)),
        );
    }
    fraction = fraction
        .series(paper_markers(
            "paper: stadium ≈ 90% at α = 1",
            [(1.0, 90.0)],
            palette(6),
        ))
        .series(paper_markers(
            "paper: Sinai ≈ 87% at α = 1",
            [(1.0, 87.0)],
            palette(4),
        ));
    let png = cli.output("chaotic_fraction.png")?;
    Grid::new(1, 2)
        .panel(fraction)
        .panel(spread)
        .save_png(&png, 1500, 640)?;

    let settings = json!({
        "method": "fd",
        "sampler": "paper",
        "threshold": spinball_analysis::CHAOS_THRESHOLD,
        "threshold_band": THRESHOLD_BAND,
        "alphas": alphas,
        "plan": plan.json(),
    });
    let (csv, json_path) = write_results(cli, "chaotic_fraction", &curves, settings, json!({}))?;
    report_done(cli, &[&csv, &json_path, &png], start);
    Ok(())
}
