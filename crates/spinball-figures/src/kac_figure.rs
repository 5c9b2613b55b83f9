//! Figures of return times against Kac's lemma ([`KacComparison`]): the
//! per-orbit histogram of mean return time over `1/μ(A)`, the mean ratio
//! against α, and the CSV rows per comparison and per orbit.

use spinball_analysis::phase_space::KacComparison;

use crate::csv::{Csv, optional};
use spinball_plot::RGBColor;
use spinball_plot::{HistogramPlot, Marker, Series};

/// The columns of [`kac_row`].
pub const KAC_COLUMNS: [&str; 11] = [
    "table",
    "region",
    "alpha",
    "mu",
    "kac",
    "mean_return",
    "sem",
    "ratio",
    "ratio_sem",
    "never_returned",
    "orbits",
];

/// The columns of [`kac_orbit_rows`].
pub const KAC_ORBIT_COLUMNS: [&str; 6] =
    ["table", "alpha", "orbit", "visits", "mean_return", "ratio"];

/// Append the summary of `kac` (of `table`, region named `region`) to
/// `csv` (made with [`KAC_COLUMNS`]); no mean return or ratio leaves the
/// fields empty.
pub fn kac_row(csv: &mut Csv, table: &str, region: &str, kac: &KacComparison) {
    let (mean, ratio) = (kac.mean_return, kac.ratio());
    csv.row(&[
        &table,
        &region,
        &kac.alpha,
        &kac.probability,
        &kac.expected,
        &optional(mean.map(|m| m.value)),
        &optional(mean.map(|m| m.sem)),
        &optional(ratio.map(|r| r.value)),
        &optional(ratio.map(|r| r.sem)),
        &kac.never_returned,
        &kac.orbits.len(),
    ]);
}

/// Append one row per orbit of `kac` (of `table`) to `csv` (made with
/// [`KAC_ORBIT_COLUMNS`]): its visits, mean return time and ratio to Kac's
/// (empty for an orbit that never returned).
pub fn kac_orbit_rows(csv: &mut Csv, table: &str, kac: &KacComparison) {
    for o in &kac.orbits {
        let ratio = o.mean_return.map(|m| m / kac.expected);
        csv.row(&[
            &table,
            &kac.alpha,
            &o.index,
            &o.visits,
            &optional(o.mean_return),
            &optional(ratio),
        ]);
    }
}

/// The returning orbits' ratios to Kac's in 30 bins over `[0, 2]` with a
/// line at 1, titled `table`, α and how many orbits never came back.
#[must_use]
pub fn kac_histogram(table: &str, kac: &KacComparison, color: RGBColor) -> HistogramPlot {
    HistogramPlot::new(kac.orbit_ratios())
        .bins(30)
        .range(0.0, 2.0)
        .title(format!(
            "{table} α = {} ({} never back)",
            kac.alpha, kac.never_returned
        ))
        .x_label("return time / Kac")
        .color(color)
        .marker(Marker::new("Kac", 1.0))
}

/// The mean ratio to Kac's ± SEM against α of `runs`, skipping those
/// without a ratio.
#[must_use]
pub fn kac_ratio_series(label: &str, runs: &[KacComparison]) -> Series {
    let points: Vec<_> = runs
        .iter()
        .filter_map(|k| k.ratio().map(|r| (k.alpha, r)))
        .collect();
    Series::new(label, points.iter().map(|(a, r)| (*a, r.value)))
        .errors(points.iter().map(|(_, r)| r.sem))
}

#[cfg(test)]
mod tests {
    use super::*;
    use spinball_analysis::phase_space::{SectionBox, kac_comparison};
    use spinball_analysis::run::Threads;
    use spinball_core::{Billiard, SpinLaw};
    use spinball_geometry::Stadium;
    use spinball_plot::Plot;

    #[test]
    fn rows_histogram_and_ratio_of_a_stadium_run() {
        let billiard = Billiard::new(Stadium::new(1.0).unwrap(), SpinLaw::new(0.5).unwrap());
        let cap = SectionBox::new(2.0..2.0 + std::f64::consts::PI, -1.0..1.0);
        let kac = kac_comparison(&billiard, &cap, 6, 2_000, 1, Threads::Fixed(1)).unwrap();
        let mut csv = Csv::new(&KAC_COLUMNS);
        kac_row(&mut csv, "stadium", "right cap", &kac);
        let row: Vec<&str> = csv.as_str().lines().nth(1).unwrap().split(',').collect();
        assert_eq!(row[..3], ["stadium", "right cap", "0.5"]);
        // μ(A) of the right cap: its share of the perimeter 4 + 2π, as
        // fig_kac prints (0.3055).
        let mu = row[3].parse::<f64>().unwrap();
        assert!((mu - 0.3055).abs() < 1e-4, "{mu}");
        let ratio = kac.ratio().unwrap();
        assert_eq!(row[7].parse::<f64>().unwrap(), ratio.value);
        assert_eq!(row[10], "6");
        let mut orbits = Csv::new(&KAC_ORBIT_COLUMNS);
        kac_orbit_rows(&mut orbits, "stadium", &kac);
        assert_eq!(orbits.rows(), 6);
        let first: Vec<&str> = orbits.as_str().lines().nth(1).unwrap().split(',').collect();
        let o = kac.orbits[0];
        assert_eq!(first[3].parse::<u64>().unwrap(), o.visits);
        let r = first[5].parse::<f64>().unwrap();
        assert_eq!(r, o.mean_return.unwrap() / kac.expected);
        assert!(
            kac_histogram("stadium", &kac, RGBColor(0, 0, 0))
                .validate()
                .is_ok()
        );
        let series = kac_ratio_series("stadium", std::slice::from_ref(&kac));
        let plot = spinball_plot::LinePlot::new().series(series);
        assert!(plot.validate().is_ok());
    }
}
