//! The paper's conserved-quantity figure (appendix C) of one run's
//! [`QPairStatistics`]: `|ΔQ|` between consecutive collisions per
//! [`PairClass`] (left panel), what is conserved to rounding (right panel),
//! a summary line per class, and the histograms as CSV.
//!
//! `|ΔQ|` is binned in `log10`; exact zeros cannot be drawn on that axis and
//! are drawn at [`Q_ZERO_AT`] instead, apart from the rest.

use spinball_analysis::diagnostics::{PairClass, QPairStatistics};

use crate::csv::Csv;
use crate::result_plots::log_counts;
use crate::result_tables::{histograms_csv, q_populations};
use spinball_plot::RGBColor;
use spinball_plot::{Legend, LineKind, LinePlot, Series};

/// Where exact zeros are drawn (`log10 |ΔQ|`).
pub const Q_ZERO_AT: f64 = -19.5;

const BLUE: RGBColor = RGBColor(0, 114, 178);
const ORANGE: RGBColor = RGBColor(230, 159, 0);
const GREEN: RGBColor = RGBColor(0, 158, 115);

/// The classes in the order of [`PairClass::ALL`], with their legend text
/// and colour.
const CLASSES: [(&str, RGBColor); 3] = [
    ("same wall (cap → same cap)", BLUE),
    ("facing walls (flat ↔ flat)", ORANGE),
    (
        "tangent turns (flat ↔ cap, cap → cap)",
        RGBColor(213, 94, 0),
    ),
];

/// The right panel's curves: `Q` through a collision, the facing-wall
/// residual, the same-wall pairs.
const CONSERVED: [(&str, RGBColor, LineKind); 3] = [
    (
        "|Q after − Q before| through a collision",
        GREEN,
        LineKind::Solid,
    ),
    ("|ΔQ + 2v∥|, facing walls", ORANGE, LineKind::Dashed),
    ("|ΔQ|, same wall", BLUE, LineKind::Dotted),
];

/// The legend text of `class` in `q`: name, count and share in percent
/// (`same wall (cap → same cap): 412 (21 %)`).
fn class_label(q: &QPairStatistics, class: PairClass, name: &str) -> String {
    let share = 100.0 * q.share(class).unwrap_or(0.0);
    format!("{name}: {} ({share:.0} %)", q.population(class).count)
}

/// One line per class: its legend text, the median and the largest `|ΔQ|`
/// (`NaN` for a class without pairs).
#[must_use]
pub fn q_class_summaries(q: &QPairStatistics) -> Vec<String> {
    let classes = PairClass::ALL.into_iter().zip(CLASSES);
    classes
        .map(|(class, (name, _))| {
            let p = q.population(class);
            let median = p.median().unwrap_or(f64::NAN);
            let label = class_label(q, class, name);
            format!("{label:<48} median |ΔQ| {median:.1e}, max {:.1e}", p.max)
        })
        .collect()
}

/// The left panel: pairs per quarter decade of `|ΔQ|`, one curve per class.
#[must_use]
pub fn q_class_panel(q: &QPairStatistics) -> LinePlot {
    let title = format!(
        "|ΔQ| between consecutive collisions ({} pairs)",
        q.pair_count()
    );
    let x = "log₁₀ |ΔQ|   (exact zeros at −19.5)";
    let plot = LinePlot::with_axes(title, x, "pairs per quarter decade")
        .x_range(-20.0, 1.5)
        .legend(Legend::UpperMiddle);
    let classes = PairClass::ALL.into_iter().zip(CLASSES);
    classes.fold(plot, |plot, (class, (name, color))| {
        let points = log_counts(&q.population(class).log10, Q_ZERO_AT);
        plot.series(Series::new(class_label(q, class, name), points).color(color))
    })
}

/// The right panel, what is conserved to rounding: `Q` through each
/// collision, `|ΔQ + 2v∥|` of the facing walls and the same-wall pairs.
#[must_use]
pub fn q_conserved_panel(q: &QPairStatistics) -> LinePlot {
    let x = "log₁₀ |·|   (exact zeros at −19.5)";
    let plot = LinePlot::with_axes(
        "What is conserved to rounding",
        x,
        "count per quarter decade",
    )
    .x_range(-20.0, -12.0)
    .legend(Legend::UpperRight);
    let same_wall = q.population(PairClass::SameWall);
    let conserved = [&q.through_collision, &q.facing_residual, same_wall];
    let curves = conserved.into_iter().zip(CONSERVED);
    curves.fold(plot, |plot, (p, (label, color, kind))| {
        let points = log_counts(&p.log10, Q_ZERO_AT);
        plot.series(Series::new(label, points).color(color).kind(kind))
    })
}

/// The `log10` histograms of the five populations of [`q_populations`]
/// (see [`histograms_csv`]).
#[must_use]
pub fn q_histograms_csv(q: &QPairStatistics) -> Csv {
    let named = q_populations(q);
    let hists: Vec<_> = named.iter().map(|(n, p)| (*n, &p.log10)).collect();
    histograms_csv("log10", &hists)
}

/// The median `|ΔQ|` of each of the five populations of [`q_populations`],
/// by name (`None` for an empty one).
#[must_use]
pub fn q_medians(q: &QPairStatistics) -> Vec<(&'static str, Option<f64>)> {
    let named = q_populations(q);
    named.iter().map(|(n, p)| (*n, p.median())).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use spinball_analysis::diagnostics::q_pair_statistics;
    use spinball_core::{Billiard, Sampler, SpinLaw};
    use spinball_geometry::Stadium;
    use spinball_plot::Plot;

    #[test]
    fn panels_summaries_and_histograms_of_a_stadium_run() {
        let billiard = Billiard::new(Stadium::new(1.0).unwrap(), SpinLaw::new(0.5).unwrap());
        let start = Sampler::Paper.initial_state(billiard.table(), billiard.law(), 1, 0);
        let q = q_pair_statistics(&billiard, start, 2_000, false).unwrap();
        let lines = q_class_summaries(&q);
        assert_eq!(lines.len(), 3);
        let same = q.population(PairClass::SameWall);
        let share = 100.0 * same.count as f64 / 1_999.0;
        let head = format!("same wall (cap → same cap): {} ({share:.0} %)", same.count);
        assert!(lines[0].starts_with(&head), "{}", lines[0]);
        // Same-cap pairs keep Q to rounding: the printed max is ~1e-16.
        assert!(same.max < 1e-13, "{}", same.max);
        assert!(lines[0].ends_with(&format!("max {:.1e}", same.max)));
        assert!(q_class_panel(&q).validate().is_ok());
        assert!(q_conserved_panel(&q).validate().is_ok());
        let medians = q_medians(&q);
        assert_eq!(
            medians[2],
            ("turned", q.population(PairClass::Turned).median())
        );
        assert_eq!(medians[3].0, "through_collision");
        // Per population an underflow row and one per bin, whose counts add
        // up to the population's count.
        let csv = q_histograms_csv(&q);
        let bins = q.through_collision.log10.counts().len();
        assert_eq!(csv.rows(), 5 * (bins + 1));
        let turned: u64 = csv
            .as_str()
            .lines()
            .filter(|l| l.starts_with("turned,"))
            .map(|l| l.rsplit(',').next().unwrap().parse::<u64>().unwrap())
            .sum();
        assert_eq!(turned, q.population(PairClass::Turned).count);
    }
}
