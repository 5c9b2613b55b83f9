//! The paper's energy-conservation figure (appendix "Energy
//! conservation"): per table a panel of `|Eₙ − E₀|` per collision and a
//! panel of the largest relative deviation over a long run, beside the
//! paper's formulas in components (dashed), one colour per α; and their
//! CSV rows.
//!
//! Exact zeros (a collision that returns the start's energy to the last
//! bit) cannot be drawn on a log axis; they are drawn on a floor line at
//! [`ENERGY_FLOOR`].

use spinball_analysis::diagnostics::{EnergyConservation, EnergyHistory, EnergyTrace};

use crate::csv::Csv;
use spinball_plot::{Legend, LineKind, LinePlot, Series};
use spinball_plot::{RGBColor, viridis};

/// Where exact zeros are drawn on the log axes.
pub const ENERGY_FLOOR: f64 = 1e-18;

/// The columns of [`energy_trace_rows`].
pub const ENERGY_TRACE_COLUMNS: [&str; 4] = ["table", "alpha", "n", "abs_dE"];

/// The columns of [`energy_long_rows`].
pub const ENERGY_LONG_COLUMNS: [&str; 5] = [
    "table",
    "alpha",
    "n",
    "max_rel_dE",
    "paper_formulas_max_rel_dE",
];

/// Append one row per point of `trace` (of `table` at `alpha`) to `csv`
/// (made with [`ENERGY_TRACE_COLUMNS`]), the deviation in exponent form.
pub fn energy_trace_rows(csv: &mut Csv, table: &str, alpha: f64, trace: &EnergyTrace) {
    for p in &trace.points {
        csv.row(&[&table, &alpha, &p.collisions, &format!("{:e}", p.deviation)]);
    }
}

/// Append one row per checkpoint of the long runs of `check` (of `table`
/// at `alpha`) to `csv` (made with [`ENERGY_LONG_COLUMNS`]): the library's
/// and the component formulas' largest relative deviation so far, in
/// exponent form.
pub fn energy_long_rows(csv: &mut Csv, table: &str, alpha: f64, check: &EnergyConservation) {
    for (p, q) in check.library.points.iter().zip(&check.components.points) {
        let (a, b) = (p.max_relative_deviation, q.max_relative_deviation);
        csv.row(&[
            &table,
            &alpha,
            &p.collisions,
            &format!("{a:e}"),
            &format!("{b:e}"),
        ]);
    }
}

/// `max |ΔE|/E₀` up to each checkpoint, floored at [`ENERGY_FLOOR`].
fn floored(history: &EnergyHistory) -> Vec<(f64, f64)> {
    let points = history.points.iter();
    points
        .map(|p| {
            (
                p.collisions as f64,
                p.max_relative_deviation.max(ENERGY_FLOOR),
            )
        })
        .collect()
}

/// The two panels of one table: the per-collision trace and the long run.
#[derive(Debug, Clone)]
pub struct EnergyPanels {
    /// `|Eₙ − E₀|` per collision, dots per α.
    pub trace: LinePlot,
    /// `max |ΔE|/E₀` up to `n`, a solid line (library) and a dashed one
    /// (paper eqs. 1–3) per α.
    pub long: LinePlot,
}

impl EnergyPanels {
    /// Empty panels titled `title` (the table), with the reference lines:
    /// `ε·E₀` (E₀ = ½) on the trace, `ε` on the long run, and the floor.
    #[must_use]
    pub fn new(title: &str) -> Self {
        let trace = LinePlot::with_axes(title, "collision number n", "|Eₙ − E₀|")
            .log_y(true)
            .y_range(ENERGY_FLOOR / 3.0, 1e-13)
            .hline(f64::EPSILON * 0.5, "ε·E₀")
            .hline(ENERGY_FLOOR, "exact 0");
        // A legend entry for the dashed curves (its one point is clipped).
        let dashed = Series::new("dashed: paper eqs. 1–3", [(1.0, ENERGY_FLOOR / 3.0)])
            .line_only()
            .kind(LineKind::Dashed)
            .color(RGBColor(60, 60, 60));
        let long = LinePlot::with_axes(title, "collisions n", "max |ΔE|/E₀ up to n")
            .log_x(true)
            .log_y(true)
            .y_range(ENERGY_FLOOR / 3.0, 1e-9)
            .legend(Legend::UpperLeft)
            .hline(f64::EPSILON, "ε")
            .hline(ENERGY_FLOOR, "exact 0")
            .series(dashed);
        EnergyPanels { trace, long }
    }

    /// Add `check`, the run at `alpha`, the `k`-th of `count` values of α
    /// (its colour; later series are drawn over earlier ones, so their
    /// markers shrink to keep every α visible).
    #[must_use]
    pub fn add(self, k: usize, count: usize, alpha: f64, check: &EnergyConservation) -> Self {
        let color = viridis(k as f64 / count.saturating_sub(1).max(1) as f64 * 0.85);
        let label = format!("α = {alpha}");
        let trace = check.trace.points.iter();
        let dots = trace.map(|p| (p.collisions as f64, p.deviation.max(ENERGY_FLOOR)));
        let dots = Series::new(label.clone(), dots)
            .markers_only()
            .marker_radius(4 - k.min(3) as u32)
            .color(color);
        let dashed = Series::unlabelled(floored(&check.components))
            .line_only()
            .kind(LineKind::Dashed)
            .color(color);
        EnergyPanels {
            trace: self.trace.series(dots),
            long: self
                .long
                .series(Series::new(label, floored(&check.library)).color(color))
                .series(dashed),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use spinball_analysis::diagnostics::energy_conservation;
    use spinball_core::{Billiard, SpinLaw, State};
    use spinball_geometry::{DVec2, Stadium};
    use spinball_plot::Plot;

    #[test]
    fn rows_and_panels_of_one_start() {
        let billiard = Billiard::new(Stadium::new(1.0).unwrap(), SpinLaw::new(0.3).unwrap());
        let start = State::new(DVec2::new(0.3, 0.2), DVec2::from_angle(0.8), 0.0);
        let check = energy_conservation(&billiard, start, 50, 1_000).unwrap();
        let mut trace = Csv::new(&ENERGY_TRACE_COLUMNS);
        energy_trace_rows(&mut trace, "stadium:a=1", 0.3, &check.trace);
        assert_eq!(trace.rows(), 50);
        let row: Vec<&str> = trace.as_str().lines().nth(7).unwrap().split(',').collect();
        assert_eq!(row[..3], ["stadium:a=1", "0.3", "7"]);
        assert_eq!(
            row[3].parse::<f64>().unwrap(),
            check.trace.points[6].deviation
        );
        let mut long = Csv::new(&ENERGY_LONG_COLUMNS);
        energy_long_rows(&mut long, "stadium:a=1", 0.3, &check);
        // Checkpoints 1, 2, 5, …, 500, 1000.
        assert_eq!(long.rows(), 10);
        let last: Vec<&str> = long.as_str().lines().last().unwrap().split(',').collect();
        assert_eq!(last[2], "1000");
        let lib = last[3].parse::<f64>().unwrap();
        assert_eq!(lib, check.library.max_relative_deviation());
        assert_eq!(
            last[4].parse::<f64>().unwrap(),
            check.components.max_relative_deviation()
        );
        let panels = EnergyPanels::new("stadium")
            .add(0, 2, 0.3, &check)
            .add(1, 2, 0.3, &check);
        assert!(panels.trace.validate().is_ok() && panels.long.validate().is_ok());
        assert_eq!(floored(&check.library).len(), 10);
        assert!(floored(&check.library).iter().all(|p| p.1 >= ENERGY_FLOOR));
    }
}
