//! Diffusion through Lorentz gases against the spin parameter α: `D(α)`
//! of the triangular gas (finite horizon) with its error and how the
//! estimate depends on the fit window, and the running coefficient
//! `⟨Δr²⟩/(4t)` against `t`, flat for the triangular gas (normal
//! diffusion) and growing like `ln t` for the square gas (infinite
//! horizon, marginal diffusion).
//!
//! ```text
//! cargo run --release --example fig_transport -- [--quick | --paper] [--out DIR] [--seed N]
//! ```
//!
//! | mode      | α grid of D   | balls | D run to | ⟨Δr²⟩/4t run to | wall time (2 cores) |
//! |-----------|---------------|-------|----------|-----------------|---------------------|
//! | `--quick` | 0, 0.5, 1     | 100   | 100      | 200             | < 1 s               |
//! | default   | 0, 0.1, …, 1  | 1 000 | 2 000    | 10⁴             | about two minutes   |
//! | `--paper` | 0, 0.1, …, 1  | 10⁴   | 10⁴      | 10⁵             | hours               |
//!
//! Gases: triangular w = 1, R = 0.45 (finite horizon) and square w = 1,
//! R = 0.4 (infinite horizon); balls start in the cell from the paper's
//! sampler; checkpoints are spaced evenly in `ln t` (six per doubling).
//! `D` is fitted on `[T/2, T]` (slope of `⟨Δr²⟩` against `4t`, error from
//! the per-ball slopes) and on each earlier halving window. Writes
//! `transport_diffusion.png` (D(α) and the window scan),
//! `transport_msd.png` (⟨Δr²⟩/4t against t for α = 0 and 1), and
//! `diffusion.csv`, `diffusion_windows.csv`, `msd.csv`.

use std::process::ExitCode;

use spinball::analysis::open::OpenEnsemble;
use spinball::geometry::LorentzGas;
use spinball::prelude::*;
use spinball_figures::{
    BoxError, Csv, DIFFUSION_COLUMNS, DiffusionRun, FigureArgs, MSD_COLUMNS, WINDOW_COLUMNS,
    apparent_d_series, diffusion_panel, diffusion_row, log_times, msd_rows, run_figure,
    window_rows, window_scan_series,
};
use spinball_plot::{Grid, Legend, LinePlot, palette};

const NAME: &str = "fig_transport";
const ABOUT: &str =
    "D(α) of the triangular Lorentz gas and ⟨Δr²⟩/4t of the triangular and square gases.";
/// Checkpoints per doubling of t.
const PER_OCTAVE: u32 = 6;

/// Run `ics` balls of `gas` at `alpha` to `t_end` and analyse them.
fn run(
    args: &FigureArgs,
    gas: LorentzGas,
    alpha: f64,
    ics: u64,
    times: &[f64],
) -> Result<DiffusionRun, BoxError> {
    let records = OpenEnsemble::new(Billiard::new(gas.table()?, SpinLaw::new(alpha)?))
        .with_seed(args.seed)
        .with_indices(0..ics)
        .with_threads(args.threads)
        .displacements(times)?;
    Ok(DiffusionRun::new(
        alpha,
        gas.horizon().into(),
        times,
        &records,
    )?)
}

fn main() -> ExitCode {
    run_figure(NAME, ABOUT, |args, report| {
        let triangular = LorentzGas::triangular(1.0, 0.45)?;
        let square = LorentzGas::square(1.0, 0.4)?;
        let (tri, sq) = ("triangular w=1 R=0.45", "square w=1 R=0.4");
        let alphas: Vec<f64> = args.pick(
            vec![0.0, 0.5, 1.0],
            (0..=10).map(|k| f64::from(k) / 10.0).collect(),
            (0..=10).map(|k| f64::from(k) / 10.0).collect(),
        );
        let ics: u64 = args.pick(100, 1_000, 10_000);
        let t_end: f64 = args.pick(100.0, 2_000.0, 10_000.0);
        let times = log_times(t_end / 256.0, t_end, PER_OCTAVE);
        println!("{tri}, {ics} balls to t = {t_end} (seed {})", args.seed);
        let (mut rows, mut windows, mut msd) = (
            Csv::new(&DIFFUSION_COLUMNS),
            Csv::new(&WINDOW_COLUMNS),
            Csv::new(&MSD_COLUMNS),
        );
        let mut runs = Vec::new();
        for &alpha in &alphas {
            let r = run(args, triangular, alpha, ics, &times)?;
            let trend = r
                .scan
                .trend
                .map_or("none".to_string(), |t| format!("{:.1} SE", t.z()));
            println!("  α = {alpha}: {} (trend over windows {trend})", r.estimate);
            diffusion_row(&mut rows, tri, &r);
            window_rows(&mut windows, tri, &r);
            runs.push(r);
        }
        let mut scan = LinePlot::with_axes(
            "dependence on the fit window",
            "window middle √(t0 t1)",
            "D of the window / D on [T/2, T]",
        )
        .log_x(true)
        .hline(1.0, "");
        for (k, r) in runs
            .iter()
            .enumerate()
            .filter(|(_, r)| [0.0, 0.5, 1.0].contains(&r.alpha))
        {
            scan =
                scan.series(window_scan_series(&format!("α = {}", r.alpha), r).color(palette(k)));
        }
        let mut d_figure = Grid::new(1, 2).title(format!(
            "Triangular Lorentz gas w = 1, R = 0.45 (finite horizon): {ics} balls to t = {t_end}"
        ));
        d_figure.push(diffusion_panel(
            "D(α) on [T/2, T] ± SE (per-ball slopes)",
            "D ± SE",
            &runs,
        ));
        d_figure.push(scan);
        report.png("transport_diffusion.png", &d_figure, (2000, 800))?;

        // ⟨Δr²⟩/4t against t: finite against infinite horizon.
        let ics_msd: u64 = args.pick(100, 1_000, 10_000);
        let t_msd: f64 = args.pick(200.0, 1e4, 1e5);
        let times = log_times(0.5, t_msd, PER_OCTAVE);
        let mut msd_figure = Grid::new(1, 2).title(format!(
            "⟨Δr²⟩/4t against t, {ics_msd} balls (bands ± SEM): finite horizon flat, infinite horizon ∝ ln t"
        ));
        for alpha in [0.0, 1.0] {
            let mut panel = LinePlot::with_axes(format!("α = {alpha}"), "time t", "⟨Δr²⟩/(4t)")
                .log_x(true)
                .log_y(true)
                .legend(Legend::UpperLeft);
            for (k, (name, gas)) in [(tri, triangular), (sq, square)].into_iter().enumerate() {
                let r = run(args, gas, alpha, ics_msd, &times)?;
                println!("  {name}, α = {alpha}: {}", r.estimate);
                msd_rows(&mut msd, name, &r);
                diffusion_row(&mut rows, name, &r);
                let label = format!("{name} ({} horizon)", r.horizon);
                panel = panel.series(apparent_d_series(&label, &r, palette(k)));
            }
            msd_figure.push(panel);
        }
        report.png("transport_msd.png", &msd_figure, (2000, 800))?;
        report.csv("diffusion.csv", &rows)?;
        report.csv("diffusion_windows.csv", &windows)?;
        report.csv("msd.csv", &msd)?;
        Ok(())
    })
}
