//! Poincaré (Birkhoff) sections of spinning billiards: every collision of a
//! few orbits drawn at `(s, sin θ)` and coloured by the spin `u` just before
//! it, for the four built-in tables and a mushroom built from segments, a
//! slice of the stadium's section at small spin, and the stadium's 3-D
//! section `(s, sin θ, u)` seen from an angle.
//!
//! ```text
//! cargo run --release --example fig_sections -- [--quick | --paper] [--out DIR] [--seed N] [--alpha A]
//! ```
//!
//! | mode      | orbits per table | collisions per orbit | wall time (2 cores) |
//! |-----------|------------------|----------------------|---------------------|
//! | `--quick` | 8                | 1 000                | < 2 s               |
//! | default   | 24               | 5 000                | a few s             |
//! | `--paper` | 48               | 20 000               | about a minute      |
//!
//! Orbits start from the paper's sampler (seed `--seed`, indices 0, 1, …)
//! at α = `--alpha` (default 0.5). Writes `sections.png` (2 × 3 panels),
//! `section_3d.png` and `sections.csv` (table, orbit, s, sin θ, u, wall, Q
//! of every collision).

use std::f64::consts::PI;
use std::process::ExitCode;

use spinball_analysis::phase_space::{sampled_sections, spin_slice};
use spinball_core::{Billiard, Sampler, SpinLaw};
use spinball_figures::{
    BoxError, Csv, SECTION_COLUMNS, run_figure_with, section_cloud, section_panel, section_rows,
    shell_spin,
};
use spinball_geometry::{
    ArcSegment, Boundary, Built, DVec2, LineSegment, Segment, SegmentTable, Table,
};
use spinball_plot::{Colorbar, Grid};

const NAME: &str = "fig_sections";
const ABOUT: &str = "Birkhoff sections (s, sin θ) coloured by spin for the built-in tables and a mushroom, a spin slice, and the stadium's 3-D section.";
const TABLES: [&str; 4] = [
    "stadium:a=1",
    "sinai:L=2,R=1",
    "circle:R=1",
    "rectangle:L=1.5,H=1",
];
/// Half-width of the stadium's spin slice, in `√α u` (the energy shell has `|√α u| ≤ 1`).
const SLICE: f64 = 0.1;

/// The mushroom of Bunimovich (2001): a semicircular cap on a stem.
fn mushroom() -> Result<SegmentTable, BoxError> {
    let p = DVec2::new;
    let line = |a, b| LineSegment::new(a, b).map(Segment::Line);
    Ok(SegmentTable::new(vec![
        line(p(-0.3, -1.0), p(0.3, -1.0))?,
        line(p(0.3, -1.0), p(0.3, 0.0))?,
        line(p(0.3, 0.0), p(1.0, 0.0))?,
        Segment::Arc(ArcSegment::new(DVec2::ZERO, 1.0, 0.0, PI)?),
        line(p(-1.0, 0.0), p(-0.3, 0.0))?,
        line(p(-0.3, 0.0), p(-0.3, -1.0))?,
    ])?)
}

/// The example's own options.
#[derive(Debug, clap::Args)]
struct Options {
    /// spin parameter α
    #[arg(
        long,
        value_name = "A",
        default_value_t = 0.5,
        allow_negative_numbers = true
    )]
    alpha: f64,
}

fn main() -> ExitCode {
    run_figure_with(NAME, ABOUT, |args, own: &Options, report| {
        let alpha = own.alpha;
        let law = SpinLaw::new(alpha)?;
        let u_max = shell_spin(alpha);
        let orbits: u64 = args.pick(8, 24, 48);
        let collisions: u64 = args.pick(1_000, 5_000, 20_000);
        let mut csv = Csv::new(&SECTION_COLUMNS);
        let mut grid = Grid::new(2, 3)
            .title(format!("Birkhoff sections at α = {alpha}: {orbits} orbits × {collisions} collisions, colour = spin u"))
            .colorbar(Colorbar::new("spin u (before the collision)", -u_max, u_max));
        // The built-in tables and the mushroom, each with the section
        // points of every orbit.
        let mut tables = Vec::new();
        for spec in TABLES {
            let table: Table = spec.parse()?;
            tables.push((table.name().to_string(), Built::Table(table)));
        }
        tables.push(("mushroom".into(), Built::Segments(mushroom()?)));
        let mut runs = Vec::new();
        for (name, table) in tables {
            let perimeter = table.perimeter();
            let billiard = Billiard::new(table, law);
            let (seed, threads) = (args.seed, args.threads);
            let orbits = sampled_sections(
                &billiard,
                Sampler::Paper,
                seed,
                0..orbits,
                collisions,
                threads,
            )?;
            section_rows(&mut csv, &name, &orbits);
            grid.push(section_panel(perimeter, u_max, orbits.iter().flatten()).title(name));
            runs.push((perimeter, orbits));
        }
        // The stadium's slice |√α u| < SLICE: the collisions near zero spin.
        let (perimeter, stadium) = &runs[0];
        let slice = spin_slice(stadium, alpha, SLICE);
        let title = format!("stadium, |√α u| < {SLICE}");
        grid.push(section_panel(*perimeter, u_max, &slice).title(title));
        report.png(
            "sections.png",
            &grid,
            args.pick((1500, 1000), (2100, 1400), (2700, 1800)),
        )?;
        let cloud = section_cloud(*perimeter, u_max, stadium.iter().flatten()).title(format!(
            "stadium a = 1, α = {alpha}: section (s, sin θ, u), colour = u"
        ));
        report.png(
            "section_3d.png",
            &cloud,
            args.pick((900, 800), (1400, 1200), (1800, 1600)),
        )?;
        report.csv("sections.csv", &csv)?;
        Ok(())
    })
}
