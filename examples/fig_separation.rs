//! The paper's phase-space separation figure (§VII.A): `⟨ln(δ_n/δ0)⟩`
//! against collision number for the four tables at α = 0, 0.3, 0.7, 1,
//! without renormalisation (δ0 = 1e-7 in a random 5-D direction, paper
//! sampler), with SEM bands; where that growth saturates; and, for the
//! stadium and Sinai tables, its early slope against the exponent per
//! collision `λ/ν` of a finite-difference Benettin ensemble.
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
//! Writes `separation.png` (2 × 2 panels), `separation.csv` (mean and SEM
//! per collision) and `separation.json` (per table and α the
//! `SeparationSummary` and the reference ensemble's `SweepRow`).

use std::process::ExitCode;
use std::time::Instant;

use serde_json::json;
use spinball_analysis::diagnostics;
use spinball_analysis::diagnostics::{
    SeparationOptions, phase_space_separation, summarize_separation,
};
use spinball_analysis::precision::Measurement;
use spinball_analysis::report::SweepRow;
use spinball_core::{Billiard, SpinLaw};
use spinball_figures::{Csv, measured_band, run_figure, template};
use spinball_geometry::Table;
use spinball_plot::{Grid, Legend, LinePlot, viridis};

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
/// Collisions averaged for the plateau.
const TAIL: usize = 10;

fn main() -> ExitCode {
    run_figure(NAME, ABOUT, |args, report| {
        let pairs: u64 = args.pick(300, 8_000, 8_000);
        let (ref_ics, ref_collisions): (u64, u64) =
            args.pick((40, 2_000), (400, 10_000), (2_000, 50_000));
        let options = SeparationOptions {
            pairs,
            seed: args.seed,
            threads: args.threads,
            ..SeparationOptions::default()
        };
        let mut grid = Grid::new(2, 2).title(format!(
            "Phase-space separation, {pairs} pairs, δ0 = 10⁻⁷, no renormalisation"
        ));
        let mut csv = Csv::new(&["table", "alpha", "n", "mean_ln_ratio", "sem"]);
        let mut rows = Vec::new();
        for (spec, title) in TABLES {
            let table: Table = spec.parse()?;
            let chaotic = matches!(table, Table::Stadium(_) | Table::Sinai(_));
            let mut plot = LinePlot::with_axes(title, "collision number n", "⟨ln(δₙ/δ₀)⟩")
                .y_range(0.0, 20.0)
                .legend([Legend::UpperLeft, Legend::LowerRight][usize::from(chaotic)])
                .hline(
                    diagnostics::SEPARATION_LN_RATIO_50,
                    "paper: ln(δ₅₀/δ₀) ≈ 15",
                );
            for (k, alpha) in ALPHAS.into_iter().enumerate() {
                let law = SpinLaw::new(alpha)?;
                let clock = Instant::now();
                let sep = phase_space_separation(&Billiard::new(table, law), &options)?;
                let seconds = clock.elapsed().as_secs_f64();
                let s = summarize_separation(&sep, TAIL)?;
                let curve: Vec<_> = (1..).zip(sep.mean.iter().zip(&sep.sem)).collect();
                for (n, (m, e)) in &curve {
                    csv.row(&[&spec, &alpha, n, m, e]);
                }
                let pts = curve
                    .iter()
                    .map(|(n, (m, e))| (f64::from(*n), Measurement::new(**m, **e)));
                let color = viridis(k as f64 / 3.0 * 0.85);
                plot = plot.series(
                    measured_band(format!("α = {alpha}"), pts)
                        .color(color)
                        .marker_radius(3),
                );
                // λ/ν of the same table and α, to compare with the early slope.
                let reference = if chaotic {
                    let t = template(args, spec)?.with_law(law).with_ics(ref_ics);
                    Some(SweepRow::from_estimate(
                        &t.with_collisions(ref_collisions).run()?,
                    )?)
                } else {
                    None
                };
                let (end, end_sem) = (sep.mean[sep.mean.len() - 1], sep.sem[sep.sem.len() - 1]);
                let (plateau, reach, slope, tail) =
                    (s.plateau, s.reach, s.growth.slope, s.tail_slope);
                let lambda_nu = reference
                    .as_ref()
                    .map_or(String::new(), |r| format!(", λ/ν = {:.3}", r.per_collision));
                println!(
                    "  {spec:<20} α = {alpha:<4} ln δ50/δ0 = {end:6.2} ± {end_sem:.2}, plateau {plateau:6.2} reached at n = {reach:2}, early slope {slope:.3}/collision, tail slope {tail:+.3}{lambda_nu}"
                );
                rows.push(json!({
                    "table": spec, "alpha": alpha, "pairs": sep.pairs, "ln_ratio_at_50": end,
                    "ln_ratio_at_50_sem": end_sem, "summary": s, "reference": reference, "wall_time_s": seconds,
                }));
            }
            grid.push(plot);
        }
        let size = args.pick((1400, 1050), (1800, 1350), (2200, 1650));
        report.png("separation.png", &grid, size)?;
        report.csv("separation.csv", &csv)?;
        let doc = json!({"options": options, "alphas": ALPHAS, "results": rows});
        report.json("separation.json", &doc)?;
        Ok(())
    })
}
