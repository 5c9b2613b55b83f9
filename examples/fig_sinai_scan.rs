//! The paper's Sinai obstacle-radius figure: λ(α) for R ∈ {0.3, 0.5, 0.8,
//! 1.0, 1.2, 1.5} in the square of half-side L = 2, with each table's share
//! of collisions on the curved obstacle in the legend.
//!
//! ```text
//! cargo run --release --example fig_sinai_scan -- [--quick | --paper] [--out DIR]
//!     [--threads N] [--seed S]
//! ```
//!
//! | mode      | α grid              | ensemble per (R, α)                                   | curved share   |
//! |-----------|---------------------|-------------------------------------------------------|----------------|
//! | `--quick` | 0, 0.5, 1           | 48 ICs × 2000 collisions                              | 8 × 1000       |
//! | default   | 0, 0.1, …, 1 (11)   | batches of 200 until SEM ≤ 2% of λ (400..3000) × 10⁴  | 64 × 10⁴       |
//! | `--paper` | 0, 0.05, …, 1 (21)  | 500 ICs × 5·10⁴ collisions (the paper's 500 ICs)      | 1000 × 10⁴     |
//!
//! Right panel: the curved share against α (from `WallStatistics`, mean
//! over initial conditions ± SEM), the α = 0 theory 2πR/(8L + 2πR) (the
//! obstacle's share of the perimeter) as dashed lines, and the paper's
//! quoted shares as markers.
//!
//! Writes `sinai_scan.png`, `sinai_scan.csv`, `sinai_scan.json` and
//! `sinai_scan_curved.csv`.

use std::process::ExitCode;

use serde_json::json;
use spinball_analysis::diagnostics;
use spinball_analysis::precision::Measurement;
use spinball_figures::{
    ALPHA_LABEL, LAMBDA_LABEL, Plan, measured, paper_markers, run_figure, run_scan, unit_grid,
    write_curves, write_shares,
};
use spinball_plot::{Grid, Legend, LineKind, LinePlot, Series, palette};

const NAME: &str = "fig_sinai_scan";
const ABOUT: &str = "λ(α) for Sinai tables L = 2, R = 0.3 … 1.5, with the share of collisions on the obstacle (paper Fig. R_scan).";
const R: [f64; 6] = [0.3, 0.5, 0.8, 1.0, 1.2, 1.5];

fn main() -> ExitCode {
    run_figure(NAME, ABOUT, |args, report| {
        let alphas = args.pick(vec![0.0, 0.5, 1.0], unit_grid(11), unit_grid(21));
        let plan = args.pick(
            Plan::fixed(48, 2_000),
            Plan::until(0.02, 200, 400, 3_000, 10_000),
            Plan::fixed(500, 50_000),
        );
        let share_plan = args.pick((8, 1_000), (64, 10_000), (1_000, 10_000));
        println!("{NAME} ({} mode): {plan}", args.mode);
        let tables: Vec<(String, String)> = R
            .iter()
            .map(|r| (format!("sinai:L=2,R={r}"), format!("R = {r}")))
            .collect();
        let scan = run_scan(args, &tables, &alphas, &plan, share_plan)?;

        let mut lambda = LinePlot::new()
            .title("Sinai (L = 2) λ(α) for obstacle radius R (mean ± SEM)")
            .x_label(ALPHA_LABEL)
            .y_label(LAMBDA_LABEL)
            .legend(Legend::UpperRight);
        let mut share = LinePlot::new()
            .title("Curved share (dashed: perimeter share; dots at right: paper)")
            .x_label(ALPHA_LABEL)
            .y_label("curved share (%)")
            .legend(Legend::Hidden);
        let mut summary = Vec::new();
        println!();
        for (i, (c, s)) in scan.curves.iter().zip(&scan.shares).enumerate() {
            let color = palette(i);
            let pct = s.iter().map(|x| {
                (
                    x.alpha,
                    Measurement::new(100.0 * x.per_ic.value, 100.0 * x.per_ic.sem),
                )
            });
            let perimeter = s.iter().map(|x| (x.alpha, 100.0 * x.perimeter_share));
            lambda = lambda.series(c.lambda_series().color(color));
            share = share
                .series(measured(c.label.clone(), pct).color(color))
                .series(
                    Series::unlabelled(perimeter)
                        .line_only()
                        .kind(LineKind::Dashed)
                        .color(color),
                );
            // The paper's share for this radius, at the right edge.
            if let Some((_, p)) = diagnostics::SINAI_CURVED_SHARE_BY_RADIUS
                .iter()
                .find(|(r, _)| *r == R[i])
            {
                share = share.series(
                    Series::unlabelled([(1.02, 100.0 * p)])
                        .markers_only()
                        .marker_radius(7)
                        .color(color),
                );
            }
            let curve = c.summary();
            println!("  {curve}");
            summary.push(json!({"summary": curve, "curved_share": scan.share_rows(i)}));
        }
        let lambda = lambda.series(paper_markers(
            "paper λ(0): R = 0.3 ≈ 0.13, R = 1.5 ≈ 0.47",
            diagnostics::SINAI_LAMBDA0_BY_RADIUS.map(|(_, l)| (0.0, l)),
            palette(6),
        ));
        report.png(
            "sinai_scan.png",
            &Grid::new(1, 2).panel(lambda).panel(share),
            (1500, 640),
        )?;
        let extra = json!({"curved_share_plan": {"ics": share_plan.0, "collisions": share_plan.1}, "scan": summary});
        write_curves(report, "sinai_scan", &scan.curves, &extra)?;
        write_shares(report, "sinai_scan", &scan)?;
        Ok(())
    })
}
