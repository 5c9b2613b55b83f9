//! Return times against Kac's lemma: per orbit, the mean number of
//! collisions between visits to a region of the section, over Kac's
//! `1/μ(region)` with the invariant measure `ds dv∥ d(√α u)` of the
//! spinning billiard map. An ergodic table gives one value (1) for every
//! orbit; islands split the orbits into groups, and orbits trapped away
//! from the region never return.
//!
//! ```text
//! cargo run --release --example fig_kac -- [--quick | --paper] [--out DIR] [--seed N]
//! ```
//!
//! | mode      | orbits | collisions per orbit | wall time (2 cores) |
//! |-----------|--------|----------------------|---------------------|
//! | `--quick` | 16     | 5 000                | < 2 s               |
//! | default   | 200    | 10⁵                  | about 30 s          |
//! | `--paper` | 1 000  | 10⁶                  | about 40 minutes    |
//!
//! Regions: the stadium's (a = 1) right cap and the Sinai table's (L = 2,
//! R = 1) disk, every velocity and spin; α ∈ {0, 0.1, 0.3, 0.5, 1}; orbits
//! start from the invariant measure. Writes `kac.png` (histograms of the
//! per-orbit ratio), `kac_ratio.png` (mean ratio against α), `kac.csv`
//! (one row per table and α) and `kac_orbits.csv` (one row per orbit).

use std::f64::consts::PI;
use std::process::ExitCode;

use spinball_analysis::{SectionBox, kac_comparison};
use spinball_core::{Billiard, SpinLaw};
use spinball_geometry::Table;
use spinball_plot::{
    Csv, Grid, Histogram, LinePlot, Marker, Series, optional, palette, run_figure,
};

const NAME: &str = "fig_kac";
const ABOUT: &str = "Per-orbit mean return times against Kac's lemma with the spinning billiard's invariant measure, stadium and Sinai over α.";
const ALPHAS: [f64; 5] = [0.0, 0.1, 0.3, 0.5, 1.0];

fn main() -> ExitCode {
    run_figure(NAME, ABOUT, |args, report| {
        let orbits: u64 = args.pick(16, 200, 1_000);
        let collisions: u64 = args.pick(5_000, 100_000, 1_000_000);
        // Table, region (s range), its name.
        let cases = [
            ("stadium:a=1", 2.0..2.0 + PI, "right cap"),
            ("sinai:L=2,R=1", 16.0..16.0 + 2.0 * PI, "disk"),
        ];
        let mut grid = Grid::new(cases.len(), ALPHAS.len()).title(format!(
            "Mean return time per orbit / Kac's 1/μ(A): {orbits} orbits × {collisions} collisions"
        ));
        let mut summary = Csv::new(&[
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
        ]);
        let mut per_orbit =
            Csv::new(&["table", "alpha", "orbit", "visits", "mean_return", "ratio"]);
        let mut lines = LinePlot::new()
            .x_label("spin parameter α")
            .y_label("⟨return time⟩ / Kac")
            .hline(1.0, "Kac (ergodic)");
        for (k, (spec, s, region_name)) in cases.into_iter().enumerate() {
            let table: Table = spec.parse()?;
            let region = SectionBox::new(s, -1.0..1.0);
            let mut curve = Vec::new();
            for alpha in ALPHAS {
                let billiard = Billiard::new(table, SpinLaw::new(alpha)?);
                let kac = kac_comparison(
                    &billiard,
                    &region,
                    orbits,
                    collisions,
                    args.seed,
                    args.threads,
                )?;
                let ratio = kac.ratio();
                println!(
                    "  {:<8} {region_name:<9} α = {alpha:<4} μ(A) = {:.4}, Kac {:.3}, mean return {}, ratio {}, never returned {} of {orbits}",
                    table.name(),
                    kac.probability,
                    kac.expected,
                    kac.mean_return
                        .map_or("-".into(), |m| format!("{:.3} ± {:.3}", m.value, m.sem)),
                    ratio.map_or("-".into(), |r| format!("{:.4} ± {:.4}", r.value, r.sem)),
                    kac.never_returned
                );
                summary.row(&[
                    &table.name(),
                    &region_name,
                    &alpha,
                    &kac.probability,
                    &kac.expected,
                    &optional(kac.mean_return.map(|m| m.value)),
                    &optional(kac.mean_return.map(|m| m.sem)),
                    &optional(ratio.map(|r| r.value)),
                    &optional(ratio.map(|r| r.sem)),
                    &kac.never_returned,
                    &orbits,
                ]);
                for o in &kac.orbits {
                    let r = o.mean_return.map(|m| m / kac.expected);
                    per_orbit.row(&[
                        &table.name(),
                        &alpha,
                        &o.index,
                        &o.visits,
                        &optional(o.mean_return),
                        &optional(r),
                    ]);
                }
                if let Some(r) = ratio {
                    curve.push((alpha, r.value, r.sem));
                }
                grid.push(
                    Histogram::new(kac.orbit_ratios())
                        .bins(30)
                        .range(0.0, 2.0)
                        .title(format!(
                            "{} α = {alpha} ({} never back)",
                            table.name(),
                            kac.never_returned
                        ))
                        .x_label("return time / Kac")
                        .color(palette(k))
                        .marker(Marker::new("Kac", 1.0)),
                );
            }
            lines = lines.series(
                Series::new(table.name(), curve.iter().map(|c| (c.0, c.1)))
                    .errors(curve.iter().map(|c| c.2))
                    .color(palette(k)),
            );
        }
        report.png(
            "kac.png",
            &grid,
            args.pick((2000, 900), (2500, 1100), (2500, 1100)),
        )?;
        report.png("kac_ratio.png", &lines, (1200, 800))?;
        report.csv("kac.csv", &summary)?;
        report.csv("kac_orbits.csv", &per_orbit)?;
        Ok(())
    })
}
