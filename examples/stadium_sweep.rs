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
//! Prints a table per method as the points finish (α, λ, SEM, SEM/λ,
//! chaotic fraction, median, ICs, seconds, why the point stopped), a
//! progress line on stderr, and writes into `--out` (default
//! `out/stadium_sweep`):
//! - `stadium_sweep.csv`: one row per method and α (every field of
//!   `spinball_analysis::SweepRow`: λ, SEM, median, conditional mean, chaotic
//!   fraction and its threshold band, DH product, collision rate, λ/ν, cost);
//! - `stadium_sweep.json`: the same points with the settings;
//! - `stadium_sweep.png`: λ(α) ± SEM for both methods with the paper's
//!   values, and the paired difference tangent − fd on the same ICs.
//!
//! The default run (2.8·10⁸ collisions) takes about a second on two cores
//! with the lane kernels and about 20 s on the scalar path. Results are
//! bitwise the same for any `--threads`.

#[allow(dead_code)]
mod sweep_support;

use std::process::ExitCode;
use std::time::Instant;

use serde_json::json;
use spinball_analysis::{Measurement, Method, paired_difference};
use spinball_plot::{Grid, Legend, LineKind, LinePlot, Plot, Series, palette};
use sweep_support::{
    ALPHA_LABEL, BoxError, Cli, Job, LAMBDA_LABEL, PAPER_STADIUM, Plan, report_done, run_jobs,
    template, write_results,
};

const NAME: &str = "stadium_sweep";
const ABOUT: &str = "λ(α) of the stadium a = 1 by finite differences (the paper's method) and exact tangent dynamics, with SEM ≤ 1% per point by default.";

fn main() -> ExitCode {
    let cli = Cli::parse(NAME, ABOUT);
    match run(&cli) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("{NAME}: {e}");
            ExitCode::FAILURE
        }
    }
}

fn run(cli: &Cli) -> Result<(), BoxError> {
    let start = Instant::now();
    let alphas = cli.pick(
        vec![0.0, 0.5, 1.0],
        vec![0.0, 0.05, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0],
        spinball_analysis::linspace(0.0, 1.0, 50),
    );
    let plan = cli.pick(
        Plan::fixed(64, 2_000),
        Plan::until(0.01, 200, 1_000, 20_000, 10_000),
        Plan::fixed(100_000, 50_000),
    );
    println!("{NAME} ({} mode): {}", cli.mode(), plan.describe());

    let methods = [Method::default(), Method::Tangent];
    let jobs = methods
        .iter()
        .map(|&m| {
            Ok(Job {
                label: format!("stadium a = 1, {}", m.name()),
                sweep: plan.sweep(template(cli, "stadium:a=1")?.with_method(m), &alphas)?,
            })
        })
        .collect::<Result<Vec<_>, BoxError>>()?;
    let curves = run_jobs(cli, jobs)?;
    let (fd, tangent) = (&curves[0], &curves[1]);

    // Paired difference on the initial conditions both runs share.
    let diffs = fd
        .estimates
        .iter()
        .zip(&tangent.estimates)
        .map(|(a, b)| paired_difference(a, b))
        .collect::<Result<Vec<_>, _>>()?;
    println!("\npaired difference tangent - fd (common ICs):");
    for (e, d) in fd.estimates.iter().zip(&diffs) {
        println!("  alpha {:>6.4}: {:+.2e} ± {:.2e}", e.alpha, d.value, d.sem);
    }
    let worst = curves
        .iter()
        .flat_map(|c| &c.estimates)
        .map(|e| e.rel_sem())
        .fold(0.0, f64::max);
    println!("largest SEM/lambda over all points: {:.2}%", 100.0 * worst);

    let lambda = LinePlot::new()
        .title("Stadium a = 1: λ(α)")
        .x_label(ALPHA_LABEL)
        .y_label(LAMBDA_LABEL)
        .series(fd.series("finite differences (δ₀ = 1e-7) ± SEM", Measurement::lambda))
        .series(
            tangent
                .series("exact tangent ± SEM", Measurement::lambda)
                .kind(LineKind::Dashed),
        )
        .series(
            Series::new("paper (§IV, Table I)", PAPER_STADIUM)
                .markers_only()
                .marker_radius(7)
                .color(palette(6)),
        )
        .legend(Legend::UpperRight);
    // The paired difference in units of the SEM of λ itself: how much the
    // choice of method matters compared with the statistical error.
    let unit: Vec<f64> = fd.estimates.iter().map(|e| e.sem).collect();
    let difference = LinePlot::new()
        .title("Same ICs: exact tangent − finite differences")
        .x_label(ALPHA_LABEL)
        .y_label("(λ_tangent − λ_fd) / SEM(λ_fd)")
        .series(
            Series::new(
                "paired difference ± its SEM",
                fd.estimates
                    .iter()
                    .zip(&diffs)
                    .zip(&unit)
                    .map(|((e, d), u)| (e.alpha, d.value / u)),
            )
            .errors(diffs.iter().zip(&unit).map(|(d, u)| d.sem / u))
            .color(palette(2)),
        )
        .series(
            Series::unlabelled(fd.estimates.iter().map(|e| (e.alpha, 0.0)))
                .band(
                    fd.estimates.iter().map(|_| -1.0),
                    fd.estimates.iter().map(|_| 1.0),
                )
                .band_label("±1 SEM of λ (statistical error)")
                .line_only()
                .color(palette(5)),
        )
        .y_range(-1.5, 1.5)
        .legend(Legend::UpperRight);
    let png = cli.output(&format!("{NAME}.png"))?;
    Grid::new(1, 2)
        .panel(lambda)
        .panel(difference)
        .save_png(&png, 1500, 640)?;

    let settings = json!({
        "table": "stadium:a=1",
        "alphas": alphas,
        "methods": ["fd", "tangent"],
        "sampler": "paper",
        "plan": plan.json(),
    });
    let extra = json!({
        "paired_difference_tangent_minus_fd": fd.estimates.iter().zip(&diffs).map(|(e, d)| json!({
            "alpha": e.alpha, "mean": d.value, "sem": d.sem,
        })).collect::<Vec<_>>(),
        "largest_rel_sem": worst,
    });
    let (csv, json_path) = write_results(cli, NAME, &curves, settings, extra)?;
    report_done(cli, &[&csv, &json_path, &png], start);
    Ok(())
}
