//! The paper's conserved-quantity figure (appendix C): `|ΔQ| = |Q_{n+1} − Q_n|`
//! between consecutive collisions in the stadium (a = 1) at α = 0.5, by what
//! the two walls have in common (`spinball_analysis::diagnostics::PairClass`): the same
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
use spinball_analysis::diagnostics::{q_pair_statistics, wall_statistics};
use spinball_core::{Billiard, Sampler, SpinLaw};
use spinball_figures::{
    q_class_panel, q_class_summaries, q_conserved_panel, q_histograms_csv, q_medians, q_pairs_csv,
    run_figure,
};
use spinball_geometry::Stadium;
use spinball_plot::Grid;

const NAME: &str = "fig_q_conservation";
const ABOUT: &str =
    "|ΔQ| between consecutive collisions by pair class, stadium a = 1, α = 0.5 (paper appendix C).";
const ALPHA: f64 = 0.5;

fn main() -> ExitCode {
    run_figure(NAME, ABOUT, |args, report| {
        let collisions: u64 = args.pick(2_000, 10_000, 10_000);
        let billiard = Billiard::new(Stadium::new(1.0)?, SpinLaw::new(ALPHA)?);
        let start = Sampler::Paper.initial_state(billiard.table(), billiard.law(), args.seed, 0);
        let q = q_pair_statistics(&billiard, start, collisions, true)?;
        let walls = wall_statistics(&billiard, start, collisions)?;

        for line in q_class_summaries(&q) {
            println!("  {line}");
        }
        let title = format!(
            "Conserved quantity Q = v∥ − αu, stadium a = 1, α = {ALPHA}, one trajectory of {collisions} collisions"
        );
        let grid = Grid::new(1, 2)
            .title(title)
            .panel(q_class_panel(&q))
            .panel(q_conserved_panel(&q));
        let size = args.pick((1600, 700), (2000, 850), (2400, 1000));
        report.png("q_conservation.png", &grid, size)?;

        report.csv("q_pairs.csv", &q_pairs_csv(&q.pairs))?;
        report.csv("q_histogram.csv", &q_histograms_csv(&q))?;
        let fractions = walls.transition_fractions();
        let doc = json!({
            "table": "stadium:a=1", "alpha": ALPHA, "collisions": collisions, "sampler": "paper",
            "ic_index": 0, "pairs": q.pair_count(), "medians": q_medians(&q),
            // Every pair is in q_pairs.csv.
            "statistics": q.without_pairs(), "shares": q.shares(),
            "transition_fraction": fractions, "curved_fraction": walls.curved_fraction(),
        });
        report.json("q_conservation.json", &doc)?;
        let (through, facing) = (q.through_collision.max, q.facing_residual.max);
        let wall = fractions.wall.unwrap_or(f64::NAN);
        println!(
            "  through a collision: max {through:.1e}; facing walls |ΔQ + 2v∥|: max {facing:.1e}; f_trans (wall rule) {wall:.3}"
        );
        Ok(())
    })
}
