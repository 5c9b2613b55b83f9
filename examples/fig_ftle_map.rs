//! FTLE maps of the section: the finite-time Lyapunov exponent of every
//! start on a grid of `(s, sin θ)` at fixed spin, for the stadium (a = 1)
//! and the Sinai table (L = 2, R = 1) at α ∈ {0, 0.3, 0.5, 1}. Regular
//! orbits are dark, the chaotic sea light; on the stadium the cells the
//! bouncing-ball rotation (`4·arctan √α` per pair of flat collisions)
//! predicts trapped between the flats are outlined in red.
//!
//! ```text
//! cargo run --release --example fig_ftle_map -- [--quick | --paper] [--out DIR] [--seed N] [--spin U]
//! ```
//!
//! | mode      | grid      | collisions | sampler ICs | wall time (2 cores) |
//! |-----------|-----------|------------|-------------|---------------------|
//! | `--quick` | 64 × 64   | 500        | 1 000       | a few s             |
//! | default   | 512 × 512 | 2 000      | 20 000      | about a minute      |
//! | `--paper` | 512 × 512 | 10 000     | 100 000     | several minutes     |
//!
//! Exact tangent method in vector lanes, starts on the shell E = ½ at spin
//! `--spin` (default 0). Beside each map the paper's sampler is run with
//! the same collisions, for its chaotic fraction and (stadium) the share of
//! its regular orbits that the rotation predicts trapped. Writes
//! `ftle_map.png`, `ftle_map_<table>_<α>.npy` (rows × columns, row 0 at
//! sin θ = −1, NaN never occurs at fixed spin), `ftle_maps.csv` (one row
//! per map) and `ftle_maps.json`.

use std::process::ExitCode;

use serde_json::json;
use spinball_analysis::phase_space::{FacingFlats, FtleMapOptions, Slice, island_map};
use spinball_core::SpinLaw;
use spinball_figures::{Csv, ISLAND_COLUMNS, island_panel, island_row, run_figure_with};
use spinball_geometry::Table;
use spinball_plot::{Colorbar, Grid};

const NAME: &str = "fig_ftle_map";
const ABOUT: &str = "FTLE maps on the section (s, sin θ) at fixed spin, stadium and Sinai at α = 0, 0.3, 0.5, 1, with the predicted bouncing-ball island.";
const TABLES: [&str; 2] = ["stadium:a=1", "sinai:L=2,R=1"];
const ALPHAS: [f64; 4] = [0.0, 0.3, 0.5, 1.0];
/// Top of the colour scale (FTLE per unit time); larger values are clamped.
const FTLE_MAX: f64 = 0.6;

/// The example's own options.
#[derive(Debug, clap::Args)]
struct Options {
    /// the spin u of the slice
    #[arg(
        long,
        value_name = "U",
        default_value_t = 0.0,
        allow_negative_numbers = true
    )]
    spin: f64,
}

fn main() -> ExitCode {
    run_figure_with(NAME, ABOUT, |args, own: &Options, report| {
        let spin = own.spin;
        let size: usize = args.pick(64, 512, 512);
        let collisions: u64 = args.pick(500, 2_000, 10_000);
        let ics: u64 = args.pick(1_000, 20_000, 100_000);
        let options = FtleMapOptions::new(size, size, Slice::Spin(spin))
            .with_collisions(collisions)
            .with_seed(args.seed)
            .with_threads(args.threads);
        let mut grid = Grid::new(TABLES.len(), ALPHAS.len())
            .title(format!("FTLE maps at u = {spin}: {size}² starts × {collisions} collisions (red: predicted bouncing balls)"))
            .colorbar(Colorbar::new("FTLE (1/time)", 0.0, FTLE_MAX));
        let mut csv = Csv::new(&ISLAND_COLUMNS);
        let mut maps = Vec::new();
        for spec in TABLES {
            let table: Table = spec.parse()?;
            let name = table.name();
            for alpha in ALPHAS {
                // The map, the sampler, and (stadium only) the cells and
                // orbits the rotation predicts trapped between the flats.
                let flats = FacingFlats::of_table(&table);
                let island = island_map(table, SpinLaw::new(alpha)?, flats, &options, ics)?;
                println!("  {name:<8} α = {alpha:<4} {island}");
                island_row(&mut csv, name, &island);
                let (map, sampled) = (&island.map, &island.sampled);
                let file = format!("ftle_map_{name}_{alpha}.npy");
                report.npy(&file, &[size as u64, size as u64], &map.to_array())?;
                grid.push(island_panel(name, &island, FTLE_MAX));
                maps.push(json!({"table": spec, "alpha": alpha, "file": file, "perimeter": map.perimeter,
                    "regular_fraction": map.regular_fraction(), "sampler": sampled.chaotic_fraction(), "bouncing": island.bouncing}));
            }
        }
        report.png(
            "ftle_map.png",
            &grid,
            args.pick((2000, 1100), (2800, 1500), (2800, 1500)),
        )?;
        report.csv("ftle_maps.csv", &csv)?;
        let axes = json!({"s": "cell centres P (i + ½)/columns", "sin_theta": "cell centres −1 + 2 (j + ½)/rows"});
        report.json(
            "ftle_maps.json",
            &json!({"options": options, "axes": axes, "maps": maps}),
        )?;
        Ok(())
    })
}
