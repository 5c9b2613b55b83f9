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

use spinball_analysis::{SectionPoint, sections};
use spinball_core::{Billiard, Sampler, SpinLaw};
use spinball_geometry::{ArcSegment, Boundary, DVec2, LineSegment, Segment, SegmentTable, Table};
use spinball_plot::cli::Opt;
use spinball_plot::{BoxError, Colorbar, Csv, Grid, MapPlot, Scatter3d, run_figure_with};

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

/// The section points of `orbits` paper-sampler orbits on `table`.
fn orbits_of<B: Boundary + Sync>(
    table: B,
    law: SpinLaw,
    args: &spinball_plot::cli::FigureArgs,
    orbits: u64,
    collisions: u64,
) -> Result<(f64, Vec<Vec<SectionPoint>>), BoxError> {
    let starts: Vec<_> = (0..orbits)
        .map(|i| Sampler::Paper.initial_state(&table, &law, args.seed, i))
        .collect();
    let perimeter = table.perimeter();
    let billiard = Billiard::new(table, law);
    Ok((
        perimeter,
        sections(&billiard, &starts, collisions, args.threads)?,
    ))
}

fn main() -> ExitCode {
    let extra = [Opt::value("alpha", "A", "spin parameter α (default 0.5)")];
    run_figure_with(NAME, ABOUT, &extra, |args, report| {
        let alpha: f64 = args.extra.get_or("alpha", 0.5)?;
        let law = SpinLaw::new(alpha)?;
        let u_max = if alpha > 0.0 { 1.0 / alpha.sqrt() } else { 1.0 };
        let orbits: u64 = args.pick(8, 24, 48);
        let collisions: u64 = args.pick(1_000, 5_000, 20_000);
        let mut csv = Csv::new(&["table", "orbit", "s", "sin_theta", "u", "wall", "q"]);
        let mut grid = Grid::new(2, 3)
            .title(format!("Birkhoff sections at α = {alpha}: {orbits} orbits × {collisions} collisions, colour = spin u"))
            .colorbar(Colorbar::new("spin u (before the collision)", -u_max, u_max));
        let mut runs = Vec::new();
        for spec in TABLES {
            let table: Table = spec.parse()?;
            runs.push((
                table.name().to_string(),
                orbits_of(table, law, args, orbits, collisions)?,
            ));
        }
        runs.push((
            "mushroom".into(),
            orbits_of(mushroom()?, law, args, orbits, collisions)?,
        ));
        let mut stadium_3d = Vec::new();
        for (k, (name, (perimeter, orbit_points))) in runs.iter().enumerate() {
            let mut points = Vec::new();
            for (i, orbit) in orbit_points.iter().enumerate() {
                for p in orbit {
                    csv.row(&[name, &i, &p.s, &p.sin_theta(), &p.spin, &p.wall, &p.q]);
                    points.push((p.s, p.sin_theta(), p.spin));
                    if k == 0 {
                        stadium_3d.push(([p.s, p.sin_theta(), p.spin], p.spin));
                    }
                }
            }
            grid.push(
                MapPlot::new((0.0, *perimeter), (-1.0, 1.0), (-u_max, u_max))
                    .points(points)
                    .labels("s", "sin θ")
                    .title(name.clone()),
            );
        }
        // The stadium's slice |√α u| < SLICE: the collisions near zero spin.
        let (perimeter, stadium) = &runs[0].1;
        let slice: Vec<_> = stadium
            .iter()
            .flatten()
            .filter(|p| p.w(alpha).abs() < SLICE)
            .map(|p| (p.s, p.sin_theta(), p.spin))
            .collect();
        grid.push(
            MapPlot::new((0.0, *perimeter), (-1.0, 1.0), (-u_max, u_max))
                .points(slice)
                .labels("s", "sin θ")
                .title(format!("stadium, |√α u| < {SLICE}")),
        );
        report.png(
            "sections.png",
            &grid,
            args.pick((1500, 1000), (2100, 1400), (2700, 1800)),
        )?;
        let cloud = Scatter3d::new(
            stadium_3d,
            [(0.0, *perimeter), (-1.0, 1.0), (-u_max, u_max)],
            (-u_max, u_max),
        )
        .labels("s", "sin θ", "u")
        .title(format!(
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
