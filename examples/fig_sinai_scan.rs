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

#[allow(dead_code)]
mod sweep_support;

use std::process::ExitCode;
use std::time::Instant;

use serde_json::json;
use spinball_plot::{Grid, Legend, LineKind, LinePlot, Plot, Series, palette};
use sweep_support::{
    ALPHA_LABEL, BoxError, Cli, LAMBDA_LABEL, Plan, main_with, paper_markers, report_done,
    run_scan, shares_json, unit_grid, write_results, write_shares,
};

const NAME: &str = "fig_sinai_scan";
const ABOUT: &str = "λ(α) for Sinai tables L = 2, R = 0.3 … 1.5, with the share of collisions on the obstacle (paper Fig. R_scan).";
const R: [f64; 6] = [0.3, 0.5, 0.8, 1.0, 1.2, 1.5];
/// The paper's quoted curved shares (§VIII): R = 0.3 "~15%", R = 0.8–1.0
/// "26–29%", R = 1.5 "~50%".
const PAPER_SHARES: [(f64, f64); 4] = [(0.3, 15.0), (0.8, 26.0), (1.0, 29.0), (1.5, 50.0)];

fn main() -> ExitCode {
    let cli = Cli::parse(NAME, ABOUT);
    main_with(NAME, || run(&cli))
}

fn run(cli: &Cli) -> Result<(), BoxError> {
    let start = Instant::now();
    let alphas = cli.pick(vec![0.0, 0.5, 1.0], unit_grid(11), unit_grid(21));
    let plan = cli.pick(
        Plan::fixed(48, 2_000),
        Plan::until(0.02, 200, 400, 3_000, 10_000),
        Plan::fixed(500, 50_000),
    );
    let (share_ics, share_collisions) = cli.pick((8, 1_000), (64, 10_000), (1_000, 10_000));
    println!("{NAME} ({} mode): {}", cli.mode(), plan.describe());
    let tables: Vec<(String, String)> = R
        .iter()
        .map(|r| (format!("sinai:L=2,R={r}"), format!("R = {r}")))
        .collect();
    let scan = run_scan(cli, &tables, &alphas, &plan, share_ics, share_collisions)?;

    let mut lambda = LinePlot::new()
        .title("Sinai (L = 2) λ(α) for obstacle radius R (mean ± SEM)")
        .x_label(ALPHA_LABEL)
        .y_label(LAMBDA_LABEL)
        .legend(Legend::UpperRight);
    let mut share = LinePlot::new()
        .title("Share of collisions on the obstacle")
        .x_label(ALPHA_LABEL)
        .y_label("curved share (%)")
        .legend(Legend::Hidden);
    let mut summary = Vec::new();
    println!();
    for (i, (c, s)) in scan.curves.iter().zip(&scan.shares).enumerate() {
        let color = palette(i);
        lambda = lambda.series(c.lambda_series().color(color));
        share = share
            .series(
                Series::new(
                    c.label.clone(),
                    s.iter().map(|x| (x.alpha, 100.0 * x.per_ic.value)),
                )
                .errors(s.iter().map(|x| 100.0 * x.per_ic.sem))
                .color(color),
            )
            .series(
                Series::unlabelled(s.iter().map(|x| (x.alpha, 100.0 * x.perimeter_share)))
                    .line_only()
                    .kind(LineKind::Dashed)
                    .color(color),
            );
        let (first, last) = (&c.estimates[0], c.estimates.last().expect("a point"));
        let min = c
            .estimates
            .iter()
            .min_by(|a, b| a.mean.total_cmp(&b.mean))
            .expect("a point");
        println!(
            "  {}: lambda(0) = {:.4} ± {:.4}, min {:.4} ± {:.4} at alpha {}, lambda(1) = {:.4} ± {:.4}",
            c.label, first.mean, first.sem, min.mean, min.sem, min.alpha, last.mean, last.sem
        );
        summary.push(json!({
            "label": c.label,
            "lambda_alpha0": first.mean,
            "lambda_alpha0_sem": first.sem,
            "lambda_min": min.mean,
            "lambda_min_sem": min.sem,
            "alpha_of_min": min.alpha,
            "curved_share": shares_json(s),
        }));
    }
    lambda = lambda.series(paper_markers(
        "paper λ(0): R = 0.3 ≈ 0.13, R = 1.5 ≈ 0.47",
        [(0.0, 0.13), (0.0, 0.47)],
        palette(6),
    ));
    // The paper's shares at the right edge, coloured like their curves.
    for (r, pct) in PAPER_SHARES {
        let i = R.iter().position(|&x| x == r).unwrap_or(0);
        share = share.series(
            Series::unlabelled([(1.02, pct)])
                .markers_only()
                .marker_radius(7)
                .color(palette(i)),
        );
    }
    let share = share.title("Curved share (dashed: perimeter share; dots at right: paper)");
    let png = cli.output("sinai_scan.png")?;
    Grid::new(1, 2)
        .panel(lambda)
        .panel(share)
        .save_png(&png, 1500, 640)?;

    let settings = json!({
        "tables": tables.iter().map(|t| &t.0).collect::<Vec<_>>(),
        "method": "fd",
        "sampler": "paper",
        "alphas": alphas,
        "plan": plan.json(),
        "curved_share": {"ics": share_ics, "collisions": share_collisions},
    });
    let (csv, json_path) = write_results(
        cli,
        "sinai_scan",
        &scan.curves,
        settings,
        json!({"scan": summary}),
    )?;
    let shares = write_shares(cli, "sinai_scan", &scan)?;
    report_done(cli, &[&csv, &json_path, &shares, &png], start);
    Ok(())
}
