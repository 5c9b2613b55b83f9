//! The paper's energy-conservation figure (App. A.2): |E_n − E_0| per
//! collision for the four tables at several α, and over a long run the
//! largest relative deviation max |ΔE|/E₀, beside the same for the paper's
//! collision formulas evaluated literally in components (no energy-shell
//! restore). Initial condition as in the paper (θ0 = 0.8, u0 = 0, speed 1,
//! E₀ = ½) from the start points of `fig_trajectories`.
//!
//! ```text
//! cargo run --release --example fig_energy -- [--quick | --paper] [--out DIR]
//! ```
//!
//! Trace 500 collisions with `--quick`, 5000 (the paper's) otherwise; long
//! run 10⁵, 10⁶ (default) or 10⁷ (`--paper`) collisions. Writes
//! `energy_trace.png`, `energy_long.png` (dashed: paper eqs. 1–3),
//! `energy_trace.csv`, `energy_long.csv` and `energy.json` (per table and α
//! both long-run `EnergyHistory`s, the largest trace deviation and its share
//! of exact zeros, which are drawn on the floor line at 10⁻¹⁸).

use std::process::ExitCode;

use serde_json::json;
use spinball_analysis::diagnostics::energy_conservation;
use spinball_core::{Billiard, SpinLaw, State};
use spinball_figures::{
    Csv, ENERGY_LONG_COLUMNS, ENERGY_TRACE_COLUMNS, EnergyPanels, energy_long_rows,
    energy_trace_rows, run_figure,
};
use spinball_geometry::{DVec2, Table};
use spinball_plot::{Grid, format_tick};

const NAME: &str = "fig_energy";
const ABOUT: &str = "Energy conservation |Eₙ − E₀| per collision and over long runs (paper appendix; fixed initial condition, --seed is not used).";
const ALPHAS: [f64; 4] = [0.0, 0.3, 0.7, 1.0];
const THETA0: f64 = 0.8;
const U0: f64 = 0.0;
const TABLES: [(&str, &str, [f64; 2]); 4] = [
    ("circle:R=1", "circle R = 1", [0.3, 0.2]),
    ("rectangle:L=1.5,H=1", "rectangle 1.5 × 1", [0.3, 0.2]),
    ("stadium:a=1", "stadium a = 1", [0.3, 0.2]),
    ("sinai:L=2,R=1", "Sinai L = 2, R = 1", [-1.5, 0.2]),
];

fn main() -> ExitCode {
    run_figure(NAME, ABOUT, |args, report| {
        let trace_len: u64 = args.pick(500, 5_000, 5_000);
        let long_len: u64 = args.pick(100_000, 1_000_000, 10_000_000);
        let title = format!("Energy deviation per collision (θ₀ = {THETA0}, u₀ = {U0}, E₀ = ½)");
        let mut traces = Grid::new(2, 2).title(title);
        let long = format_tick(long_len as f64);
        let title = format!("Largest relative energy deviation over {long} collisions");
        let mut longs = Grid::new(2, 2).title(title);
        let mut trace_csv = Csv::new(&ENERGY_TRACE_COLUMNS);
        let mut long_csv = Csv::new(&ENERGY_LONG_COLUMNS);
        let mut rows = Vec::new();
        for (spec, title, start) in TABLES {
            let table: Table = spec.parse()?;
            let start = State::new(DVec2::from(start), DVec2::from_angle(THETA0), U0);
            let mut panels = EnergyPanels::new(title);
            for (k, alpha) in ALPHAS.into_iter().enumerate() {
                let billiard = Billiard::new(table, SpinLaw::new(alpha)?);
                // The trace, and the long run of our map and of the paper's
                // formulas in components.
                let check = energy_conservation(&billiard, start, trace_len, long_len)?;
                energy_trace_rows(&mut trace_csv, spec, alpha, &check.trace);
                energy_long_rows(&mut long_csv, spec, alpha, &check);
                panels = panels.add(k, ALPHAS.len(), alpha, &check);
                rows.push(json!({
                    "table": spec, "alpha": alpha, "trace_max_abs_dE": check.trace.max_deviation,
                    "trace_exact_zero_fraction": check.trace.exact_zero_fraction(),
                    "long": check.library, "paper_formulas_long": check.components,
                }));
            }
            traces.push(panels.trace);
            longs.push(panels.long);
        }
        let size = args.pick((1200, 900), (1600, 1200), (2000, 1500));
        report.png("energy_trace.png", &traces, size)?;
        report.png("energy_long.png", &longs, size)?;
        report.csv("energy_trace.csv", &trace_csv)?;
        report.csv("energy_long.csv", &long_csv)?;
        let doc = json!({
            "theta0": THETA0, "u0": U0, "energy": 0.5, "trace_collisions": trace_len,
            "long_collisions": long_len, "tables": TABLES, "results": rows,
        });
        report.json("energy.json", &doc)?;
        Ok(())
    })
}
