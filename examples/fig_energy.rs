//! The paper's energy-conservation figure (appendix): |E_n − E_0| against
//! collision number for the four tables at several α, and a long run that
//! tracks the largest relative deviation max |ΔE|/E₀.
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
//! max |ΔE|/E₀, log–log), `energy_trace.csv`, `energy_long.csv` and
//! `energy.json` (per table and α: largest deviations, share of exact zeros,
//! wall time). An exact zero cannot sit on a log axis: zeros are drawn on the
//! floor line at 10⁻¹⁸ and counted in the JSON.

use std::error::Error;
use std::fmt::Write as _;
use std::process::ExitCode;
use std::time::Instant;

use spinball_core::{Billiard, EnergyMonitor, SpinLaw, State};
use spinball_geometry::{Boundary, DVec2, Table, TableVisitor};
use spinball_plot::cli::FigureArgs;
use spinball_plot::{Grid, Legend, LinePlot, Plot, Series, viridis};

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

type BoxError = Box<dyn Error + Send + Sync>;

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

/// One table at one α: the trace and the long run.
struct Measured {
    spec: &'static str,
    alpha: f64,
    trace: Vec<f64>,
    long: Vec<(u64, f64)>,
    long_seconds: f64,
}

fn run(args: &FigureArgs) -> Result<(), BoxError> {
    let t0 = Instant::now();
    let trace_len: u64 = args.pick(500, 5_000, 5_000);
    let long_len: u64 = args.pick(100_000, 1_000_000, 10_000_000);
    let (width, height) = args.pick((1200, 900), (1600, 1200), (2000, 1500));

    let mut results = Vec::new();
    for (spec, _, start) in TABLES {
        let table: Table = spec.parse()?;
        let start = State::new(DVec2::from(start), DVec2::from_angle(THETA0), U0);
        for alpha in ALPHAS {
            let trace = table.visit(Trace {
                alpha,
                start,
                collisions: trace_len,
            })?;
            let t = Instant::now();
            let long = table.visit(LongRun {
                alpha,
                start,
                collisions: long_len,
            })?;
            results.push(Measured {
                spec,
                alpha,
                trace,
                long,
                long_seconds: t.elapsed().as_secs_f64(),
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

    // Figure 2: the long run.
    let mut grid = Grid::new(2, 2).title(format!(
        "Largest relative energy deviation over {} collisions",
        fmt_count(long_len)
    ));
    for (spec, title, _) in TABLES {
        let mut plot = LinePlot::new()
            .title(title)
            .x_label("collisions n")
            .y_label("max |ΔE|/E₀ up to n")
            .log_x(true)
            .log_y(true)
            .y_range(FLOOR / 3.0, 1e-13)
            .legend(Legend::UpperRight)
            .hline(f64::EPSILON, "ε")
            .hline(FLOOR, "exact 0");
        for (k, m) in results.iter().filter(|m| m.spec == spec).enumerate() {
            let pts = m.long.iter().map(|&(n, d)| (n as f64, d.max(FLOOR)));
            plot = plot.series(Series::new(format!("α = {}", m.alpha), pts).color(alpha_color(k)));
        }
        grid.push(plot);
    }
    let long_png = args.output("energy_long.png")?;
    grid.save_png(&long_png, width, height)?;

    // Data.
    let mut csv = String::from("table,alpha,n,abs_dE\n");
    let mut long_csv = String::from("table,alpha,n,max_rel_dE\n");
    for m in &results {
        for (n, d) in m.trace.iter().enumerate() {
            let _ = writeln!(csv, "\"{}\",{},{},{:e}", m.spec, m.alpha, n + 1, d);
        }
        for (n, d) in &m.long {
            let _ = writeln!(long_csv, "\"{}\",{},{},{:e}", m.spec, m.alpha, n, d);
        }
    }
    std::fs::write(args.output("energy_trace.csv")?, csv)?;
    std::fs::write(args.output("energy_long.csv")?, long_csv)?;
    std::fs::write(
        args.output("energy.json")?,
        summary(args, trace_len, long_len, &results),
    )?;

    let worst = results
        .iter()
        .map(|m| m.long.last().map_or(0.0, |l| l.1))
        .fold(0.0, f64::max);
    println!(
        "{NAME} ({} mode): max |ΔE|/E₀ over {} collisions = {worst:.2e} (all tables, α); wrote {} and {} in {:.2} s",
        args.mode,
        fmt_count(long_len),
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

/// |E_n − E_0| after each of `collisions` collisions.
struct Trace {
    alpha: f64,
    start: State,
    collisions: u64,
}

impl TableVisitor for Trace {
    type Output = Result<Vec<f64>, BoxError>;
    fn visit<B: Boundary + Clone + Send + Sync>(self, table: &B) -> Self::Output {
        let law = SpinLaw::new(self.alpha)?;
        let billiard = Billiard::new(table.clone(), law);
        let mut ball = billiard.launch(self.start)?;
        let e0 = self.start.energy(&law);
        let mut out = Vec::with_capacity(self.collisions as usize);
        billiard.run(&mut ball, self.collisions, &mut |_: &_, s: &State| {
            out.push((s.energy(&law) - e0).abs());
        })?;
        Ok(out)
    }
}

/// The running maximum of |E_n − E_0|/E_0 at checkpoints 1, 2, 5, 10, ….
struct LongRun {
    alpha: f64,
    start: State,
    collisions: u64,
}

impl TableVisitor for LongRun {
    type Output = Result<Vec<(u64, f64)>, BoxError>;
    fn visit<B: Boundary + Clone + Send + Sync>(self, table: &B) -> Self::Output {
        let law = SpinLaw::new(self.alpha)?;
        let billiard = Billiard::new(table.clone(), law);
        let mut ball = billiard.launch(self.start)?;
        let mut monitor = EnergyMonitor::new(law, &self.start);
        let mut done = 0;
        let mut out = Vec::new();
        for cp in checkpoints(self.collisions) {
            billiard.run(&mut ball, cp - done, &mut monitor)?;
            done = cp;
            out.push((cp, monitor.max_relative_deviation));
        }
        Ok(out)
    }
}

/// 1, 2, 5, 10, 20, 50, … up to and including `n`.
fn checkpoints(n: u64) -> Vec<u64> {
    let mut out = Vec::new();
    let mut decade = 1;
    'outer: loop {
        for m in [1, 2, 5] {
            let c = m * decade;
            if c >= n {
                break 'outer;
            }
            out.push(c);
        }
        decade *= 10;
    }
    out.push(n);
    out
}

fn fmt_count(n: u64) -> String {
    let e = (n as f64).log10();
    if n >= 10_000 && (e - e.round()).abs() < 1e-12 {
        spinball_plot::format_tick(n as f64)
    } else {
        n.to_string()
    }
}

fn summary(args: &FigureArgs, trace_len: u64, long_len: u64, results: &[Measured]) -> String {
    let rows: Vec<String> = results
        .iter()
        .map(|m| {
            let max_abs = m.trace.iter().copied().fold(0.0, f64::max);
            let zeros = m.trace.iter().filter(|d| **d == 0.0).count();
            let long_max = m.long.last().map_or(0.0, |l| l.1);
            format!(
                "    {{\"table\": \"{}\", \"alpha\": {}, \"trace_max_abs_dE\": {:e}, \
                 \"trace_exact_zero_fraction\": {:.4}, \"long_max_rel_dE\": {:e}, \
                 \"long_collisions\": {}, \"long_seconds\": {:.3}}}",
                m.spec,
                m.alpha,
                max_abs,
                zeros as f64 / m.trace.len().max(1) as f64,
                long_max,
                long_len,
                m.long_seconds
            )
        })
        .collect();
    format!(
        "{{\n  \"figure\": \"{NAME}\",\n  \"mode\": \"{}\",\n  \"theta0\": {THETA0},\n  \"u0\": {U0},\n  \
         \"energy\": 0.5,\n  \"trace_collisions\": {trace_len},\n  \"long_collisions\": {long_len},\n  \
         \"tables\": [{}],\n  \"results\": [\n{}\n  ],\n  \"version\": \"{}\"\n}}\n",
        args.mode,
        TABLES
            .iter()
            .map(|(s, _, p)| format!("{{\"table\": \"{s}\", \"start\": [{}, {}]}}", p[0], p[1]))
            .collect::<Vec<_>>()
            .join(", "),
        rows.join(",\n"),
        env!("CARGO_PKG_VERSION")
    )
}
