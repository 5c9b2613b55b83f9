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
//! chaotic ones take long to leave the band.
//!
//! Writes `chaotic_fraction.png`, `chaotic_fraction.csv` (every field of
//! `SweepRow`, including `chaotic_fraction_band_min/max`) and
//! `chaotic_fraction.json`.

use std::process::ExitCode;

use serde_json::json;
use spinball_analysis::diagnostics;
use spinball_analysis::estimators::{CHAOS_THRESHOLD, THRESHOLD_BAND};
use spinball_analysis::precision::Measurement;
use spinball_analysis::run::{LyapunovEstimate, linspace};
use spinball_figures::{
    ALPHA_LABEL, Job, Plan, measured, paper_markers, run_figure, run_jobs, scaled, template,
    unit_grid, write_curves,
};
use spinball_plot::{Grid, Legend, LinePlot, Series, palette};

const NAME: &str = "fig_chaotic_fraction";
const ABOUT: &str = "Chaotic fraction (FTLE > 0.01) vs α for the stadium and Sinai tables, with the 0.001–0.05 threshold band (paper Fig. chaotic_fraction).";

/// Table spec, legend label and the paper's fraction at α = 1.
const TABLES: [(&str, &str); 2] = [
    ("stadium:a=1", "stadium a = 1"),
    ("sinai:L=2,R=1", "Sinai L = 2, R = 1"),
];
/// The paper's fractions at α = 1, in the order of `TABLES`.
const AT_ONE: [f64; 2] = [
    diagnostics::STADIUM_CHAOTIC_FRACTION_ALPHA1,
    diagnostics::SINAI_CHAOTIC_FRACTION_ALPHA1,
];
const PCT: f64 = 100.0;

fn main() -> ExitCode {
    run_figure(NAME, ABOUT, |args, report| {
        let alphas = args.pick(vec![0.0, 0.5, 1.0], unit_grid(21), linspace(0.0, 1.0, 50));
        let plan = args.pick(
            Plan::fixed(64, 2_000),
            Plan::fixed(2_000, 50_000),
            Plan::fixed(100_000, 50_000),
        );
        println!("{NAME} ({} mode): {plan}", args.mode);
        let mut jobs = Vec::new();
        for (spec, label) in TABLES {
            jobs.push(Job::new(label, &plan, template(args, spec)?, &alphas)?);
        }
        let curves = run_jobs(jobs)?;

        let title = "Chaotic fraction (FTLE > 0.01; shaded: thresholds 0.001–0.05)";
        let mut fraction = LinePlot::with_axes(title, ALPHA_LABEL, "chaotic fraction f_ch (%)")
            .legend(Legend::LowerLeft);
        let y = "max − min of f_ch over thresholds (pp)";
        let mut spread = LinePlot::with_axes("Width of the threshold band", ALPHA_LABEL, y)
            .hline(
                PCT * diagnostics::THRESHOLD_BAND_WIDTH,
                "paper: < 1 percentage point",
            )
            .legend(Legend::UpperLeft);
        println!();
        for (i, ((c, (_, name)), at_one)) in curves.iter().zip(TABLES).zip(AT_ONE).enumerate() {
            let f = |e: &LyapunovEstimate| {
                Measurement::new(e.chaotic_fraction(), e.chaotic_fraction_sem())
            };
            let (lo, hi) = (
                c.rows.iter().map(|r| PCT * r.chaotic_fraction_band_min),
                c.rows.iter().map(|r| PCT * r.chaotic_fraction_band_max),
            );
            let band =
                measured(format!("{} ± SEM", c.label), scaled(c.points(f), PCT)).band(lo, hi);
            let paper = format!("paper: {name} ≈ {:.0}% at α = 1", PCT * at_one);
            fraction = fraction
                .series(band.color(palette(i)))
                .series(paper_markers(paper, [(1.0, PCT * at_one)], palette(i)));
            let width: Vec<(f64, f64)> = c
                .rows
                .iter()
                .map(|r| {
                    (
                        r.alpha,
                        PCT * (r.chaotic_fraction_band_max - r.chaotic_fraction_band_min),
                    )
                })
                .collect();
            let (alpha, widest) = width
                .iter()
                .copied()
                .fold((0.0, 0.0), |m, w| if w.1 > m.1 { w } else { m });
            println!(
                "  {}: threshold band at most {widest:.2} pp wide (alpha = {alpha})",
                c.label
            );
            spread = spread.series(Series::new(c.label.clone(), width).color(palette(i)));
        }
        let grid = Grid::new(1, 2).panel(fraction).panel(spread);
        report.png("chaotic_fraction.png", &grid, (1500, 640))?;
        let extra = json!({"threshold": CHAOS_THRESHOLD, "threshold_band": THRESHOLD_BAND});
        write_curves(report, "chaotic_fraction", &curves, &extra)?;
        Ok(())
    })
}
