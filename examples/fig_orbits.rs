//! Stability diagram of period-2 orbits: Greene's residue against α for
//! every period-2 orbit of the stadium, the Sinai table and a table built
//! from walls (a half-stadium: a flat wall facing a cap), found at α = 0 by
//! Newton's method and followed in α, with the α where each changes
//! stability. See docs/PHASE_SPACE.md, "Periodic orbits and their stability".
//!
//! ```text
//! cargo run --release --example fig_orbits -- [--quick | --paper] [--out DIR]
//! ```
//!
//! | mode      | α grid          | normal-incidence seeds |
//! |-----------|-----------------|------------------------|
//! | `--quick` | 0..1, 20 steps  | 1024                   |
//! | default   | 0..1, 100 steps | 4096                   |
//! | `--paper` | 0..1, 400 steps | 16384                  |
//!
//! Writes `orbits.png` (one panel per table: residue `(2 − T)/4` against α,
//! elliptic between the lines 0 and 1), `orbits.csv` (one row per orbit and
//! α) and `orbits.json` (the diagrams, with every stability change).
//!
//! Then the islands: `islands.png` (the FTLE map of the Sinai table at
//! α = 0.5 with its period-2 orbits marked by stability class, the window
//! around the axis orbit with its island outlined, and the island's area
//! against α for L = 2 with R = 1 and R = 0.5, the onsets α* = 1/5 and 3/7
//! marked), `islands.csv` and `islands.json`.
//!
//! | mode      | FTLE map            | island window | island α grid   |
//! |-----------|---------------------|---------------|-----------------|
//! | `--quick` | 64 × 32, 1000 coll. | 21², 1000     | 0.1..0.9, 4 steps |
//! | default   | 256 × 128, 2000     | 61², 2000     | 0..1, 40 steps  |
//! | `--paper` | 512 × 256, 2000     | 81², 4000     | 0..1, 100 steps |

use std::f64::consts::PI;
use std::process::ExitCode;

use spinball_analysis::orbits::{
    BirkhoffPoint, IslandCurve, IslandOptions, NewtonOptions, ORBIT_CSV_HEADER, SearchOptions,
    StabilityDiagram, find_orbit, island_around, island_sizes, periodic_orbits, stability_diagram,
};
use spinball_analysis::phase_space::{FtleMapOptions, Slice, ftle_map};
use spinball_core::{Billiard, SpinLaw};
use spinball_figures::{
    ALPHA_LABEL, BoxError, Csv, FigureArgs, Report, island_area_panel, island_window_panel,
    optional, orbits_map_panel, run_figure,
};
use spinball_geometry::{
    ArcSegment, Boundary, DVec2, LineSegment, Segment, SegmentTable, Sinai, Stadium,
};
use spinball_plot::{Grid, Legend, LinePlot, Series, palette};

const NAME: &str = "fig_orbits";
const ABOUT: &str =
    "Stability diagram of the period-2 orbits of the stadium, Sinai and a user table against α.";

/// A flat wall at `x = −a` facing a unit half-circle cap centred at `x = a`.
fn half_stadium(a: f64) -> Result<SegmentTable, Box<dyn std::error::Error + Send + Sync>> {
    let p = DVec2::new;
    let line = |a, b| LineSegment::new(a, b).map(Segment::Line);
    Ok(SegmentTable::new(vec![
        line(p(-a, -1.0), p(a, -1.0))?,
        Segment::Arc(ArcSegment::new(p(a, 0.0), 1.0, -0.5 * PI, PI)?),
        line(p(a, 1.0), p(-a, 1.0))?,
        line(p(-a, 1.0), p(-a, -1.0))?,
    ])?)
}

fn diagram<B: Boundary>(
    table: &B,
    alphas: &[f64],
    samples: u32,
) -> Result<StabilityDiagram, Box<dyn std::error::Error + Send + Sync>> {
    let search = SearchOptions {
        normal_samples: samples,
        ..SearchOptions::default()
    };
    Ok(stability_diagram(table, 2, alphas, 1e-10, &search)?)
}

fn main() -> ExitCode {
    run_figure(NAME, ABOUT, |args, report| {
        let steps: u32 = args.pick(20, 100, 400);
        let samples = args.pick(1024, 4096, 16384);
        let alphas: Vec<f64> = (0..=steps)
            .map(|i| f64::from(i) / f64::from(steps))
            .collect();
        let diagrams = [
            (
                "stadium a = 1",
                diagram(&Stadium::new(1.0)?, &alphas, samples)?,
            ),
            (
                "Sinai L = 2, R = 1",
                diagram(&Sinai::new(2.0, 1.0)?, &alphas, samples)?,
            ),
            (
                "half-stadium (flat facing a cap), a = 0.5",
                diagram(&half_stadium(0.5)?, &alphas, samples)?,
            ),
        ];
        let mut grid = Grid::new(1, 3);
        let mut csv = format!("table,{ORBIT_CSV_HEADER}\n");
        println!(
            "{NAME} ({} mode): period 2, α in [0, 1] in {steps} steps",
            args.mode
        );
        for (label, d) in &diagrams {
            let mut plot = LinePlot::new()
                .title(label.to_string())
                .x_label(ALPHA_LABEL)
                .y_label("residue (2 − T)/4")
                .y_range(-9.0, 2.0)
                .hline(0.0, "")
                .hline(1.0, "")
                .legend(Legend::LowerRight);
            for (i, b) in d.branches.iter().enumerate() {
                let walls: Vec<String> = b.orbits[0].walls.iter().map(u32::to_string).collect();
                let points = b
                    .orbits
                    .iter()
                    .map(|o| (o.alpha, o.stability.residue.clamp(-9.0, 2.0)));
                plot = plot.series(
                    Series::new(format!("walls {}", walls.join("-")), points)
                        .color(palette(i))
                        .line_only(),
                );
                for c in &b.changes {
                    println!(
                        "  {label}, orbit {i} (walls {}): T = {:+} at α = {:.10} ± {:.0e}",
                        walls.join("-"),
                        c.crossing,
                        c.alpha,
                        c.error
                    );
                }
            }
            for row in d.rows() {
                csv.push_str(&format!("\"{label}\",{}\n", row.csv_line()));
            }
            grid = grid.panel(plot);
        }
        report.png("orbits.png", &grid, (1800, 600))?;
        report.text("orbits.csv", &csv)?;
        let body: Vec<_> = diagrams
            .iter()
            .map(|(label, d)| serde_json::json!({"table": label, "diagram": d}))
            .collect();
        report.json("orbits.json", &serde_json::json!({ "diagrams": body }))?;
        islands(args, report)
    })
}

/// The Sinai axis orbit (from the middle of the bottom box wall, `s = L`,
/// to the disk) at α = 0, followed through `alphas` with its island.
fn axis_islands(
    l: f64,
    r: f64,
    alphas: &[f64],
    options: &IslandOptions,
) -> Result<IslandCurve, BoxError> {
    let table = Sinai::new(l, r)?;
    let billiard = Billiard::new(&table, SpinLaw::new(0.0)?);
    let newton = NewtonOptions::default();
    let orbit = find_orbit(&billiard, BirkhoffPoint::normal(l), 2, &newton)?;
    Ok(island_sizes(
        &table, &orbit, alphas, 1e-10, &newton, options,
    )?)
}

/// The islands figure: orbits on an FTLE map, one island's window, island
/// area against α.
fn islands(args: &FigureArgs, report: &mut Report) -> Result<(), BoxError> {
    let (columns, rows, collisions) = args.pick((64, 32, 1000), (256, 128, 2000), (512, 256, 2000));
    let (cells, island_collisions) = args.pick((21, 1000), (61, 2000), (81, 4000));
    let alphas: Vec<f64> = args.pick(
        vec![0.1, 0.3, 0.5, 0.7, 0.9],
        (0..=40).map(|i| f64::from(i) / 40.0).collect(),
        (0..=100).map(|i| f64::from(i) / 100.0).collect(),
    );
    let options = IslandOptions::default()
        .with_cells(cells)
        .with_collisions(island_collisions)
        .with_seed(args.seed)
        .with_threads(args.threads);
    let l = 2.0;
    let sinai = Sinai::new(l, 1.0)?;
    let search = SearchOptions {
        normal_samples: args.pick(1024, 4096, 16384),
        ..SearchOptions::default()
    };
    // Below the onset α* = 1/5 (axis orbits hyperbolic) and above it.
    let mut panels = Vec::new();
    for alpha in [0.1, 0.5] {
        let law = SpinLaw::new(alpha)?;
        let map = ftle_map(
            sinai,
            law,
            &FtleMapOptions::new(columns, rows, Slice::Spin(0.0))
                .with_collisions(collisions)
                .with_seed(args.seed)
                .with_threads(args.threads),
        )?;
        let (orbits, _) = periodic_orbits(&Billiard::new(&sinai, law), 2, &search)?;
        panels.push(orbits_map_panel("Sinai R = 1", &map, &orbits, 0.5));
    }
    let axis = find_orbit(
        &Billiard::new(&sinai, SpinLaw::new(0.5)?),
        BirkhoffPoint::normal(l),
        2,
        &search.newton,
    )?;
    let island = island_around(&sinai, &axis, &options)?;
    let curves = vec![
        (
            "Sinai L = 2, R = 1".to_string(),
            axis_islands(l, 1.0, &alphas, &options)?,
            0.2,
        ),
        (
            "Sinai L = 2, R = 0.5".to_string(),
            axis_islands(l, 0.5, &alphas, &options)?,
            3.0 / 7.0,
        ),
    ];
    let mut csv = Csv::new(&[
        "table",
        "alpha",
        "class",
        "pair_trace",
        "area",
        "error",
        "s_min",
        "s_max",
        "sin_theta_min",
        "sin_theta_max",
    ]);
    println!("island around the Sinai axis orbit (slice u = 0, area in (s, sin θ)):");
    for (label, curve, _) in &curves {
        for p in &curve.points {
            let extent =
                |f: fn(&spinball_analysis::orbits::IslandSize) -> f64| p.size.map(|z| f(&z));
            csv.row(&[
                label,
                &p.alpha,
                &p.class.name(),
                &p.pair_trace,
                &optional(p.area),
                &optional(p.error),
                &optional(extent(|z| z.s_extent[0])),
                &optional(extent(|z| z.s_extent[1])),
                &optional(extent(|z| z.sin_theta_extent[0])),
                &optional(extent(|z| z.sin_theta_extent[1])),
            ]);
            if let (Some(a), Some(e)) = (p.area, p.error) {
                println!(
                    "  {label}, α = {:.3}: {a:.4} ± {e:.4} ({})",
                    p.alpha,
                    p.class.name()
                );
            } else if let Some(why) = &p.failure {
                println!("  {label}, α = {:.3}: not measured: {why}", p.alpha);
            }
        }
    }
    let mut grid = Grid::new(2, 2);
    for panel in panels {
        grid = grid.panel(panel);
    }
    grid = grid
        .panel(island_window_panel("axis orbit", &island, 0.5))
        .panel(island_area_panel(&curves));
    report.png("islands.png", &grid, (1200, 800))?;
    report.csv("islands.csv", &csv)?;
    let body: Vec<_> = curves
        .iter()
        .map(|(label, c, _)| serde_json::json!({"table": label, "islands": c}))
        .collect();
    report.json(
        "islands.json",
        &serde_json::json!({ "window": island, "curves": body }),
    )?;
    Ok(())
}
