//! The paper's collision-rate appendix: the mean collision rate ν(α) and
//! the per-collision exponent λ/ν for the stadium (a = 1) and the Sinai
//! table (L = 2, R = 1) — with the paper's initial conditions **and** with
//! the microcanonical (Liouville) sampler, to show how the paper's
//! convention (its speed distribution jumps at α = 0⁺) shapes ν and λ near
//! α = 0.
//!
//! ```text
//! cargo run --release --example fig_collision_rate -- [--quick | --paper] [--out DIR]
//!     [--threads N] [--seed S]
//! ```
//!
//! | mode      | α grid                                          | ensemble per α                                        |
//! |-----------|-------------------------------------------------|-------------------------------------------------------|
//! | `--quick` | 0, 0.01, 0.5, 1                                 | 48 ICs × 2000 collisions                              |
//! | default   | 0, 0.001, 0.003, 0.01, 0.03, 0.05, 0.1, …, 1    | batches of 200 until SEM ≤ 2% of λ (400..4000) × 10⁴  |
//! | `--paper` | 0, 0.001, 0.003, 0.01, 0.03 and 49 values in (0, 1] | 10⁵ ICs × 10⁴ collisions (the paper's)           |
//!
//! ν and λ/ν as in `spinball_figures::CurveRates`, drawn relative to Santaló's
//! rate at α = 0, `|∂Q|/(π|Q|)`; reference lines: the mean speed of the
//! paper's initial conditions at any α > 0 (`√3/4 + π/6 ≈ 0.957`) and of the
//! invariant measure (`π/4`). Writes `collision_rate.png` (2 × 2: ν on
//! linear and log α axes, λ/ν, λ per unit time), `collision_rate.csv` and
//! `collision_rate.json`.

use std::process::ExitCode;

use serde_json::json;
use spinball_analysis::run::linspace;
use spinball_core::Sampler;
use spinball_figures::{
    Job, Plan, collision_rate_grid, run_figure, run_jobs, template, write_curves,
};

const NAME: &str = "fig_collision_rate";
const ABOUT: &str = "Collision rate ν(α) and per-collision exponent λ/ν for the stadium and Sinai tables, paper and microcanonical initial conditions (paper appendix, Fig. collision_rate).";
const TABLES: [(&str, &str); 2] = [("stadium:a=1", "stadium"), ("sinai:L=2,R=1", "Sinai")];
const SMALL: [f64; 5] = [0.0, 0.001, 0.003, 0.01, 0.03];
const COARSE: [f64; 11] = [0.05, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0];

fn main() -> ExitCode {
    run_figure(NAME, ABOUT, |args, report| {
        let fine = linspace(0.0, 1.0, 50);
        let alphas = args.pick(
            vec![0.0, 0.01, 0.5, 1.0],
            [&SMALL[..], &COARSE].concat(),
            [&SMALL[..], &fine[1..]].concat(),
        );
        let plan = args.pick(
            Plan::fixed(48, 2_000),
            Plan::until(0.02, 200, 400, 4_000, 10_000),
            Plan::fixed(100_000, 10_000),
        );
        println!("{NAME} ({} mode): {plan}", args.mode);
        let mut jobs = Vec::new();
        for (spec, name) in TABLES {
            // Solid for the paper's ICs, dashed for the microcanonical ones.
            for sampler in [Sampler::Paper, Sampler::Microcanonical] {
                let t = template(args, spec)?.with_sampler(sampler);
                let label = format!("{name}, {sampler} ICs");
                jobs.push(Job::new(label, &plan, t, &alphas)?);
            }
        }
        let curves = run_jobs(jobs)?;

        let (grid, rates) = collision_rate_grid(&curves, &alphas)?;
        println!();
        for r in &rates {
            println!("  {r}");
        }
        report.png("collision_rate.png", &grid, (1300, 1020))?;
        write_curves(report, "collision_rate", &curves, &json!({"rates": rates}))?;
        Ok(())
    })
}
