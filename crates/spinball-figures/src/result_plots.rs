//! Plot pieces made from analysis results: the paper's FTLE histogram
//! panel, Lyapunov spectra against α (one panel, or the paper's grid of
//! exact and finite-difference spectra), and the counts of a log-binned
//! analysis histogram as points.
//!
//! These pictures recur (every FTLE figure shows a distribution with its
//! mean, median and conditional mean; every |ΔQ| plot shows log-binned
//! counts with exact zeros set apart), so they are built here from the
//! analysis types rather than by hand in each example.
//!
//! ```
//! use spinball_analysis::run::Ensemble;
//! use spinball_core::SpinLaw;
//! use spinball_geometry::Stadium;
//! use spinball_figures::ftle_histogram;
//! use spinball_plot::Plot;
//!
//! let e = Ensemble::new(Stadium::new(1.0)?, SpinLaw::new(0.5)?)
//!     .with_ics(16)
//!     .with_collisions(1_000)
//!     .run()?;
//! assert!(ftle_histogram(&e)?.validate().is_ok());
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use spinball_analysis::AnalysisError;
use spinball_analysis::run::{LyapunovEstimate, SpectrumEstimate};

use spinball_plot::{
    Grid, HistogramPlot, Legend, LineKind, LinePlot, Marker, RGBColor, Series, palette,
};

/// Subscripts of the five exponents.
const SUB: [&str; 5] = ["₁", "₂", "₃", "₄", "₅"];

/// The spectra of one table at one α: `[exact tangent, finite
/// differences]`.
pub type SpectrumPair = (f64, [SpectrumEstimate; 2]);

/// The rows of [`spectrum_grid`]: what they show, which exponents, and
/// whether of the finite-difference spectra.
const SPECTRUM_VIEWS: [(&str, &[usize], bool); 4] = [
    ("exact tangent: λ₁ … λ₅", &[0, 1, 2, 3, 4], false),
    ("exact tangent: middle three, enlarged", &[1, 2, 3], false),
    ("finite differences: leading four", &[0, 1, 2, 3], true),
    (
        "finite differences: fifth (collapsed flow direction)",
        &[4],
        true,
    ),
];

/// The FTLE distribution of `estimate` as a probability density (60 bins)
/// with the paper's three lines: mean (solid), median (dashed) and, if any
/// trajectory is chaotic, the conditional mean of the chaotic part
/// (dotted); titled with α, the standard deviation and the chaotic fraction.
///
/// # Errors
/// Only for an estimate whose trajectories were emptied or altered.
pub fn ftle_histogram(estimate: &LyapunovEstimate) -> Result<HistogramPlot, AnalysisError> {
    let e = estimate;
    let ftle = e.ftle()?;
    let title = format!(
        "α = {}   (std {:.3}, f_ch {:.1} %)",
        e.alpha(),
        e.std(),
        100.0 * e.chaotic_fraction()
    );
    let median = Marker::new(format!("median {:.3}", e.median()), e.median())
        .color(RGBColor(0, 90, 200))
        .kind(LineKind::Dashed);
    let mut h = HistogramPlot::new(ftle.exponents().iter().copied())
        .bins(60)
        .density(true)
        .title(title)
        .x_label("FTLE λ (1/time)")
        .y_label("probability density")
        .color(RGBColor(150, 170, 200))
        .legend(Legend::UpperLeft)
        .marker(Marker::new(format!("mean {:.3}", e.mean()), e.mean()).color(RGBColor(0, 0, 0)))
        .marker(median);
    if let Some(cm) = e.conditional_mean() {
        let marker = Marker::new(format!("cond. mean {cm:.3}"), cm)
            .color(RGBColor(0, 150, 60))
            .kind(LineKind::Dotted);
        h = h.marker(marker);
    }
    Ok(h)
}

/// The exponents `slots` (0 to 4: λ₁ … λ₅) of spectrum estimates against
/// α, mean ± SEM, one series per exponent labelled `λᵢ` plus `suffix` and
/// coloured by its index; the y axis names the exponents when there are at
/// most three.
pub fn spectrum_plot(
    title: impl Into<String>,
    points: &[(f64, &SpectrumEstimate)],
    slots: &[usize],
    suffix: &str,
) -> LinePlot {
    let names: Vec<String> = slots.iter().map(|&k| format!("λ{}", SUB[k])).collect();
    let y = match slots.len() {
        1..=3 => format!("{} (1/time)", names.join(", ")),
        _ => "λᵢ (1/time)".to_string(),
    };
    let mut plot = LinePlot::with_axes(title, "spin parameter α", y);
    for (&k, name) in slots.iter().zip(&names) {
        let values = points.iter().map(|(a, e)| (*a, e.mean[k]));
        let series = Series::new(format!("{name}{suffix}"), values)
            .errors(points.iter().map(|(_, e)| e.sem[k]))
            .color(palette(k))
            .marker_radius(4);
        plot = plot.series(series);
    }
    plot
}

/// The paper's spectrum figure: a column per table (`(title, spectra
/// against α)`) and four rows, the exact spectrum, its middle three
/// enlarged, the finite-difference leading four (with the exact `±λ₁`
/// dashed) and the finite-difference fifth exponent.
#[must_use]
pub fn spectrum_grid(title: impl Into<String>, tables: &[(&str, &[SpectrumPair])]) -> Grid {
    let grey = RGBColor(90, 90, 90);
    let mut grid = Grid::new(SPECTRUM_VIEWS.len(), tables.len()).title(title);
    for (r, (what, slots, fd)) in SPECTRUM_VIEWS.into_iter().enumerate() {
        for (name, points) in tables {
            let column: Vec<_> = points
                .iter()
                .map(|(a, e)| (*a, &e[usize::from(fd)]))
                .collect();
            let suffix = if fd { " (fd)" } else { "" };
            let plot = spectrum_plot(format!("{name}: {what}"), &column, slots, suffix);
            let exact = |k: usize| points.iter().map(move |(a, e)| (*a, e[0].mean[k]));
            let dashed = |s: Series| s.line_only().kind(LineKind::Dashed).color(grey);
            grid.push(match r {
                0 => plot.hline(0.0, "").y_range(-0.5, 0.85),
                1 => plot.hline(0.0, ""),
                2 => plot
                    .series(dashed(Series::new("exact ±λ₁", exact(0))))
                    .series(dashed(Series::unlabelled(exact(4))))
                    .hline(0.0, "")
                    .y_range(-0.5, 0.85),
                _ => plot.legend(Legend::LowerLeft),
            });
        }
    }
    grid
}

/// The counts of `histogram` (binned in some `log10 x`) as `(bin centre,
/// count)` points from its first to its last occupied bin; the underflow
/// (exact zeros and values below the bins) as a separate point at
/// `zero_at`, kept apart from the rest by a break in the line.
pub fn log_counts(
    histogram: &spinball_analysis::estimators::Histogram,
    zero_at: f64,
) -> Vec<(f64, f64)> {
    let counts = histogram.counts();
    let mut pts = Vec::new();
    if histogram.underflow() > 0 {
        pts.extend([
            (zero_at, histogram.underflow() as f64),
            (f64::NAN, f64::NAN),
        ]);
    }
    let first = counts.iter().position(|&c| c > 0);
    let last = counts.iter().rposition(|&c| c > 0);
    if let (Some(a), Some(b)) = (first, last) {
        pts.extend((a..=b).map(|i| (histogram.center(i), counts[i] as f64)));
    }
    pts
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spectra_against_alpha() {
        use spinball_analysis::estimators::{Method, SpectrumOptions};
        use spinball_analysis::run::{Threads, spectrum_ensemble};
        use spinball_core::{Billiard, Sampler, SpinLaw};
        use spinball_plot::Plot;
        let run = |alpha| {
            let billiard = Billiard::new(
                spinball_geometry::Stadium::new(1.0).unwrap(),
                SpinLaw::new(alpha).unwrap(),
            );
            let options = SpectrumOptions::new(200, Method::Tangent);
            spectrum_ensemble(
                &billiard,
                Sampler::Paper,
                1,
                0..2,
                &options,
                Threads::Fixed(1),
            )
            .unwrap()
        };
        let (a, b) = (run(0.0), run(1.0));
        let plot = spectrum_plot("t", &[(0.0, &a), (1.0, &b)], &[1, 2, 3], " (x)");
        assert!(plot.validate().is_ok());
        assert!(spectrum_plot("t", &[], &[0], "").validate().is_err());
        let pairs = [(0.0, [a.clone(), a]), (1.0, [b.clone(), b])];
        let grid = spectrum_grid("spectra", &[("one", &pairs), ("two", &pairs[..1])]);
        assert!(grid.validate().is_ok());
        // Four rows of two tables, row by row.
        let text = format!("{grid:?}");
        let at = |t: &str| text.find(t).unwrap_or_else(|| panic!("no panel {t}"));
        assert!(at("one: exact tangent: λ₁ … λ₅") < at("two: exact tangent: λ₁ … λ₅"));
        assert!(at("two: exact tangent: λ₁ … λ₅") < at("one: exact tangent: middle three"));
        assert!(at("two: finite differences: leading four") < at("one: finite differences: fifth"));
        assert_eq!(text.matches("exact ±λ₁").count(), 2);
        assert_eq!(text.matches("λ₅ (fd)").count(), 2);
    }

    #[test]
    fn log_counts_set_zeros_apart() {
        let mut h = spinball_analysis::estimators::Histogram::new(-4.0, 0.0, 4).unwrap();
        for x in [f64::NEG_INFINITY, -10.0, -2.5, -2.2, -0.5] {
            h.push(x);
        }
        let pts = log_counts(&h, -5.0);
        assert_eq!(pts[0], (-5.0, 2.0));
        assert!(pts[1].0.is_nan() && pts[1].1.is_nan());
        // Bins -3..-2 (two values), -2..-1 (none), -1..0 (one).
        assert_eq!(&pts[2..], &[(-2.5, 2.0), (-1.5, 0.0), (-0.5, 1.0)]);
        let empty = spinball_analysis::estimators::Histogram::new(-4.0, 0.0, 4).unwrap();
        assert!(log_counts(&empty, -5.0).is_empty());
    }
}
