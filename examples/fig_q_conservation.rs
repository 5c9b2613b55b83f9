//! The paper's conserved-quantity figure (appendix C): `|ΔQ| = |Q_{n+1} − Q_n|`
//! between consecutive collisions in the stadium (a = 1) at α = 0.5, by what
//! the two walls have in common (`spinball_analysis::PairClass`): the same
//! cap twice (`ΔQ = 0` to rounding, the circle's angular momentum), facing
//! flats (opposite oriented tangents, `ΔQ = −2v∥` exactly) and turned
//! tangents (flat ↔ cap, cap → other cap: `O(1)`). The right panel shows
//! what is at machine precision: `Q` through each collision, `ΔQ + 2v∥` for
//! facing walls, and the same-wall pairs again.
//!
//! ```text
//! cargo run --release --example fig_q_conservation -- [--quick | --paper] [--out DIR] [--seed N]
//! ```
//!
//! One trajectory (paper sampler, initial condition 0 of the seed), 2000
//! collisions with `--quick`, 10⁴ (the paper's) otherwise. Writes
//! `q_conservation.png`, `q_pairs.csv` (every pair), `q_histogram.csv`
//! (counts per quarter decade) and `q_conservation.json`
//! (`QPairStatistics` without the pairs, medians, and the wall-transition
//! fractions under the three rules of `WallStatistics`).

use std::process::ExitCode;

use serde_json::json;
use spinball_analysis::{PairClass, TransitionRule as Rule, q_pair_statistics, wall_statistics};
use spinball_core::{Billiard, Sampler, SpinLaw};
use spinball_geometry::Stadium;
use spinball_plot::{
    Grid, Legend, LineKind, LinePlot, RGBColor, Series, histograms_csv, log_counts, q_pairs_csv,
    q_populations, run_figure,
};

const NAME: &str = "fig_q_conservation";
const ABOUT: &str =
    "|ΔQ| between consecutive collisions by pair class, stadium a = 1, α = 0.5 (paper appendix C).";
const ALPHA: f64 = 0.5;
/// Where exact zeros are drawn (log10 |ΔQ|).
const ZERO_AT: f64 = -19.5;
const X_LEFT: &str = "log₁₀ |ΔQ|   (exact zeros at −19.5)";
const X_RIGHT: &str = "log₁₀ |·|   (exact zeros at −19.5)";
const BLUE: RGBColor = RGBColor(0, 114, 178);
const ORANGE: RGBColor = RGBColor(230, 159, 0);
const GREEN: RGBColor = RGBColor(0, 158, 115);
/// The right panel: what is conserved to rounding.
const CONSERVED: [(&str, RGBColor, LineKind); 3] = [
    (
        "|Q after − Q before| through a collision",
        GREEN,
        LineKind::Solid,
    ),
    ("|ΔQ + 2v∥|, facing walls", ORANGE, LineKind::Dashed),
    ("|ΔQ|, same wall", BLUE, LineKind::Dotted),
];
const CLASSES: [(PairClass, &str, RGBColor); 3] = [
    (PairClass::SameWall, "same wall (cap → same cap)", BLUE),
    (PairClass::FacingWalls, "facing walls (flat ↔ flat)", ORANGE),
    (
        PairClass::Turned,
        "tangent turns (flat ↔ cap, cap → cap)",
        RGBColor(213, 94, 0),
    ),
];

fn main() -> ExitCode {
    run_figure(NAME, ABOUT, |args, report| {
        let collisions: u64 = args.pick(2_000, 10_000, 10_000);
        let billiard = Billiard::new(Stadium::new(1.0)?, SpinLaw::new(ALPHA)?);
        let start = Sampler::Paper.initial_state(billiard.table(), billiard.law(), args.seed, 0);
        let q = q_pair_statistics(&billiard, start, collisions, true)?;
        let walls = wall_statistics(&billiard, start, collisions)?;

        let n = q.pair_count();
        let title = format!("|ΔQ| between consecutive collisions ({n} pairs)");
        let mut left = LinePlot::with_axes(title, X_LEFT, "pairs per quarter decade")
            .x_range(-20.0, 1.5)
            .legend(Legend::UpperMiddle);
        for (class, label, color) in CLASSES {
            let (p, share) = (q.population(class), 100.0 * q.share(class).unwrap_or(0.0));
            let label = format!("{label}: {} ({share:.0} %)", p.count);
            let median = p.median().unwrap_or(f64::NAN);
            println!("  {label:<48} median |ΔQ| {median:.1e}, max {:.1e}", p.max);
            left = left.series(Series::new(label, log_counts(&p.log10, ZERO_AT)).color(color));
        }
        let same_wall = q.population(PairClass::SameWall);
        let y = "count per quarter decade";
        let mut right = LinePlot::with_axes("What is conserved to rounding", X_RIGHT, y)
            .x_range(-20.0, -12.0)
            .legend(Legend::UpperRight);
        let conserved = [&q.through_collision, &q.facing_residual, same_wall];
        for (p, (label, color, kind)) in conserved.into_iter().zip(CONSERVED) {
            let points = log_counts(&p.log10, ZERO_AT);
            right = right.series(Series::new(label, points).color(color).kind(kind));
        }
        let title = format!(
            "Conserved quantity Q = v∥ − αu, stadium a = 1, α = {ALPHA}, one trajectory of {collisions} collisions"
        );
        let grid = Grid::new(1, 2).title(title).panel(left).panel(right);
        let size = args.pick((1600, 700), (2000, 850), (2400, 1000));
        report.png("q_conservation.png", &grid, size)?;

        report.csv("q_pairs.csv", &q_pairs_csv(&q.pairs))?;
        let named = q_populations(&q);
        let hists: Vec<_> = named.iter().map(|(n, p)| (*n, &p.log10)).collect();
        report.csv("q_histogram.csv", &histograms_csv("log10", &hists))?;
        let medians: Vec<_> = named.iter().map(|(n, p)| (n, p.median())).collect();
        let f = |rule| walls.transition_fraction(rule);
        let (tangent, direction, wall) = (f(Rule::Tangent), f(Rule::Direction), f(Rule::Wall));
        let mut statistics = q.clone();
        statistics.pairs.clear(); // every pair is in q_pairs.csv
        let doc = json!({
            "table": "stadium:a=1", "alpha": ALPHA, "collisions": collisions, "sampler": "paper",
            "ic_index": 0, "pairs": q.pair_count(), "medians": medians, "statistics": statistics,
            "shares": CLASSES.map(|(c, ..)| (c, q.share(c))),
            "transition_fraction": {"tangent": tangent, "direction": direction, "wall": wall},
            "curved_fraction": walls.curved_fraction(),
        });
        report.json("q_conservation.json", &doc)?;
        let (through, facing) = (q.through_collision.max, q.facing_residual.max);
        let wall = wall.unwrap_or(f64::NAN);
        println!(
            "  through a collision: max {through:.1e}; facing walls |ΔQ + 2v∥|: max {facing:.1e}; f_trans (wall rule) {wall:.3}"
        );
        Ok(())
    })
}
