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
//! ν and λ/ν as in `spinball_plot::CurveRates`, drawn relative to Santaló's
//! rate at α = 0, `|∂Q|/(π|Q|)`; reference lines: the mean speed of the
//! paper's initial conditions at any α > 0 (`√3/4 + π/6 ≈ 0.957`) and of the
//! invariant measure (`π/4`). Writes `collision_rate.png` (2 × 2: ν on
//! linear and log α axes, λ/ν, λ per unit time), `collision_rate.csv` and
//! `collision_rate.json`.

use std::process::ExitCode;

use serde_json::json;
use spinball_analysis::{initial_mean_speed, linspace};
use spinball_core::Sampler;
use spinball_plot::{
    ALPHA_LABEL, CurveRates, Grid, Job, LAMBDA_LABEL, Legend, LineKind, LinePlot, Plan, RGBColor,
    Series, measured, palette, run_figure, run_jobs, template, write_curves,
};

const NAME: &str = "fig_collision_rate";
const ABOUT: &str = "Collision rate ν(α) and per-collision exponent λ/ν for the stadium and Sinai tables, paper and microcanonical initial conditions (paper appendix, Fig. collision_rate).";
const TABLES: [(&str, &str); 2] = [("stadium:a=1", "stadium"), ("sinai:L=2,R=1", "Sinai")];
const SMALL: [f64; 5] = [0.0, 0.001, 0.003, 0.01, 0.03];
const COARSE: [f64; 11] = [0.05, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0];
const REL: &str = "ν / ν_Santaló(α = 0)";

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
            for sampler in [Sampler::Paper, Sampler::Microcanonical] {
                let t = template(args, spec)?.with_sampler(sampler);
                let label = format!("{name}, {sampler} ICs");
                jobs.push(Job::new(label, &plan, t, &alphas)?);
            }
        }
        let curves = run_jobs(jobs)?;

        let title = "Collision rate (relative to Santaló's α = 0 rate)";
        let mut nu_lin = LinePlot::with_axes(title, ALPHA_LABEL, REL);
        let title = "Near α = 0⁺ (log α; α = 0 values at left)";
        let mut nu_log = LinePlot::with_axes(title, "spin parameter α (log scale)", REL)
            .log_x(true)
            .legend(Legend::Hidden);
        let title = "Exponent per collision λ/ν";
        let mut per_coll = LinePlot::with_axes(title, ALPHA_LABEL, "λ/ν (per collision)");
        let title = "Exponent per unit time λ";
        let mut lambda = LinePlot::with_axes(title, ALPHA_LABEL, LAMBDA_LABEL);
        let (lo, hi) = (alphas[1], alphas[alphas.len() - 1]);
        let zero_x = lo / 2.0; // where the α = 0 values sit on the log axis
        let mut rates = Vec::new();
        println!();
        for (i, c) in curves.iter().enumerate() {
            let r = CurveRates::of(c)?;
            println!("  {r}");
            let kind = [LineKind::Solid, LineKind::Dashed][i % 2];
            let style = |s: Series| s.kind(kind).color(palette(i));
            let relative = r.relative_nu();
            let log_x = relative
                .iter()
                .map(|&(a, m)| (if a > 0.0 { a } else { zero_x }, m));
            nu_lin = nu_lin.series(style(measured(c.label.clone(), relative.clone())));
            nu_log = nu_log.series(style(measured(c.label.clone(), log_x)));
            per_coll = per_coll.series(style(measured(c.label.clone(), r.per_collision.clone())));
            lambda = lambda.series(style(c.lambda_series()));
            rates.push(r);
        }
        let guide = |label: &str, sampler, from: f64, color| {
            let y = initial_mean_speed(sampler, 1.0);
            let line = Series::new(label, [(from, y), (hi, y)]).line_only();
            line.kind(LineKind::Dotted).color(color)
        };
        let (paper, micro) = (Sampler::Paper, Sampler::Microcanonical);
        let (black, grey) = (palette(6), RGBColor(0x70, 0x70, 0x70));
        let nu_lin = nu_lin
            .series(guide("paper ICs, α > 0: ⟨|v|⟩ = 0.957", paper, 0.0, black))
            .series(guide(
                "invariant measure, α > 0: ⟨|v|⟩ = π/4",
                micro,
                0.0,
                grey,
            ))
            .legend(Legend::UpperRight);
        let nu_log = nu_log
            .series(guide("", paper, zero_x, black))
            .series(guide("", micro, zero_x, grey));
        let plots = [nu_lin, nu_log, per_coll, lambda];
        let grid = plots.into_iter().fold(Grid::new(2, 2), Grid::panel);
        report.png("collision_rate.png", &grid, (1300, 1020))?;
        write_curves(report, "collision_rate", &curves, &json!({"rates": rates}))?;
        Ok(())
    })
}
