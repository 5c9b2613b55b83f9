//! Plot series of measured values (value ± standard error) and of the
//! paper's published values, and the axis labels of the λ(α) figures.
//!
//! Nearly every curve of the paper's figures is a list of `(x, value ±
//! SEM)`; building each from two parallel lists in every example repeats
//! the same zip. [`measured`] takes the pairs as
//! [`Measurement`]s and gives a [`Series`] with error bars;
//! [`paper_markers`] draws published numbers the same way in every figure
//! (large markers, no line).
//!
//! ```
//! use spinball_analysis::diagnostics;
//! use spinball_analysis::precision::Measurement;
//! use spinball_figures::{measured, paper_markers, ALPHA_LABEL};
//! use spinball_plot::{LinePlot, palette};
//!
//! let ours = [(0.0, Measurement::new(0.430, 0.002)), (1.0, Measurement::new(0.147, 0.002))];
//! let plot = LinePlot::new()
//!     .x_label(ALPHA_LABEL)
//!     .series(measured("stadium ± SEM", ours))
//!     .series(paper_markers("paper", diagnostics::STADIUM_LAMBDA, palette(6)));
//! # let _ = plot;
//! ```

use spinball_analysis::precision::Measurement;

use spinball_plot::{RGBColor, Series};

/// x-axis label of every λ(α) plot.
pub const ALPHA_LABEL: &str = "spin parameter α = I/(m r²)";

/// y-axis label of λ per unit time (E = ½, so |V| = 1: time in units of
/// length over that speed).
pub const LAMBDA_LABEL: &str = "λ (per unit time, E = ½)";

/// Points `(x, value)` with error bars `± sem`.
pub fn measured(
    label: impl Into<String>,
    points: impl IntoIterator<Item = (f64, Measurement)>,
) -> Series {
    let (xy, sem): (Vec<(f64, f64)>, Vec<f64>) = points
        .into_iter()
        .map(|(x, m)| ((x, m.value), m.sem))
        .unzip();
    Series::new(label, xy).errors(sem)
}

/// Points `(x, value)` with a shaded band `value ± sem` instead of error
/// bars (for dense curves).
pub fn measured_band(
    label: impl Into<String>,
    points: impl IntoIterator<Item = (f64, Measurement)>,
) -> Series {
    let points: Vec<(f64, Measurement)> = points.into_iter().collect();
    let lo = points.iter().map(|(_, m)| m.value - m.sem);
    let hi = points.iter().map(|(_, m)| m.value + m.sem);
    Series::new(label, points.iter().map(|&(x, m)| (x, m.value))).band(lo, hi)
}

/// `points` with value and error multiplied by `factor` (a change of unit:
/// fraction to percent, a rate relative to a reference).
pub fn scaled(
    points: impl IntoIterator<Item = (f64, Measurement)>,
    factor: f64,
) -> Vec<(f64, Measurement)> {
    points
        .into_iter()
        .map(|(x, m)| {
            (
                x,
                Measurement::new(factor * m.value, (factor * m.sem).abs()),
            )
        })
        .collect()
}

/// Published values drawn as large markers without a line.
pub fn paper_markers(
    label: impl Into<String>,
    points: impl IntoIterator<Item = (f64, f64)>,
    color: RGBColor,
) -> Series {
    Series::new(label, points)
        .markers_only()
        .marker_radius(7)
        .color(color)
}

#[cfg(test)]
mod tests {
    use super::*;
    use spinball_plot::{LinePlot, Plot, PlotError};

    #[test]
    fn measured_points_keep_their_errors() {
        let pts = [
            (0.0, Measurement::new(1.0, 0.1)),
            (1.0, Measurement::new(2.0, 0.2)),
        ];
        let s = scaled(pts, 100.0);
        assert_eq!(s[1], (1.0, Measurement::new(200.0, 20.0)));
        assert_eq!(scaled(pts, -2.0)[0].1, Measurement::new(-2.0, 0.2));
        let plot = LinePlot::new()
            .series(measured("m", pts))
            .series(measured_band("b", pts))
            .series(paper_markers("p", [(0.5, 1.5)], RGBColor(0, 0, 0)));
        assert!(plot.validate().is_ok());
        // Only non-finite data: nothing to draw.
        let empty = LinePlot::new().series(measured("m", [(f64::NAN, Measurement::new(1.0, 0.1))]));
        assert!(matches!(empty.validate(), Err(PlotError::EmptyData(_))));
    }
}
