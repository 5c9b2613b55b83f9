//! λ(α) for the Bunimovich stadium (a = 1) with both methods: the paper's
//! finite-difference Benettin exponent and the exact tangent exponent.
//!
//! ```text
//! cargo run --release --example stadium_sweep -- [--quick | --paper] [--out DIR]
//!     [--threads N] [--seed S]
//! ```
//!
//! | mode      | α grid                    | ensemble per α                                          |
//! |-----------|---------------------------|---------------------------------------------------------|
//! | `--quick` | 0, 0.5, 1                 | 64 ICs × 2000 collisions (seconds, for CI)              |
//! | default   | 0, 0.05, 0.1, 0.2, …, 1   | batches of 200 ICs until SEM ≤ 1% of λ (1000..20000) × 10⁴ |
//! | `--paper` | 50 values in [0, 1]       | 10⁵ ICs × 5·10⁴ collisions (the paper's Fig. 2)         |
//!
//! Prints a table per method as the points finish, a progress line on
//! stderr, and writes into `--out` (default `out/stadium_sweep`):
//! - `stadium_sweep.csv`: one row per method and α (every field of
//!   `spinball_analysis::report::SweepRow`);
//! - `stadium_sweep.json`: the same points with each curve's plan, the
//!   paired difference tangent − fd per α, and each point's error budget
//!   (SEM, finite-time bias fitted on its first 256 ICs at T/8 … T, method
//!   bias, total error, stop reason; also printed as a table);
//! - `stadium_sweep.png`: λ(α) ± SEM for both methods with the paper's
//!   values, and the paired difference on the same ICs.
//!
//! Results are bitwise the same for any `--threads`.

use std::process::ExitCode;

use serde_json::json;
use spinball_analysis::diagnostics;
use spinball_analysis::estimators::Method;
use spinball_analysis::precision::{ErrorBudget, Measurement, paired_difference};
use spinball_analysis::report::BudgetRow;
use spinball_analysis::run::linspace;
use spinball_core::SpinLaw;
use spinball_figures::{
    ALPHA_LABEL, Job, LAMBDA_LABEL, Plan, measured, paper_markers, run_figure, run_jobs, template,
    write_curves,
};
use spinball_plot::{Grid, LineKind, LinePlot, Series, palette};

const NAME: &str = "stadium_sweep";
const ABOUT: &str = "λ(α) of the stadium a = 1 by finite differences (the paper's method) and exact tangent dynamics, with SEM ≤ 1% per point by default.";

fn main() -> ExitCode {
    run_figure(NAME, ABOUT, |args, report| {
        let alphas = args.pick(
            vec![0.0, 0.5, 1.0],
            vec![0.0, 0.05, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0],
            linspace(0.0, 1.0, 50),
        );
        let plan = args.pick(
            Plan::fixed(64, 2_000),
            Plan::until(0.01, 200, 1_000, 20_000, 10_000),
            Plan::fixed(100_000, 50_000),
        );
        println!("{NAME} ({} mode): {plan}", args.mode);
        let stadium = template(args, "stadium:a=1")?;
        let mut jobs = Vec::new();
        for m in [Method::default(), Method::Tangent] {
            let label = format!("stadium a = 1, {}", m.name());
            jobs.push(Job::new(
                label,
                &plan,
                stadium.clone().with_method(m),
                &alphas,
            )?);
        }
        let curves = run_jobs(jobs)?;
        let (fd, tangent) = (&curves[0], &curves[1]);

        // Paired difference on the initial conditions both runs share, in
        // units of the SEM of λ itself: how much the method matters
        // compared with the statistical error.
        println!("\npaired difference tangent - fd (common ICs):");
        let (mut diffs, mut in_sem) = (Vec::new(), Vec::new());
        for (a, b) in fd.estimates.iter().zip(&tangent.estimates) {
            let d = paired_difference(a, b)?;
            println!(
                "  alpha {:>6.4}: {:+.2e} ± {:.2e}",
                a.alpha(),
                d.value,
                d.sem
            );
            diffs.push((a.alpha(), d));
            in_sem.push((
                a.alpha(),
                Measurement::new(d.value / a.sem(), d.sem / a.sem()),
            ));
        }
        // Each point's error budget: the SEM is one of three errors.
        let mut budgets = Vec::new();
        for (curve, m) in curves.iter().zip([Method::default(), Method::Tangent]) {
            println!(
                "\nerror budget, {}:\n{}",
                curve.label,
                BudgetRow::table_header()
            );
            for e in &curve.estimates {
                let at = stadium
                    .clone()
                    .with_method(m)
                    .with_law(SpinLaw::new(e.alpha())?);
                let row = BudgetRow::new(e, &ErrorBudget::for_estimate(&at, e, 256)?);
                println!("{}", row.table_line());
                budgets.push(row);
            }
        }
        let worst = curves
            .iter()
            .flat_map(|c| &c.estimates)
            .map(|e| e.rel_sem());
        let worst = worst.fold(0.0, f64::max);
        println!("largest SEM/lambda over all points: {:.2}%", 100.0 * worst);

        let fd_label = "finite differences (δ₀ = 1e-7) ± SEM";
        let paper = paper_markers(
            "paper (§IV, Table I)",
            diagnostics::STADIUM_LAMBDA,
            palette(6),
        );
        let lambda = LinePlot::with_axes("Stadium a = 1: λ(α)", ALPHA_LABEL, LAMBDA_LABEL)
            .series(fd.series(fd_label, Measurement::lambda))
            .series(
                tangent
                    .series("exact tangent ± SEM", Measurement::lambda)
                    .kind(LineKind::Dashed),
            )
            .series(paper);
        let ones = |y: f64| alphas.iter().map(move |_| y);
        let zero = Series::unlabelled(alphas.iter().map(|&a| (a, 0.0))).band(ones(-1.0), ones(1.0));
        let title = "Same ICs: exact tangent − finite differences";
        let difference = LinePlot::with_axes(title, ALPHA_LABEL, "(λ_tangent − λ_fd) / SEM(λ_fd)")
            .series(measured("paired difference ± its SEM", in_sem).color(palette(2)))
            .series(
                zero.band_label("±1 SEM of λ (statistical error)")
                    .line_only()
                    .color(palette(5)),
            )
            .y_range(-1.5, 1.5);
        let grid = Grid::new(1, 2).panel(lambda).panel(difference);
        report.png(&format!("{NAME}.png"), &grid, (1500, 640))?;
        let extra = json!({"paired_difference_tangent_minus_fd": diffs, "largest_rel_sem": worst, "error_budgets": budgets});
        write_curves(report, NAME, &curves, &extra)?;
        Ok(())
    })
}
