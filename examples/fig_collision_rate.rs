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
//! ν is the mean over trajectories of collisions / flight time; λ/ν is the
//! paper's `λ_coll` (ratio of the means, error with their covariance). The
//! rates are drawn relative to Santaló's rate at α = 0, `|∂Q|/(π|Q|)`;
//! reference lines: the mean speed of the paper's initial conditions at any
//! α > 0 (`√3/4 + π/6 ≈ 0.957`) and of the invariant measure (`π/4`).
//!
//! Writes `collision_rate.png` (2 × 2: ν on linear and log α axes, λ/ν,
//! λ per unit time), `collision_rate.csv` and `collision_rate.json`.

#[allow(dead_code)]
mod sweep_support;

use std::process::ExitCode;
use std::time::Instant;

use serde_json::json;
use spinball_analysis::{
    Measurement, initial_mean_speed, linspace, liouville_collision_rate, rate_summary,
};
use spinball_core::Sampler;
use spinball_geometry::Table;
use spinball_plot::{Grid, Legend, LineKind, LinePlot, Plot, Series, palette};
use sweep_support::{
    ALPHA_LABEL, BoxError, Cli, Curve, Job, LAMBDA_LABEL, Plan, main_with, report_done, run_jobs,
    template, write_results,
};

const NAME: &str = "fig_collision_rate";
const ABOUT: &str = "Collision rate ν(α) and per-collision exponent λ/ν for the stadium and Sinai tables, paper and microcanonical initial conditions (paper appendix, Fig. collision_rate).";

const TABLES: [(&str, &str); 2] = [("stadium:a=1", "stadium"), ("sinai:L=2,R=1", "Sinai")];
const SAMPLERS: [Sampler; 2] = [Sampler::Paper, Sampler::Microcanonical];

fn main() -> ExitCode {
    let cli = Cli::parse(NAME, ABOUT);
    main_with(NAME, || run(&cli))
}

/// ν, λ/ν per point of a curve.
struct Rates {
    nu: Vec<Measurement>,
    per_collision: Vec<Measurement>,
}

fn rates(c: &Curve) -> Result<Rates, BoxError> {
    let mut nu = Vec::new();
    let mut per_collision = Vec::new();
    for e in &c.estimates {
        let r = rate_summary(e)?;
        nu.push(Measurement::new(r.rate_mean, r.rate_sem));
        per_collision.push(Measurement::new(r.per_collision, r.per_collision_sem));
    }
    Ok(Rates { nu, per_collision })
}

fn run(cli: &Cli) -> Result<(), BoxError> {
    let start = Instant::now();
    let small = [0.0, 0.001, 0.003, 0.01, 0.03];
    let alphas = cli.pick(
        vec![0.0, 0.01, 0.5, 1.0],
        [
            &small[..],
            &[0.05, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0],
        ]
        .concat(),
        [&small[..], &linspace(0.0, 1.0, 50)[1..]].concat(),
    );
    let plan = cli.pick(
        Plan::fixed(48, 2_000),
        Plan::until(0.02, 200, 400, 4_000, 10_000),
        Plan::fixed(100_000, 10_000),
    );
    println!("{NAME} ({} mode): {}", cli.mode(), plan.describe());
    let mut jobs = Vec::new();
    let mut specs = Vec::new();
    for (spec, name) in TABLES {
        for sampler in SAMPLERS {
            jobs.push(Job {
                label: format!("{name}, {sampler} ICs"),
                sweep: plan.sweep(template(cli, spec)?.with_sampler(sampler), &alphas)?,
            });
            specs.push((spec.parse::<Table>()?, sampler));
        }
    }
    let curves = run_jobs(cli, jobs)?;

    let rel = "ν / ν_Santaló(α = 0)";
    let mut nu_lin = LinePlot::new()
        .title("Collision rate (relative to Santaló's α = 0 rate)")
        .x_label(ALPHA_LABEL)
        .y_label(rel)
        .legend(Legend::UpperRight);
    let mut nu_log = LinePlot::new()
        .title("Near α = 0⁺ (log α; α = 0 values at left)")
        .x_label("spin parameter α (log scale)")
        .y_label(rel)
        .log_x(true)
        .legend(Legend::Hidden);
    let mut per_coll = LinePlot::new()
        .title("Exponent per collision λ/ν")
        .x_label(ALPHA_LABEL)
        .y_label("λ/ν (per collision)")
        .legend(Legend::UpperRight);
    let mut lambda = LinePlot::new()
        .title("Exponent per unit time λ")
        .x_label(ALPHA_LABEL)
        .y_label(LAMBDA_LABEL)
        .legend(Legend::UpperRight);

    let positive: Vec<f64> = alphas.iter().copied().filter(|&a| a > 0.0).collect();
    let (lo, hi) = (positive[0], *positive.last().expect("alphas > 0"));
    // Where the α = 0 values sit on the log axis.
    let zero_x = lo / 2.0;
    let mut summary = Vec::new();
    println!(
        "\n  {:<24} {:>7} {:>16} {:>9} {:>16} {:>16}",
        "series", "alpha", "nu", "nu/nu_S", "lambda/nu", "lambda"
    );
    for (i, (c, (table, sampler))) in curves.iter().zip(&specs).enumerate() {
        let r = rates(c)?;
        let nu0 = liouville_collision_rate(table, 0.0);
        let color = palette(i);
        let kind = if *sampler == Sampler::Paper {
            LineKind::Solid
        } else {
            LineKind::Dashed
        };
        let alphas = c.alphas();
        for ((a, n), (p, e)) in alphas
            .iter()
            .zip(&r.nu)
            .zip(r.per_collision.iter().zip(&c.estimates))
        {
            println!(
                "  {:<24} {:>7.3} {:>8.5} ± {:.5} {:>9.4} {:>8.5} ± {:.5} {:>8.5} ± {:.5}",
                c.label,
                a,
                n.value,
                n.sem,
                n.value / nu0,
                p.value,
                p.sem,
                e.mean,
                e.sem
            );
        }
        let scaled = |m: &Measurement| Measurement::new(m.value / nu0, m.sem / nu0);
        let rel_nu: Vec<Measurement> = r.nu.iter().map(scaled).collect();
        nu_lin = nu_lin.series(
            Series::new(
                c.label.clone(),
                alphas.iter().zip(&rel_nu).map(|(&a, m)| (a, m.value)),
            )
            .errors(rel_nu.iter().map(|m| m.sem))
            .kind(kind)
            .color(color),
        );
        nu_log = nu_log.series(
            Series::new(
                c.label.clone(),
                alphas
                    .iter()
                    .zip(&rel_nu)
                    .map(|(&a, m)| (if a > 0.0 { a } else { zero_x }, m.value)),
            )
            .errors(rel_nu.iter().map(|m| m.sem))
            .kind(kind)
            .color(color),
        );
        per_coll = per_coll.series(
            Series::new(
                c.label.clone(),
                alphas
                    .iter()
                    .zip(&r.per_collision)
                    .map(|(&a, m)| (a, m.value)),
            )
            .errors(r.per_collision.iter().map(|m| m.sem))
            .kind(kind)
            .color(color),
        );
        lambda = lambda.series(c.lambda_series().kind(kind).color(color));

        // The paper's claims, measured: variation of ν over α > 0, the
        // drop of ν and of λ/ν from α = 0 to 1.
        let over = |from: f64| {
            let v: Vec<f64> = alphas
                .iter()
                .zip(&r.nu)
                .filter(|(a, _)| **a >= from)
                .map(|(_, m)| m.value)
                .collect();
            let (mn, mx) = v
                .iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
                    (a.min(x), b.max(x))
                });
            (mx - mn) / mx
        };
        let (nu_first, nu_last) = (r.nu[0].value, r.nu.last().expect("a point").value);
        let (pc_first, pc_last) = (
            r.per_collision[0].value,
            r.per_collision.last().expect("a point").value,
        );
        let s = json!({
            "label": c.label,
            "sampler": sampler.name(),
            "santalo_rate_alpha0": nu0,
            "liouville_rate_alpha_positive": liouville_collision_rate(table, 1.0),
            "initial_mean_speed_alpha_positive": initial_mean_speed(*sampler, 1.0),
            "nu_alpha0": r.nu[0],
            "nu_alpha1": r.nu.last(),
            "nu_drop_0_to_1": 1.0 - nu_last / nu_first,
            "nu_spread_alpha_ge_smallest_positive": over(lo),
            "nu_spread_alpha_ge_0.1": over(0.1),
            "per_collision_drop_0_to_1": 1.0 - pc_last / pc_first,
            "lambda_drop_0_to_1": 1.0 - c.estimates.last().expect("a point").mean / c.estimates[0].mean,
        });
        println!(
            "  => {}: nu falls {:.1}% from alpha 0 to 1; spread of nu over alpha >= {lo}: {:.1}%, over alpha >= 0.1: {:.1}%; lambda/nu falls {:.1}%",
            c.label,
            100.0 * (1.0 - nu_last / nu_first),
            100.0 * over(lo),
            100.0 * over(0.1),
            100.0 * (1.0 - pc_last / pc_first),
        );
        summary.push(s);
    }
    let grey = spinball_plot::RGBColor(0x70, 0x70, 0x70);
    let black = palette(6);
    let guide = |label: &str, y: f64, from: f64, to: f64, color| {
        Series::new(label, [(from, y), (to, y)])
            .line_only()
            .kind(LineKind::Dotted)
            .color(color)
    };
    let paper_speed = initial_mean_speed(Sampler::Paper, 1.0);
    let micro_speed = initial_mean_speed(Sampler::Microcanonical, 1.0);
    nu_lin = nu_lin
        .series(guide(
            "paper ICs, α > 0: ⟨|v|⟩ = 0.957",
            paper_speed,
            0.0,
            hi,
            black,
        ))
        .series(guide(
            "invariant measure, α > 0: ⟨|v|⟩ = π/4",
            micro_speed,
            0.0,
            hi,
            grey,
        ));
    nu_log = nu_log
        .series(guide("", paper_speed, zero_x, hi, black))
        .series(guide("", micro_speed, zero_x, hi, grey));

    let png = cli.output("collision_rate.png")?;
    Grid::new(2, 2)
        .panel(nu_lin)
        .panel(nu_log)
        .panel(per_coll)
        .panel(lambda)
        .save_png(&png, 1300, 1020)?;

    let settings = json!({
        "method": "fd",
        "samplers": ["paper", "microcanonical"],
        "alphas": alphas,
        "plan": plan.json(),
    });
    let (csv, json_path) = write_results(
        cli,
        "collision_rate",
        &curves,
        settings,
        json!({"rates": summary}),
    )?;
    report_done(cli, &[&csv, &json_path, &png], start);
    Ok(())
}
