//! λ(α) on one table: the machine interface for scripts and other tools.
//!
//! ```text
//! cargo run --release --example sweep -- --table stadium:a=1 --alphas 0,0.5,1 \
//!     --ics 1000 --collisions 10000 --method fd --seed 1 --json sweep.json \
//!     [--sampler paper|microcanonical] [--threads T] [--extended]
//! ```
//!
//! For every α it runs an ensemble of `--ics` initial conditions (indices
//! `0..N` of seed `--seed`) for `--collisions` collisions each, prints a row
//! of a table, and (re)writes the JSON file after each point so a long sweep
//! leaves its finished points behind:
//!
//! ```json
//! {"table": "stadium:a=1", "method": "fd", "sampler": "paper", "seed": 1,
//!  "delta0": 1e-7, "threshold": 0.01, "version": "0.1.0",
//!  "points": [{"alpha": 0.5, "mean": 0.18, "sem": 0.002, "median": 0.2,
//!              "chaotic_fraction": 0.9, "n_ics": 1000, "n_collisions": 10000,
//!              "wall_time_s": 1.1, "std": 0.05, "conditional_mean": 0.2,
//!              "collision_rate": 1.2, "stop": "completed",
//!              "error_budget": {"sem": 0.002, "finite_time_bias": 1e-4,
//!                               "regime": "1/T", "method_bias": 2e-5, "total": 0.0021, ...}}]}
//! ```
//!
//! Each point's error budget (`spinball_analysis::precision::ErrorBudget::for_estimate`)
//! adds to its SEM the finite-time bias, fitted on its first 64 initial
//! conditions read at T/8, T/4, T/2 and T, and for finite differences the
//! method bias against a tangent run of those initial conditions; a second
//! table prints it with the stop reason.
//!
//! `n_collisions` is the number of collisions **per initial condition**;
//! `wall_time_s` the time spent on that point. Exponents are per unit time.
//! Results are bitwise the same for any `--threads`. The arguments are
//! `spinball_plot::cli::SweepArgs`, the document `spinball_plot::SweepDocument`.
//!
//! SPEC is `circle`, `rectangle:L=1,H=1`, `stadium:a=1` or `sinai:L=2,R=1`
//! (any values). α must lie in the physical range [0, 1] unless
//! `--extended` is given. Bad arguments (and an unwritable `--json` path)
//! print a message and exit with code 2; a failure while computing exits
//! with code 1.

use std::process::ExitCode;

use spinball_analysis::precision::ErrorBudget;
use spinball_analysis::report::BudgetRow;
use spinball_plot::SweepDocument;
use spinball_plot::cli::SweepArgs;

/// Initial conditions each point's bias estimate is fitted on.
const BIAS_ICS: u64 = 64;

fn main() -> ExitCode {
    let args = SweepArgs::parse_or_exit();
    // Fail on an unwritable path now, not after the computation.
    let mut doc = match SweepDocument::create(&args) {
        Ok(doc) => doc,
        Err(e) => {
            eprintln!("sweep: --json: {e}");
            return ExitCode::from(2);
        }
    };
    println!(
        "{} | {} | sampler {} | seed {} | {} ICs x {} collisions",
        args.table,
        args.method.name(),
        args.sampler,
        args.seed,
        args.ics,
        args.collisions
    );
    println!(
        "{:>8} {:>10} {:>9} {:>10} {:>7} {:>9}",
        "alpha", "lambda", "SEM", "median", "f_ch", "time/s"
    );
    let mut budgets = Vec::new();
    for &law in &args.laws {
        let ensemble = args.ensemble(law);
        let est = match ensemble.run() {
            Ok(est) => est,
            Err(e) => {
                eprintln!("sweep: alpha = {}: {e}", law.alpha());
                return ExitCode::FAILURE;
            }
        };
        println!(
            "{:>8} {:>10.5} {:>9.5} {:>10.5} {:>7.3} {:>9.2}",
            est.alpha, est.mean, est.sem, est.median, est.chaotic_fraction, est.wall_time_s
        );
        // The budget needs a bias fit (at least 8 collisions); a point
        // without one is still written, with the reason on stderr.
        let pushed = match ErrorBudget::for_estimate(&ensemble, &est, BIAS_ICS) {
            Ok(budget) => {
                let row = BudgetRow::new(&est, &budget);
                budgets.push(row.table_line());
                doc.push_with_budget(&est, row)
            }
            Err(e) => {
                eprintln!("sweep: alpha = {}: no error budget: {e}", law.alpha());
                doc.push(&est)
            }
        };
        if let Err(e) = pushed {
            eprintln!("sweep: {e}");
            return ExitCode::FAILURE;
        }
    }
    println!("\nerror budget (bias from the first {BIAS_ICS} ICs):");
    println!("{}", BudgetRow::table_header());
    for line in budgets {
        println!("{line}");
    }
    println!("wrote {}", doc.path().display());
    ExitCode::SUCCESS
}
