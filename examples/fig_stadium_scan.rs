//! The paper's stadium-geometry figures: λ(α) for flat half-lengths
//! a ∈ {0.2, 0.5, 1, 2, 4} (unit caps), and the normalised λ(α)/λ(0).
//!
//! ```text
//! cargo run --release --example fig_stadium_scan -- [--quick | --paper] [--out DIR]
//!     [--threads N] [--seed S]
//! ```
//!
//! | mode      | α grid              | ensemble per (a, α)                                   | curved share   |
//! |-----------|---------------------|-------------------------------------------------------|----------------|
//! | `--quick` | 0, 0.5, 1           | 48 ICs × 2000 collisions                              | 8 × 1000       |
//! | default   | 0, 0.1, …, 1 (11)   | batches of 200 until SEM ≤ 2% of λ (400..3000) × 10⁴  | 64 × 10⁴       |
//! | `--paper` | 0, 0.05, …, 1 (21)  | 10⁴ ICs × 5·10⁴ collisions (the paper's)              | 1000 × 10⁴     |
//!
//! The legend gives each table's share of collisions on the curved caps
//! (range over α, from `WallStatistics`); the α = 0 theory is the caps'
//! share of the perimeter, 2π/(4a + 2π). Errors of λ(α)/λ(0) combine both
//! SEMs as if independent (the runs share initial positions and directions,
//! so this overstates them slightly).
//!
//! Writes `stadium_scan.png`, `stadium_scan.csv`, `stadium_scan.json` and
//! `stadium_scan_curved.csv`.

use std::process::ExitCode;

use serde_json::json;
use spinball_analysis::precision::normalised;
use spinball_figures::{
    ALPHA_LABEL, LAMBDA_LABEL, Plan, measured, run_figure, run_scan, unit_grid, write_curves,
    write_shares,
};
use spinball_plot::{Grid, Legend, LinePlot, palette};

const NAME: &str = "fig_stadium_scan";
const ABOUT: &str = "λ(α) for stadiums a = 0.2, 0.5, 1, 2, 4 and the normalised λ(α)/λ(0), with the curved-collision share (paper Figs. geometry and collapse).";
const A: [f64; 5] = [0.2, 0.5, 1.0, 2.0, 4.0];

fn main() -> ExitCode {
    run_figure(NAME, ABOUT, |args, report| {
        let alphas = args.pick(vec![0.0, 0.5, 1.0], unit_grid(11), unit_grid(21));
        let plan = args.pick(
            Plan::fixed(48, 2_000),
            Plan::until(0.02, 200, 400, 3_000, 10_000),
            Plan::fixed(10_000, 50_000),
        );
        let share_plan = args.pick((8, 1_000), (64, 10_000), (1_000, 10_000));
        println!("{NAME} ({} mode): {plan}", args.mode);
        let tables: Vec<(String, String)> = A
            .iter()
            .map(|a| (format!("stadium:a={a}"), format!("a = {a}")))
            .collect();
        let scan = run_scan(args, &tables, &alphas, &plan, share_plan)?;

        let mut lambda = LinePlot::new()
            .title("Stadium λ(α) for flat half-length a (mean ± SEM)")
            .x_label(ALPHA_LABEL)
            .y_label(LAMBDA_LABEL)
            .legend(Legend::UpperRight);
        let mut ratio = LinePlot::new()
            .title("Normalised λ(α)/λ(0)")
            .x_label(ALPHA_LABEL)
            .y_label("λ(α) / λ(0)")
            .legend(Legend::UpperRight);
        let mut summary = Vec::new();
        println!();
        for (i, c) in scan.curves.iter().enumerate() {
            let n: Vec<_> = c
                .alphas()
                .into_iter()
                .zip(normalised(&c.estimates))
                .collect();
            lambda = lambda.series(c.lambda_series().color(palette(i)));
            ratio = ratio.series(measured(c.label.clone(), n.clone()).color(palette(i)));
            let (s, last) = (c.summary(), n[n.len() - 1].1);
            println!(
                "  {s}; lambda(1)/lambda(0) = {:.3} ± {:.3}",
                last.value, last.sem
            );
            summary
                .push(json!({"summary": s, "normalised": n, "curved_share": scan.share_rows(i)}));
        }
        report.png(
            "stadium_scan.png",
            &Grid::new(1, 2).panel(lambda).panel(ratio),
            (1500, 640),
        )?;
        let extra = json!({"curved_share_plan": {"ics": share_plan.0, "collisions": share_plan.1}, "scan": summary});
        write_curves(report, "stadium_scan", &scan.curves, &extra)?;
        write_shares(report, "stadium_scan", &scan)?;
        Ok(())
    })
}
