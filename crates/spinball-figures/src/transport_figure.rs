//! Figures of transport on a periodic table ([`DiffusionRun`]): the
//! diffusion coefficient against α with its error, how the estimate
//! depends on the fit window, and the running coefficient `⟨Δr²⟩/(4t)`
//! against `t` (flat for normal diffusion, growing like `ln t` for
//! marginal); and the CSV rows of each.

use spinball_analysis::open::DisplacementRecord;
use spinball_analysis::precision::Measurement;
use spinball_analysis::transport::{
    Diffusion, Displacements, Horizon, MeanSquareDisplacement, TransportError, WindowScan,
    diffusion, window_scan,
};
use spinball_plot::{LinePlot, RGBColor, Series};

use crate::csv::{Csv, optional};
use crate::measured::{ALPHA_LABEL, measured, measured_band};

/// Checkpoint times spaced evenly in `ln t`: `per_octave` per doubling,
/// ending at `t_end` and starting at the first at or after `t_first`.
/// Every halving window `[T/2^{k+1}, T/2^k]` of
/// [`window_scan`] then holds `per_octave + 1` checkpoints.
#[must_use]
pub fn log_times(t_first: f64, t_end: f64, per_octave: u32) -> Vec<f64> {
    let step = 2f64.powf(1.0 / f64::from(per_octave.max(1)));
    let mut times: Vec<f64> = std::iter::successors(Some(t_end), |t| Some(t / step))
        .take_while(|&t| t >= t_first * (1.0 - 1e-12))
        .collect();
    times.reverse();
    times
}

/// One ensemble on a periodic table analysed: its mean-square
/// displacement, the diffusion estimate on the default window (or the
/// marginal coefficient for an infinite horizon) and the window scan.
#[derive(Debug, Clone)]
pub struct DiffusionRun {
    /// The spin parameter.
    pub alpha: f64,
    /// The table's horizon.
    pub horizon: Horizon,
    /// `⟨Δr²⟩(t)` with its SEM.
    pub msd: MeanSquareDisplacement,
    /// The estimate on `[T/2, T]`.
    pub estimate: Diffusion,
    /// The estimate over the halving windows and its trend.
    pub scan: WindowScan,
}

impl DiffusionRun {
    /// Analyse the displacement `records` at checkpoint `times` of a table
    /// of the given `horizon`.
    ///
    /// # Errors
    /// As [`Displacements::new`], [`diffusion`] and [`window_scan`].
    pub fn new(
        alpha: f64,
        horizon: Horizon,
        times: &[f64],
        records: &[DisplacementRecord],
    ) -> Result<Self, TransportError> {
        let dr = DisplacementRecord::rows(records);
        let d = Displacements::new(times, &dr)?;
        Ok(DiffusionRun {
            alpha,
            horizon,
            msd: MeanSquareDisplacement::new(&d),
            estimate: diffusion(&d, horizon, None)?,
            scan: window_scan(&d, horizon)?,
        })
    }
}

/// `D ± SE` against α of the runs with a finite `D` (an infinite-horizon
/// run has none and is left out).
#[must_use]
pub fn diffusion_series(label: &str, runs: &[DiffusionRun]) -> Series {
    measured(
        label,
        runs.iter().filter_map(|r| {
            r.estimate
                .finite_d()
                .map(|d| (r.alpha, Measurement::new(d.value, d.error)))
        }),
    )
}

/// `D(α)` of `runs` ([`diffusion_series`]) on a log axis; the α whose
/// balls fly ballistically (no finite `D`) are named in the title.
#[must_use]
pub fn diffusion_panel(title: &str, label: &str, runs: &[DiffusionRun]) -> LinePlot {
    let ballistic: Vec<String> = runs
        .iter()
        .filter(|r| matches!(r.estimate, Diffusion::Ballistic(..)))
        .map(|r| r.alpha.to_string())
        .collect();
    let title = if ballistic.is_empty() {
        title.to_string()
    } else {
        format!(
            "{title}; no D at α = {} (ballistic balls)",
            ballistic.join(", ")
        )
    };
    LinePlot::with_axes(title, ALPHA_LABEL, "diffusion coefficient D")
        .log_y(true)
        .series(diffusion_series(label, runs).markers_only())
}

/// The window scan of `run`: the apparent `D` (slope of `⟨Δr²⟩` against
/// `4t`) of each halving window ± SE, at the window's geometric middle,
/// divided by the estimate on `[T/2, T]` so that runs of different α
/// share an axis.
#[must_use]
pub fn window_scan_series(label: &str, run: &DiffusionRun) -> Series {
    let reference = run.scan.apparent_d[0].coefficient;
    measured(
        label,
        run.scan.apparent_d.iter().map(|f| {
            (
                (f.window.t0 * f.window.t1).sqrt(),
                Measurement::new(f.coefficient / reference, f.sem / reference),
            )
        }),
    )
}

/// `⟨Δr²⟩/(4t)` of `run` against `t` with a band of ± one SEM.
#[must_use]
pub fn apparent_d_series(label: &str, run: &DiffusionRun, color: RGBColor) -> Series {
    measured_band(
        label,
        run.msd
            .points()
            .iter()
            .map(|p| (p.t, Measurement::new(p.apparent_d(), p.sem / (4.0 * p.t)))),
    )
    .line_only()
    .color(color)
}

/// The columns of [`diffusion_row`].
pub const DIFFUSION_COLUMNS: [&str; 12] = [
    "table",
    "alpha",
    "horizon",
    "law",
    "ics",
    "t0",
    "t1",
    "coefficient",
    "sem",
    "windows",
    "trend_per_ln_t",
    "trend_sem",
];

/// Append the estimate of `run` (on `table`) to `csv` (made with
/// [`DIFFUSION_COLUMNS`]): law `normal` (`D`), `marginal` (`D_m`) or
/// `ballistic` (no finite `D`; the coefficient of the fit over all balls), the
/// default window, and the trend of the window scan.
pub fn diffusion_row(csv: &mut Csv, table: &str, run: &DiffusionRun) {
    let fit = run.estimate.fit();
    let law = match run.estimate {
        Diffusion::Normal(_) => "normal",
        Diffusion::Marginal(_) => "marginal",
        Diffusion::Ballistic(..) => "ballistic",
    };
    csv.row(&[
        &table,
        &run.alpha,
        &run.horizon,
        &law,
        &fit.n_ics,
        &fit.window.t0,
        &fit.window.t1,
        &fit.coefficient,
        &fit.sem,
        &run.scan.apparent_d.len(),
        &optional(run.scan.trend.map(|t| t.per_ln_t)),
        &optional(run.scan.trend.map(|t| t.sem)),
    ]);
}

/// The columns of [`window_rows`].
pub const WINDOW_COLUMNS: [&str; 6] = ["table", "alpha", "t0", "t1", "apparent_d", "sem"];

/// Append the window scan of `run` (on `table`), one row per window, latest
/// first, to `csv` (made with [`WINDOW_COLUMNS`]).
pub fn window_rows(csv: &mut Csv, table: &str, run: &DiffusionRun) {
    for f in &run.scan.apparent_d {
        csv.row(&[
            &table,
            &run.alpha,
            &f.window.t0,
            &f.window.t1,
            &f.coefficient,
            &f.sem,
        ]);
    }
}

/// The columns of [`msd_rows`].
pub const MSD_COLUMNS: [&str; 5] = ["table", "alpha", "t", "msd", "sem"];

/// Append `⟨Δr²⟩(t)` of `run` (on `table`) to `csv` (made with
/// [`MSD_COLUMNS`]).
pub fn msd_rows(csv: &mut Csv, table: &str, run: &DiffusionRun) {
    for p in run.msd.points() {
        csv.row(&[&table, &run.alpha, &p.t, &p.msd, &p.sem]);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use spinball_analysis::transport::Trend;
    use spinball_geometry::DVec2;
    use spinball_plot::{Plot, palette};

    #[test]
    fn log_times_fill_every_halving_window() {
        let t = log_times(1.0, 64.0, 4);
        assert_eq!(t.len(), 25);
        assert!((t[0] - 1.0).abs() < 1e-12 && t[24] == 64.0);
        assert!((t[4] - 2.0).abs() < 1e-12);
        // [T/2, T] holds per_octave + 1 checkpoints.
        assert_eq!(t.iter().filter(|&&x| x >= 32.0 - 1e-9).count(), 5);
    }

    /// Records of deterministic paths with `|Δr|² = 4Dt` for every IC (so
    /// `D` is exact and the SE 0), turning a quarter turn at each
    /// checkpoint (so that no ball moves in a straight line, which the
    /// ballistic check would flag).
    fn exact_growth(times: &[f64], d: f64) -> Vec<DisplacementRecord> {
        (0..4u64)
            .map(|i| DisplacementRecord {
                index: i,
                displacement: times
                    .iter()
                    .enumerate()
                    .map(|(j, t)| {
                        let turn = (i as usize + j) % 4;
                        let r = (4.0 * d * t).sqrt();
                        [DVec2::X, DVec2::Y, -DVec2::X, -DVec2::Y][turn] * r
                    })
                    .collect(),
                collisions: 0,
                crossings: 0,
            })
            .collect()
    }

    #[test]
    fn runs_series_and_rows_of_exact_growth() {
        let times = log_times(1.0, 256.0, 4);
        let runs: Vec<DiffusionRun> = [(0.0, 0.1), (1.0, 0.02)]
            .into_iter()
            .map(|(alpha, d)| {
                DiffusionRun::new(alpha, Horizon::Finite, &times, &exact_growth(&times, d)).unwrap()
            })
            .collect();
        let d = runs[1].estimate.finite_d().unwrap();
        assert!((d.value - 0.02).abs() < 1e-12 && d.error < 1e-12);
        // |Δr|² = 4Dt exactly: no trend over the windows.
        let Trend { per_ln_t, .. } = runs[0].scan.trend.unwrap();
        assert!(per_ln_t.abs() < 1e-12);
        assert!(diffusion_panel("D", "D", &runs).validate().is_ok());
        let scan = window_scan_series("α = 0", &runs[0]);
        let lines =
            LinePlot::new()
                .series(scan)
                .series(apparent_d_series("α = 0", &runs[0], palette(0)));
        assert!(lines.validate().is_ok());
        // The same data on an infinite-horizon table: no finite D, no point.
        let marginal =
            DiffusionRun::new(0.0, Horizon::Infinite, &times, &exact_growth(&times, 0.1)).unwrap();
        assert!(marginal.estimate.finite_d().is_none());
        let mut csv = Csv::new(&DIFFUSION_COLUMNS);
        diffusion_row(&mut csv, "gas", &runs[0]);
        diffusion_row(&mut csv, "gas", &marginal);
        let rows: Vec<Vec<&str>> = csv
            .as_str()
            .lines()
            .skip(1)
            .map(|l| l.split(',').collect())
            .collect();
        assert_eq!(rows[0][3], "normal");
        assert_eq!(rows[1][3], "marginal");
        assert!((rows[0][7].parse::<f64>().unwrap() - 0.1).abs() < 1e-12);
        let mut windows = Csv::new(&WINDOW_COLUMNS);
        window_rows(&mut windows, "gas", &runs[0]);
        assert_eq!(windows.rows(), runs[0].scan.apparent_d.len());
        let mut msd = Csv::new(&MSD_COLUMNS);
        msd_rows(&mut msd, "gas", &runs[0]);
        assert_eq!(msd.rows(), times.len());
    }
}
