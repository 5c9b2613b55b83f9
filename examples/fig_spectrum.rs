//! The paper's full-spectrum figure (App. A.6): the five Lyapunov exponents
//! against α for the stadium (a = 1) and the Sinai table (L = 2, R = 1), by
//! exact tangent dynamics and by the paper's five-shadow finite differences
//! (δ0 = 1e-7), QR after every collision, paper sampler. The exact spectrum
//! is `(λ, 0, 0, 0, −λ)`; the finite-difference one `(λ, ≈0, ≈0, −λ, λ₅)`
//! with `λ₅` the collapsed flow direction, set by `δ0` and rounding, not by
//! the dynamics (see `spinball_analysis::estimators::lyapunov_spectrum`).
//!
//! ```text
//! cargo run --release --example fig_spectrum -- [--quick | --paper] [--out DIR] [--seed N]
//! ```
//!
//! | mode      | α values          | ICs | collisions |
//! |-----------|-------------------|-----|------------|
//! | `--quick` | 0, 0.3, 0.7, 1    | 4   | 2 000      |
//! | default   | 0, 0.1, …, 1 (11) | 50  | 5·10⁴      |
//! | `--paper` | 0, 0.05, …, 1 (21)| 50  | 5·10⁴      |
//!
//! Writes `spectrum.png` (rows: exact, its middle three enlarged, fd leading
//! four, fd fifth), `spectrum.csv` and `spectrum.json` (both
//! `SpectrumEstimate`s per table and α, without the per-trajectory spectra,
//! with `middle_max_abs` and `λ₁ + λ₅` (exact) or `λ₁ + λ₄` (fd)).

use std::process::ExitCode;

use serde_json::json;
use spinball_analysis::estimators::{Method, SpectrumOptions};
use spinball_analysis::run::spectrum_ensemble;
use spinball_core::{Billiard, Sampler, SpinLaw};
use spinball_figures::{SpectrumPair, run_figure, spectrum_grid, spectrum_pairs_csv, unit_grid};
use spinball_geometry::Table;

const NAME: &str = "fig_spectrum";
const ABOUT: &str = "Full Lyapunov spectrum vs α, stadium and Sinai, exact tangent and the paper's finite differences (paper appendix E).";
const TABLES: [&str; 2] = ["stadium:a=1", "sinai:L=2,R=1"];
const TITLES: [&str; 2] = ["stadium a = 1", "Sinai L = 2, R = 1"];

fn main() -> ExitCode {
    run_figure(NAME, ABOUT, |args, report| {
        let alphas = args.pick(vec![0.0, 0.3, 0.7, 1.0], unit_grid(11), unit_grid(21));
        let ics: u64 = args.pick(4, 50, 50);
        let collisions: u64 = args.pick(2_000, 50_000, 50_000);
        let (seed, threads) = (args.seed, args.threads);
        let (mut results, mut records): (Vec<Vec<SpectrumPair>>, _) = (Vec::new(), Vec::new());
        for spec in TABLES {
            let table: Table = spec.parse()?;
            let mut points = Vec::new();
            for &alpha in &alphas {
                let billiard = Billiard::new(table, SpinLaw::new(alpha)?);
                let run = |method| {
                    let options = SpectrumOptions::new(collisions, method);
                    spectrum_ensemble(&billiard, Sampler::Paper, seed, 0..ics, &options, threads)
                };
                let pair = [run(Method::Tangent)?, run(Method::default())?];
                let [exact, fd] = pair
                    .each_ref()
                    .map(|e| e.mean.map(|x| format!("{x:+.4}")).join(" "));
                println!("  {spec:<14} α = {alpha:<4} exact [{exact}]  fd [{fd}]");
                // The JSON keeps every statistic but not the per-trajectory
                // spectra; the pairing sum is λ₁ + λ₅ (exact), λ₁ + λ₄ (fd).
                let [exact, fd] = &pair;
                records.push(json!({
                    "table": spec, "alpha": alpha,
                    "exact": {"estimate": exact.without_spectra(), "l1_plus_l5": exact.pair_sum(0, 4), "middle_max_abs": exact.neutral_max_abs()},
                    "fd": {"estimate": fd.without_spectra(), "l1_plus_l4": fd.pair_sum(0, 3), "middle_max_abs": fd.neutral_max_abs()},
                }));
                points.push((alpha, pair));
            }
            results.push(points);
        }

        let title =
            format!("Lyapunov spectrum vs α ({ics} ICs × {collisions} collisions, mean ± SEM)");
        // The spectra of each table, named by its title (figure) or spec (CSV).
        let named = |names: [&'static str; 2]| -> Vec<(&str, &[SpectrumPair])> {
            names
                .into_iter()
                .zip(results.iter().map(Vec::as_slice))
                .collect()
        };
        let size = args.pick((1400, 1700), (1800, 2200), (2200, 2700));
        report.png("spectrum.png", &spectrum_grid(title, &named(TITLES)), size)?;
        report.csv("spectrum.csv", &spectrum_pairs_csv(&named(TABLES)))?;
        let doc = json!({"ics": ics, "collisions": collisions, "results": records});
        report.json("spectrum.json", &doc)?;
        Ok(())
    })
}
