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
use spinball_analysis::{
    CHAOS_THRESHOLD, Ensemble, FacingFlats, FtleMapOptions, Method, Slice, bouncing_share, ftle_map,
};
use spinball_core::{Sampler, SpinLaw};
use spinball_geometry::Table;
use spinball_plot::cli::Opt;
use spinball_plot::{Colorbar, Csv, Grid, MapPlot, run_figure_with};

const NAME: &str = "fig_ftle_map";
const ABOUT: &str = "FTLE maps on the section (s, sin θ) at fixed spin, stadium and Sinai at α = 0, 0.3, 0.5, 1, with the predicted bouncing-ball island.";
const TABLES: [&str; 2] = ["stadium:a=1", "sinai:L=2,R=1"];
const ALPHAS: [f64; 4] = [0.0, 0.3, 0.5, 1.0];
/// Top of the colour scale (FTLE per unit time); larger values are clamped.
const FTLE_MAX: f64 = 0.6;

fn main() -> ExitCode {
    let extra = [Opt::value(
        "spin",
        "U",
        "the spin u of the slice (default 0)",
    )];
    run_figure_with(NAME, ABOUT, &extra, |args, report| {
        let spin: f64 = args.extra.get_or("spin", 0.0)?;
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
        let mut csv = Csv::new(&[
            "table",
            "alpha",
            "spin",
            "cells",
            "collisions",
            "map_regular_fraction",
            "sampler_chaotic_fraction",
            "sampler_chaotic_fraction_sem",
            "predicted_cells",
            "predicted_cells_regular",
            "sampler_regular",
            "sampler_regular_predicted",
            "sampler_chaotic_predicted",
        ]);
        let mut maps = Vec::new();
        for spec in TABLES {
            let table: Table = spec.parse()?;
            for alpha in ALPHAS {
                let law = SpinLaw::new(alpha)?;
                let map = ftle_map(table, law, &options)?;
                let flats = match table {
                    Table::Stadium(s) => Some((s, FacingFlats::of(&s))),
                    _ => None,
                };
                // Cells the rotation predicts trapped (stadium only).
                let mask = flats.map_or_else(
                    || vec![false; size * size],
                    |(_, f)| f.trapped_cells(&law, &map),
                );
                let (predicted, predicted_regular) = map.regular_among(&mask);
                let sampled = Ensemble::new(table, law)
                    .with_method(Method::Tangent)
                    .with_collisions(collisions)
                    .with_ics(ics)
                    .with_seed(args.seed)
                    .with_threads(args.threads)
                    .run()?;
                let share = flats.map(|(s, _)| {
                    bouncing_share(
                        &s,
                        &law,
                        Sampler::Paper,
                        args.seed,
                        &sampled.trajectories,
                        CHAOS_THRESHOLD,
                    )
                });
                let (regular, regular_in, chaotic_in) = share.map_or((0, 0, 0), |s| {
                    (s.regular, s.regular_trapped, s.chaotic_trapped)
                });
                println!(
                    "  {:<8} α = {alpha:<4} map regular {:.4}, sampler chaotic {:.4} ± {:.4}, predicted cells {predicted} ({predicted_regular} regular), sampler regular {regular} of which predicted {regular_in}, chaotic predicted {chaotic_in}",
                    table.name(),
                    map.regular_fraction(),
                    sampled.chaotic_fraction,
                    sampled.chaotic_fraction_sem
                );
                csv.row(&[
                    &table.name(),
                    &alpha,
                    &spin,
                    &(size * size),
                    &collisions,
                    &map.regular_fraction(),
                    &sampled.chaotic_fraction,
                    &sampled.chaotic_fraction_sem,
                    &predicted,
                    &predicted_regular,
                    &regular,
                    &regular_in,
                    &chaotic_in,
                ]);
                let file = format!("ftle_map_{}_{alpha}.npy", table.name());
                report.npy(&file, &[size as u64, size as u64], &map.to_array())?;
                let title = format!(
                    "{} α = {alpha}: regular {:.1} %",
                    table.name(),
                    100.0 * map.regular_fraction()
                );
                grid.push(
                    MapPlot::new((0.0, map.perimeter), (-1.0, 1.0), (0.0, FTLE_MAX))
                        .cells(size, size, map.exponents.clone())
                        .outline(mask)
                        .labels("s", "sin θ")
                        .title(title),
                );
                maps.push(json!({"table": spec, "alpha": alpha, "file": file, "perimeter": map.perimeter,
                    "regular_fraction": map.regular_fraction(), "sampler": sampled.chaotic_fraction, "bouncing": share}));
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
