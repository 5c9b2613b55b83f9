//! The paper's phase-space separation figure (§V.A): `⟨ln(δ_n/δ0)⟩` against
//! collision number for the four tables at α = 0, 0.3, 0.7, 1, without
//! renormalisation, with SEM bands; and where that growth saturates.
//!
//! ```text
//! cargo run --release --example fig_separation -- [--quick | --paper] [--out DIR] [--seed N]
//! ```
//!
//! | mode      | pairs | collisions | λ/ν reference ensemble |
//! |-----------|-------|------------|------------------------|
//! | `--quick` | 300   | 50         | 40 ICs × 2000          |
//! | default   | 8000  | 50         | 400 ICs × 10⁴          |
//! | `--paper` | 8000  | 50         | 2000 ICs × 5·10⁴       |
//!
//! δ0 = 1e-7 in a random 5-D direction, paper sampler. For the stadium and
//! Sinai tables the early slope (per collision, fitted before the curve
//! passes half its plateau) is compared with the exponent per collision
//! `λ/ν` of a finite-difference Benettin ensemble. Writes `separation.png`
//! (2 × 2 panels), `separation.csv` (mean and SEM per collision) and
//! `separation.json` (plateau, collision at which it is reached, early slope,
//! `λ/ν`).

use std::error::Error;
use std::fmt::Write as _;
use std::process::ExitCode;
use std::time::Instant;

use serde_json::json;
use spinball_analysis::{
    Ensemble, Separation, SeparationOptions, phase_space_separation, summarize_separation,
};
use spinball_core::{Billiard, SpinLaw};
use spinball_geometry::{Boundary, Table, TableVisitor};
use spinball_plot::cli::FigureArgs;
use spinball_plot::{Grid, Legend, LinePlot, Plot, Series, viridis};

const NAME: &str = "fig_separation";
const ABOUT: &str =
    "Phase-space separation ⟨ln δn/δ0⟩ vs collision number, four tables, four α (paper §V.A).";
const ALPHAS: [f64; 4] = [0.0, 0.3, 0.7, 1.0];
const TABLES: [(&str, &str); 4] = [
    ("circle:R=1", "circle R = 1"),
    ("rectangle:L=1,H=1", "rectangle L = H = 1"),
    ("stadium:a=1", "stadium a = 1"),
    ("sinai:L=2,R=1", "Sinai L = 2, R = 1"),
];
/// The paper's estimate of `ln(δ_50/δ0)` ("`~1e-7·e^15`").
const PAPER_LN_50: f64 = 15.0;
/// Collisions averaged for the plateau.
const TAIL: usize = 10;

fn main() -> ExitCode {
    let args = FigureArgs::parse_or_exit(NAME, ABOUT);
    match run(&args) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("{NAME}: {e}");
            ExitCode::FAILURE
        }
    }
}

/// `phase_space_separation` with the concrete table type.
struct Separate(SpinLaw, SeparationOptions);

impl TableVisitor for Separate {
    type Output = Result<Separation, spinball_analysis::AnalysisError>;
    fn visit<B: Boundary + Clone + Send + Sync>(self, table: &B) -> Self::Output {
        phase_space_separation(&Billiard::new(table.clone(), self.0), &self.1)
    }
}

fn run(args: &FigureArgs) -> Result<(), Box<dyn Error>> {
    let t0 = Instant::now();
    let pairs: u64 = args.pick(300, 8_000, 8_000);
    let (ref_ics, ref_collisions): (u64, u64) =
        args.pick((40, 2_000), (400, 10_000), (2_000, 50_000));
    let options = SeparationOptions {
        pairs,
        seed: args.seed,
        ..SeparationOptions::default()
    };

    let mut grid = Grid::new(2, 2).title(format!(
        "Phase-space separation, {pairs} pairs, δ0 = 10⁻⁷, no renormalisation"
    ));
    let mut csv = String::from("table,alpha,n,mean_ln_ratio,sem\n");
    let mut rows = Vec::new();
    for (spec, title) in TABLES {
        let table: Table = spec.parse()?;
        let chaotic = matches!(table, Table::Stadium(_) | Table::Sinai(_));
        let mut plot = LinePlot::new()
            .title(title)
            .x_label("collision number n")
            .y_label("⟨ln(δₙ/δ₀)⟩")
            .y_range(0.0, 20.0)
            .legend(if chaotic {
                Legend::LowerRight
            } else {
                Legend::UpperLeft
            })
            .hline(PAPER_LN_50, "paper: ln(δ₅₀/δ₀) ≈ 15");
        for (k, alpha) in ALPHAS.into_iter().enumerate() {
            let law = SpinLaw::new(alpha)?;
            let clock = Instant::now();
            let sep = table.visit(Separate(law, options))?;
            let seconds = clock.elapsed().as_secs_f64();
            let summary = summarize_separation(&sep, TAIL)?;
            for (n, (m, e)) in sep.mean.iter().zip(&sep.sem).enumerate() {
                let _ = writeln!(csv, "\"{spec}\",{alpha},{},{m:.6},{e:.6}", n + 1);
            }
            let xs = (1..=sep.mean.len()).map(|n| n as f64);
            plot = plot.series(
                Series::new(format!("α = {alpha}"), xs.zip(sep.mean.iter().copied()))
                    .band(
                        sep.mean.iter().zip(&sep.sem).map(|(m, e)| m - e),
                        sep.mean.iter().zip(&sep.sem).map(|(m, e)| m + e),
                    )
                    .color(viridis(k as f64 / 3.0 * 0.85))
                    .marker_radius(3),
            );
            // λ/ν of the same table and α for comparison with the early slope.
            let reference = if chaotic {
                let e = Ensemble::new(table, law)
                    .with_ics(ref_ics)
                    .with_collisions(ref_collisions)
                    .with_seed(args.seed)
                    .run()?;
                Some(json!({
                    "lambda": e.mean, "lambda_sem": e.sem,
                    "per_collision": e.per_collision_mean,
                    "collision_rate": e.collision_rate,
                    "ics": e.n_ics, "collisions": e.collisions_per_ic,
                }))
            } else {
                None
            };
            println!(
                "  {spec:<20} α = {alpha:<4} ln δ50/δ0 = {:6.2} ± {:.2}, plateau {:6.2} reached at n = {:2}, early slope {:.3}/collision over n ≤ {}, tail slope {:+.3}{}",
                sep.mean[sep.mean.len() - 1],
                sep.sem[sep.sem.len() - 1],
                summary.plateau,
                summary.reach,
                summary.growth.slope,
                summary.fit_range.1,
                summary.tail_slope,
                reference.as_ref().map_or(String::new(), |r| format!(
                    ", λ/ν = {:.3}",
                    r["per_collision"].as_f64().unwrap_or(f64::NAN)
                )),
            );
            rows.push(json!({
                "table": spec, "alpha": alpha, "pairs": sep.pairs,
                "ln_ratio_at_50": sep.mean[sep.mean.len() - 1],
                "ln_ratio_at_50_sem": sep.sem[sep.sem.len() - 1],
                "plateau": summary.plateau, "plateau_tail": summary.tail,
                "reach_collision": summary.reach,
                "early_slope_per_collision": summary.growth.slope,
                "early_fit_collisions": [summary.fit_range.0, summary.fit_range.1],
                "tail_slope": summary.tail_slope,
                "reference": reference,
                "wall_time_s": seconds,
            }));
        }
        grid.push(plot);
    }
    let png = args.output("separation.png")?;
    let (w, h) = args.pick((1400, 1050), (1800, 1350), (2200, 1650));
    grid.save_png(&png, w, h)?;
    std::fs::write(args.output("separation.csv")?, csv)?;
    let doc = json!({
        "figure": NAME, "mode": args.mode.to_string(), "pairs": pairs,
        "collisions": options.collisions, "delta0": options.delta0, "sampler": "paper",
        "seed": args.seed, "alphas": ALPHAS, "results": rows,
        "version": env!("CARGO_PKG_VERSION"),
    });
    std::fs::write(
        args.output("separation.json")?,
        serde_json::to_string_pretty(&doc)? + "\n",
    )?;
    println!(
        "{NAME} ({} mode): wrote {} and CSV/JSON in {:.1} s",
        args.mode,
        png.display(),
        t0.elapsed().as_secs_f64()
    );
    Ok(())
}
