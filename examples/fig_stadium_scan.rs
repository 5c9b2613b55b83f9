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

#[allow(dead_code)]
mod sweep_support;

use std::process::ExitCode;
use std::time::Instant;

use serde_json::json;
use spinball_analysis::normalised;
use spinball_plot::{Grid, Legend, LinePlot, Plot, Series, palette};
use sweep_support::{
    ALPHA_LABEL, BoxError, Cli, LAMBDA_LABEL, Plan, main_with, report_done, run_scan, shares_json,
    unit_grid, write_results, write_shares,
};

const NAME: &str = "fig_stadium_scan";
const ABOUT: &str = "λ(α) for stadiums a = 0.2, 0.5, 1, 2, 4 and the normalised λ(α)/λ(0), with the curved-collision share (paper Figs. geometry and collapse).";
const A: [f64; 5] = [0.2, 0.5, 1.0, 2.0, 4.0];

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
        Plan::fixed(10_000, 50_000),
    );
    let (share_ics, share_collisions) = cli.pick((8, 1_000), (64, 10_000), (1_000, 10_000));
    println!("{NAME} ({} mode): {}", cli.mode(), plan.describe());
    let tables: Vec<(String, String)> = A
        .iter()
        .map(|a| (format!("stadium:a={a}"), format!("a = {a}")))
        .collect();
    let scan = run_scan(cli, &tables, &alphas, &plan, share_ics, share_collisions)?;

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
        let n = normalised(&c.estimates);
        lambda = lambda.series(c.lambda_series().color(palette(i)));
        ratio = ratio.series(
            Series::new(
                c.label.clone(),
                c.alphas().into_iter().zip(n.iter().map(|m| m.value)),
            )
            .errors(n.iter().map(|m| m.sem))
            .color(palette(i)),
        );
        let last = n.last().expect("a point");
        println!(
            "  {}: lambda(0) = {:.4} ± {:.4}, lambda(1)/lambda(0) = {:.3} ± {:.3}",
            c.label, c.estimates[0].mean, c.estimates[0].sem, last.value, last.sem
        );
        summary.push(json!({
            "label": c.label,
            "lambda_alpha0": c.estimates[0].mean,
            "lambda_alpha0_sem": c.estimates[0].sem,
            "normalised": c.alphas().iter().zip(&n).map(|(a, m)| json!({"alpha": a, "ratio": m})).collect::<Vec<_>>(),
            "curved_share": shares_json(&scan.shares[i]),
        }));
    }
    let png = cli.output("stadium_scan.png")?;
    Grid::new(1, 2)
        .panel(lambda)
        .panel(ratio)
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
        "stadium_scan",
        &scan.curves,
        settings,
        json!({"scan": summary}),
    )?;
    let shares = write_shares(cli, "stadium_scan", &scan)?;
    report_done(cli, &[&csv, &json_path, &shares, &png], start);
    Ok(())
}
