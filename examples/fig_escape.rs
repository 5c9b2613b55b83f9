//! Escape from the stadium with a hole against the spin parameter α: the
//! survival probability `P(t)` (Kaplan–Meier with its 95 % band, the fitted
//! exponential regime on its window, the algebraic tail where the tail
//! test finds one) for α ∈ {0, 0.4, 1}, and the escape rate `γ(α)` with
//! the α whose escape is not exponential marked as such.
//!
//! ```text
//! cargo run --release --example fig_escape -- [--quick | --paper] [--out DIR] [--seed N]
//! ```
//!
//! | mode      | α grid        | balls  | time budget | wall time (2 cores) |
//! |-----------|---------------|--------|-------------|---------------------|
//! | `--quick` | 0, 0.4, 1     | 300    | 5 000       | < 1 s               |
//! | default   | 0, 0.1, …, 1  | 4 000  | 10⁵         | about a minute      |
//! | `--paper` | 0, 0.1, …, 1  | 40 000 | 10⁶         | hours               |
//!
//! The stadium (a = 1) has a hole of arc length 0.2 centred on its right
//! cap; balls start from the paper's sampler; a ball still inside at the
//! time budget is censored. Writes `escape_survival.png` (log–log and
//! log–lin panels), `escape_rate.png` (γ and the tail exponent β against
//! α), `escape.csv` (one row per α) and `escape_survival.csv` (the curves).

use std::f64::consts::PI;
use std::process::ExitCode;

use spinball::analysis::escape::KacPrediction;
use spinball::analysis::open::{Budget, OpenEnsemble};
use spinball::prelude::*;
use spinball_figures::{
    Csv, ESCAPE_COLUMNS, EscapeFit, SURVIVAL_COLUMNS, escape_rate_panel, escape_row, run_figure,
    survival_panel, survival_rows, tail_exponent_panel,
};
use spinball_plot::{Grid, palette};

const NAME: &str = "fig_escape";
const ABOUT: &str = "Survival P(t) and escape rate γ(α) of the stadium with a hole on its cap.";
/// The α of the survival panels.
const SHOWN: [f64; 3] = [0.0, 0.4, 1.0];
/// Arc length of the hole.
const HOLE: f64 = 0.2;

fn main() -> ExitCode {
    run_figure(NAME, ABOUT, |args, report| {
        let alphas: Vec<f64> = args.pick(
            SHOWN.to_vec(),
            (0..=10).map(|k| f64::from(k) / 10.0).collect(),
            (0..=10).map(|k| f64::from(k) / 10.0).collect(),
        );
        let balls: u64 = args.pick(300, 4_000, 40_000);
        let budget = Budget::time(args.pick(5e3, 1e5, 1e6));
        println!(
            "stadium a = 1, hole {HOLE} centred on the right cap, {balls} balls (paper sampler, seed {}), time budget {}",
            args.seed, budget.time
        );
        let mut fits = Vec::new();
        let (mut rows, mut curves) = (Csv::new(&ESCAPE_COLUMNS), Csv::new(&SURVIVAL_COLUMNS));
        for &alpha in &alphas {
            let table = SegmentTable::stadium_with_hole(1.0, 2.0 + PI / 2.0, HOLE)?;
            let kac = KacPrediction::for_table(&table, HOLE, alpha)?;
            let records = OpenEnsemble::new(Billiard::new(table, SpinLaw::new(alpha)?))
                .with_seed(args.seed)
                .with_indices(0..balls)
                .with_threads(args.threads)
                .escape_times(budget)?;
            let (times, censored): (Vec<f64>, Vec<bool>) =
                records.iter().map(|r| (r.time, r.censored)).unzip();
            let fit = EscapeFit::new(alpha, &times, &censored, &kac)?;
            let rate = fit.rate.map_or_else(
                || "no rate (too few escapes)".to_string(),
                |r| r.to_string(),
            );
            let law = fit.law.map_or_else(|| "-".to_string(), |l| l.to_string());
            let tail = fit
                .tail
                .map_or_else(|| "no tail fit".to_string(), |t| t.to_string());
            println!(
                "  α = {alpha}: {} censored; {rate}; {law}\n    tail: {tail}",
                fit.survival.censored()
            );
            escape_row(&mut rows, &fit);
            survival_rows(&mut curves, &fit);
            fits.push(fit);
        }
        let mut panels = Grid::new(2, SHOWN.len()).title(format!(
            "Stadium a = 1 with a hole of {HOLE} on its cap: survival of {balls} balls (95 % bands)"
        ));
        for log_t in [true, false] {
            for (k, alpha) in SHOWN.into_iter().enumerate() {
                let fit = fits.iter().find(|f| f.alpha == alpha).expect("shown α run");
                let title = format!(
                    "α = {alpha}{}: {} censored",
                    if log_t { ", log–log" } else { ", log–lin" },
                    fit.survival.censored()
                );
                panels.push(survival_panel(&title, fit, log_t, palette([0, 2, 3][k])));
            }
        }
        report.png("escape_survival.png", &panels, (2200, 1300))?;
        let mut rates = Grid::new(1, 2).title(format!(
            "Escape from the stadium with a hole: default windows, {balls} balls"
        ));
        rates.push(escape_rate_panel(
            "escape rate γ ± SE on the default window",
            &fits,
        ));
        if let Some(beta) = tail_exponent_panel("algebraic tail P ∝ t^−β", &fits) {
            rates.push(beta);
        }
        report.png("escape_rate.png", &rates, (2000, 800))?;
        report.csv("escape.csv", &rows)?;
        report.csv("escape_survival.csv", &curves)?;
        Ok(())
    })
}
