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

use std::f64::consts::PI;
use std::process::ExitCode;

use spinball_analysis::orbits::{
    ORBIT_CSV_HEADER, SearchOptions, StabilityDiagram, stability_diagram,
};
use spinball_figures::{ALPHA_LABEL, run_figure};
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
        Ok(())
    })
}
