//! The paper's energy-conservation figure (appendix): |E_n − E_0| against
//! collision number for the four tables at several α, and a long run that
//! tracks the largest relative deviation max |ΔE|/E₀, beside the same
//! measurement for the paper's collision formulas evaluated literally in
//! components (no energy-shell restore).
//!
//! ```text
//! cargo run --release --example fig_energy -- [--quick | --paper] [--out DIR]
//! ```
//!
//! Initial condition as in the paper (θ0 = 0.8, u0 = 0, speed 1, E₀ = ½),
//! from the start points of `fig_trajectories`: (0.3, 0.2) in the circle,
//! rectangle (L = 1.5, H = 1) and stadium (a = 1), (−1.5, 0.2) in the Sinai
//! table (L = 2, R = 1).
//!
//! | mode      | trace       | long run             |
//! |-----------|-------------|----------------------|
//! | `--quick` | 500         | 10⁵ collisions       |
//! | default   | 5000 (paper)| 10⁶ collisions       |
//! | `--paper` | 5000        | 10⁷ collisions       |
//!
//! Writes `energy_trace.png` (2 × 2 grid, log y), `energy_long.png` (running
//! max |ΔE|/E₀, log–log; solid: this library, dashed: paper eqs. 1–3 in
//! components), `energy_trace.csv`, `energy_long.csv` and `energy.json` (per
//! table and α: largest deviations of both, share of exact zeros, wall
//! time). An exact zero cannot sit on a log axis: zeros are drawn on the
//! floor line at 10⁻¹⁸ and counted in the JSON.

use std::error::Error;
use std::fmt::Write as _;
use std::process::ExitCode;
use std::time::Instant;

use serde_json::json;
use spinball_analysis::{
    EnergyHistory, component_law_energy_history, energy_history, energy_trace,
};
use spinball_core::{Billiard, SpinLaw, State};
use spinball_geometry::{DVec2, Table};
use spinball_plot::cli::FigureArgs;
use spinball_plot::{Grid, Legend, LineKind, LinePlot, Plot, Series, viridis};

const NAME: &str = "fig_energy";
const ABOUT: &str = "Energy conservation |Eₙ − E₀| per collision and over long runs (paper appendix; fixed initial condition, --seed is not used).";
const ALPHAS: [f64; 4] = [0.0, 0.3, 0.7, 1.0];
const THETA0: f64 = 0.8;
const U0: f64 = 0.0;
/// Where exact zeros are drawn on the log axes.
const FLOOR: f64 = 1e-18;

const TABLES: [(&str, &str, [f64; 2]); 4] = [
    ("circle:R=1", "circle R = 1", [0.3, 0.2]),
    (
        "rectangle:L=1.5,H=1",
        "rectangle L = 1.5, H = 1",
        [0.3, 0.2],
    ),
    ("stadium:a=1", "stadium a = 1", [0.3, 0.2]),
    ("sinai:L=2,R=1", "Sinai L = 2, R = 1", [-1.5, 0.2]),
];

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

/// One table at one α: the trace and the long runs.
struct Measured {
    spec: &'static str,
    alpha: f64,
    trace: Vec<f64>,
    long: EnergyHistory,
    paper: EnergyHistory,
    long_seconds: f64,
}

fn run(args: &FigureArgs) -> Result<(), Box<dyn Error>> {
    let t0 = Instant::now();
    let trace_len: u64 = args.pick(500, 5_000, 5_000);
    let long_len: u64 = args.pick(100_000, 1_000_000, 10_000_000);
    let (width, height) = args.pick((1200, 900), (1600, 1200), (2000, 1500));

    let mut results = Vec::new();
    for (spec, _, start) in TABLES {
        let table: Table = spec.parse()?;
        let start = State::new(DVec2::from(start), DVec2::from_angle(THETA0), U0);
        for alpha in ALPHAS {
            let billiard = Billiard::new(table, SpinLaw::new(alpha)?);
            let trace = energy_trace(&billiard, start, trace_len, 1)?
                .points
                .iter()
                .map(|p| p.deviation)
                .collect();
            let t = Instant::now();
            let long = energy_history(&billiard, start, long_len)?;
            let long_seconds = t.elapsed().as_secs_f64();
            let paper = component_law_energy_history(&table, billiard.law(), start, long_len)?;
            results.push(Measured {
                spec,
                alpha,
                trace,
                long,
                paper,
                long_seconds,
            });
        }
    }

    // Figure 1: the trace.
    let mut grid = Grid::new(2, 2).title(format!(
        "Energy deviation per collision (θ₀ = {THETA0}, u₀ = {U0}, E₀ = ½)"
    ));
    for (spec, title, _) in TABLES {
        let mut plot = LinePlot::new()
            .title(title)
            .x_label("collision number n")
            .y_label("|Eₙ − E₀|")
            .log_y(true)
            .y_range(FLOOR / 3.0, 1e-13)
            .legend(Legend::UpperRight)
            .hline(f64::EPSILON * 0.5, "ε·E₀")
            .hline(FLOOR, "exact 0");
        for (k, m) in results.iter().filter(|m| m.spec == spec).enumerate() {
            let pts = m
                .trace
                .iter()
                .enumerate()
                .map(|(n, d)| ((n + 1) as f64, d.max(FLOOR)));
            plot = plot.series(
                Series::new(format!("α = {}", m.alpha), pts)
                    .markers_only()
                    // Later series are drawn over earlier ones: shrink them so
                    // every α stays visible.
                    .marker_radius(4 - k.min(3) as u32)
                    .color(alpha_color(k)),
            );
        }
        grid.push(plot);
    }
    let trace_png = args.output("energy_trace.png")?;
    grid.save_png(&trace_png, width, height)?;

    // Figure 2: the long runs.
    let mut grid = Grid::new(2, 2).title(format!(
        "Largest relative energy deviation over {} collisions",
        spinball_plot::format_tick(long_len as f64)
    ));
    for (spec, title, _) in TABLES {
        let mut plot = LinePlot::new()
            .title(title)
            .x_label("collisions n")
            .y_label("max |ΔE|/E₀ up to n")
            .log_x(true)
            .log_y(true)
            .y_range(FLOOR / 3.0, 1e-9)
            .legend(Legend::UpperLeft)
            .hline(f64::EPSILON, "ε")
            .hline(FLOOR, "exact 0");
        // A legend entry for the dashed curves (its one point is clipped).
        plot = plot.series(
            Series::new("dashed: paper eqs. 1–3", [(1.0, FLOOR / 3.0)])
                .line_only()
                .kind(LineKind::Dashed)
                .color(spinball_plot::RGBColor(60, 60, 60)),
        );
        for (k, m) in results.iter().filter(|m| m.spec == spec).enumerate() {
            let curve = |h: &EnergyHistory| {
                h.points
                    .iter()
                    .map(|p| (p.collisions as f64, p.max_relative_deviation.max(FLOOR)))
                    .collect::<Vec<_>>()
            };
            plot = plot
                .series(
                    Series::new(format!("α = {}", m.alpha), curve(&m.long)).color(alpha_color(k)),
                )
                .series(
                    Series::unlabelled(curve(&m.paper))
                        .line_only()
                        .kind(LineKind::Dashed)
                        .color(alpha_color(k)),
                );
        }
        grid.push(plot);
    }
    let long_png = args.output("energy_long.png")?;
    grid.save_png(&long_png, width, height)?;

    // Data.
    let mut csv = String::from("table,alpha,n,abs_dE\n");
    let mut long_csv = String::from("table,alpha,n,max_rel_dE,paper_formulas_max_rel_dE\n");
    for m in &results {
        for (n, d) in m.trace.iter().enumerate() {
            let _ = writeln!(csv, "\"{}\",{},{},{:e}", m.spec, m.alpha, n + 1, d);
        }
        for (p, q) in m.long.points.iter().zip(&m.paper.points) {
            let _ = writeln!(
                long_csv,
                "\"{}\",{},{},{:e},{:e}",
                m.spec, m.alpha, p.collisions, p.max_relative_deviation, q.max_relative_deviation
            );
        }
    }
    std::fs::write(args.output("energy_trace.csv")?, csv)?;
    std::fs::write(args.output("energy_long.csv")?, long_csv)?;
    let rows: Vec<_> = results
        .iter()
        .map(|m| {
            let zeros = m.trace.iter().filter(|d| **d == 0.0).count();
            json!({
                "table": m.spec, "alpha": m.alpha,
                "trace_max_abs_dE": m.trace.iter().copied().fold(0.0, f64::max),
                "trace_exact_zero_fraction": zeros as f64 / m.trace.len().max(1) as f64,
                "long_max_rel_dE": m.long.max_relative_deviation(),
                "long_final_rel_dE": m.long.final_relative_deviation(),
                "paper_formulas_long_max_rel_dE": m.paper.max_relative_deviation(),
                "paper_formulas_long_final_rel_dE": m.paper.final_relative_deviation(),
                "long_collisions": long_len, "long_seconds": m.long_seconds,
            })
        })
        .collect();
    let doc = json!({
        "figure": NAME, "mode": args.mode.to_string(), "theta0": THETA0, "u0": U0,
        "energy": 0.5, "trace_collisions": trace_len, "long_collisions": long_len,
        "tables": TABLES.iter().map(|(s, _, p)| json!({"table": s, "start": p})).collect::<Vec<_>>(),
        "results": rows, "version": env!("CARGO_PKG_VERSION"),
    });
    std::fs::write(
        args.output("energy.json")?,
        serde_json::to_string_pretty(&doc)? + "\n",
    )?;

    let worst = |f: fn(&Measured) -> f64| results.iter().map(f).fold(0.0, f64::max);
    println!(
        "{NAME} ({} mode): max |ΔE|/E₀ over {long_len} collisions = {:.2e} (all tables, α), \
         paper formulas in components {:.2e}; wrote {} and {} in {:.2} s",
        args.mode,
        worst(|m| m.long.max_relative_deviation()),
        worst(|m| m.paper.max_relative_deviation()),
        trace_png.display(),
        long_png.display(),
        t0.elapsed().as_secs_f64()
    );
    Ok(())
}

/// Colours for the α values, dark to light (viridis without the pale end).
fn alpha_color(k: usize) -> spinball_plot::RGBColor {
    viridis(k as f64 / (ALPHAS.len() - 1) as f64 * 0.85)
}
