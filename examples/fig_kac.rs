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

use spinball_analysis::phase_space::{SectionBox, kac_comparison};
use spinball_core::{Billiard, SpinLaw};
use spinball_figures::{
    Csv, KAC_COLUMNS, KAC_ORBIT_COLUMNS, kac_histogram, kac_orbit_rows, kac_ratio_series, kac_row,
    run_figure,
};
use spinball_geometry::Table;
use spinball_plot::{Grid, LinePlot, palette};

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
        let mut summary = Csv::new(&KAC_COLUMNS);
        let mut per_orbit = Csv::new(&KAC_ORBIT_COLUMNS);
        let mut lines = LinePlot::new()
            .x_label("spin parameter α")
            .y_label("⟨return time⟩ / Kac")
            .hline(1.0, "Kac (ergodic)");
        for (k, (spec, s, region_name)) in cases.into_iter().enumerate() {
            let table: Table = spec.parse()?;
            let name = table.name();
            let region = SectionBox::new(s, -1.0..1.0);
            let mut runs = Vec::new();
            for alpha in ALPHAS {
                let billiard = Billiard::new(table, SpinLaw::new(alpha)?);
                let (seed, threads) = (args.seed, args.threads);
                let kac = kac_comparison(&billiard, &region, orbits, collisions, seed, threads)?;
                println!("  {name:<8} {region_name:<9} α = {alpha:<4} {kac}");
                kac_row(&mut summary, name, region_name, &kac);
                kac_orbit_rows(&mut per_orbit, name, &kac);
                grid.push(kac_histogram(name, &kac, palette(k)));
                runs.push(kac);
            }
            lines = lines.series(kac_ratio_series(name, &runs).color(palette(k)));
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
