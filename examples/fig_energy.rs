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
use spinball_analysis::{
    EnergyHistory, component_law_energy_history, energy_history, energy_trace,
};
use spinball_core::{Billiard, SpinLaw, State};
use spinball_geometry::{DVec2, Table};
use spinball_plot::{
    Csv, Grid, Legend, LineKind, LinePlot, RGBColor, Series, format_tick, run_figure, viridis,
};

const NAME: &str = "fig_energy";
const ABOUT: &str = "Energy conservation |Eₙ − E₀| per collision and over long runs (paper appendix; fixed initial condition, --seed is not used).";
const ALPHAS: [f64; 4] = [0.0, 0.3, 0.7, 1.0];
const THETA0: f64 = 0.8;
const U0: f64 = 0.0;
/// Where exact zeros are drawn on the log axes.
const FLOOR: f64 = 1e-18;
const TABLES: [(&str, &str, [f64; 2]); 4] = [
    ("circle:R=1", "circle R = 1", [0.3, 0.2]),
    ("rectangle:L=1.5,H=1", "rectangle 1.5 × 1", [0.3, 0.2]),
    ("stadium:a=1", "stadium a = 1", [0.3, 0.2]),
    ("sinai:L=2,R=1", "Sinai L = 2, R = 1", [-1.5, 0.2]),
];

/// `max |ΔE|/E₀` up to each checkpoint, floored.
fn curve(h: &EnergyHistory) -> Vec<(f64, f64)> {
    let p = h.points.iter();
    p.map(|p| (p.collisions as f64, p.max_relative_deviation.max(FLOOR)))
        .collect()
}

fn main() -> ExitCode {
    run_figure(NAME, ABOUT, |args, report| {
        let trace_len: u64 = args.pick(500, 5_000, 5_000);
        let long_len: u64 = args.pick(100_000, 1_000_000, 10_000_000);
        let title = format!("Energy deviation per collision (θ₀ = {THETA0}, u₀ = {U0}, E₀ = ½)");
        let mut traces = Grid::new(2, 2).title(title);
        let long = format_tick(long_len as f64);
        let title = format!("Largest relative energy deviation over {long} collisions");
        let mut longs = Grid::new(2, 2).title(title);
        let mut trace_csv = Csv::with_columns("table,alpha,n,abs_dE");
        let mut long_csv = Csv::with_columns("table,alpha,n,max_rel_dE,paper_formulas_max_rel_dE");
        let mut rows = Vec::new();
        for (spec, title, start) in TABLES {
            let table: Table = spec.parse()?;
            let start = State::new(DVec2::from(start), DVec2::from_angle(THETA0), U0);
            let mut trace_plot = LinePlot::with_axes(title, "collision number n", "|Eₙ − E₀|")
                .log_y(true)
                .y_range(FLOOR / 3.0, 1e-13)
                .hline(f64::EPSILON * 0.5, "ε·E₀")
                .hline(FLOOR, "exact 0");
            // A legend entry for the dashed curves (its one point is clipped).
            let dashed = Series::new("dashed: paper eqs. 1–3", [(1.0, FLOOR / 3.0)]).line_only();
            let mut long_plot = LinePlot::with_axes(title, "collisions n", "max |ΔE|/E₀ up to n")
                .log_x(true)
                .log_y(true)
                .y_range(FLOOR / 3.0, 1e-9)
                .legend(Legend::UpperLeft)
                .hline(f64::EPSILON, "ε")
                .hline(FLOOR, "exact 0")
                .series(dashed.kind(LineKind::Dashed).color(RGBColor(60, 60, 60)));
            for (k, alpha) in ALPHAS.into_iter().enumerate() {
                let billiard = Billiard::new(table, SpinLaw::new(alpha)?);
                let trace = energy_trace(&billiard, start, trace_len, 1)?;
                let deviations: Vec<f64> = trace.points.iter().map(|p| p.deviation).collect();
                let ours = energy_history(&billiard, start, long_len)?;
                let paper = component_law_energy_history(&table, billiard.law(), start, long_len)?;
                for (n, d) in deviations.iter().enumerate() {
                    trace_csv.row(&[&spec, &alpha, &(n + 1), &format!("{d:e}")]);
                }
                for (p, q) in ours.points.iter().zip(&paper.points) {
                    let (a, b) = (p.max_relative_deviation, q.max_relative_deviation);
                    let (a, b) = (format!("{a:e}"), format!("{b:e}"));
                    long_csv.row(&[&spec, &alpha, &p.collisions, &a, &b]);
                }
                // Later series are drawn over earlier ones: shrink their
                // markers so every α stays visible.
                let color = viridis(k as f64 / (ALPHAS.len() - 1) as f64 * 0.85);
                let pts = deviations
                    .iter()
                    .enumerate()
                    .map(|(n, d)| ((n + 1) as f64, d.max(FLOOR)));
                let dots = Series::new(format!("α = {alpha}"), pts).markers_only();
                trace_plot =
                    trace_plot.series(dots.marker_radius(4 - k.min(3) as u32).color(color));
                let dashed = Series::unlabelled(curve(&paper))
                    .line_only()
                    .kind(LineKind::Dashed);
                long_plot = long_plot
                    .series(Series::new(format!("α = {alpha}"), curve(&ours)).color(color))
                    .series(dashed.color(color));
                let zeros = deviations.iter().filter(|d| **d == 0.0).count();
                let largest = deviations.iter().copied().fold(0.0, f64::max);
                rows.push(json!({
                    "table": spec, "alpha": alpha, "trace_max_abs_dE": largest,
                    "trace_exact_zero_fraction": zeros as f64 / deviations.len().max(1) as f64,
                    "long": ours, "paper_formulas_long": paper,
                }));
            }
            traces.push(trace_plot);
            longs.push(long_plot);
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
