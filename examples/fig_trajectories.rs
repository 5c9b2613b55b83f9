//! The paper's trajectory figure: four tables × α ∈ {0, 0.3, 0.7, 1}, 500
//! collisions each, coloured from early (dark) to late (light).
//!
//! ```text
//! cargo run --release --example fig_trajectories -- [--quick | --paper] [--out DIR]
//! ```
//!
//! Initial condition (the paper gives θ0 = 0.8 and u0 = 0 but no start
//! point): speed 1 (E = ½) in direction θ0 = 0.8 rad from the x axis, no
//! spin, starting at (0.3, 0.2) in the circle (R = 1), the rectangle
//! (L = 1.5, H = 1) and the stadium (a = 1), and at (−1.5, 0.2) in the Sinai
//! table (L = 2, R = 1), whose centre is the obstacle. `--quick` draws 200
//! collisions on a smaller image; the default and `--paper` draw 500.
//!
//! Writes `trajectories.png` (4 × 4 grid, rows = tables, columns = α),
//! `trajectories.csv` (every collision point with time, velocity and spin)
//! and `trajectories.json` (the set-up).

use std::process::ExitCode;

use serde_json::json;
use spinball_core::{Billiard, Recorder, SpinLaw, State};
use spinball_figures::{Csv, run_figure};
use spinball_geometry::{DVec2, Table};
use spinball_plot::{Colorbar, Grid, TablePlot};

const NAME: &str = "fig_trajectories";
const ABOUT: &str = "Trajectories in the four tables at α = 0, 0.3, 0.7, 1, coloured by time (paper Fig. 1; fixed initial condition, --seed is not used).";
const ALPHAS: [f64; 4] = [0.0, 0.3, 0.7, 1.0];
/// Launch angle (radians from the x axis) and spin of the paper.
const THETA0: f64 = 0.8;
const U0: f64 = 0.0;
/// Table spec, title, start point.
const TABLES: [(&str, &str, [f64; 2]); 4] = [
    ("circle:R=1", "circle", [0.3, 0.2]),
    ("rectangle:L=1.5,H=1", "rectangle", [0.3, 0.2]),
    ("stadium:a=1", "stadium", [0.3, 0.2]),
    ("sinai:L=2,R=1", "Sinai", [-1.5, 0.2]),
];

fn main() -> ExitCode {
    run_figure(NAME, ABOUT, |args, report| {
        let collisions: u64 = args.pick(200, 500, 500);
        let title = format!("Trajectories, {collisions} collisions (θ₀ = {THETA0}, u₀ = {U0})");
        let mut grid = Grid::new(TABLES.len(), ALPHAS.len()).title(title);
        let mut csv = Csv::new(&[
            "table", "alpha", "n", "time", "x", "y", "vx", "vy", "u", "wall",
        ]);
        for (spec, title, start) in TABLES {
            let table: Table = spec.parse()?;
            let start = State::new(DVec2::from(start), DVec2::from_angle(THETA0), U0);
            for alpha in ALPHAS {
                let billiard = Billiard::new(table, SpinLaw::new(alpha)?);
                let mut ball = billiard.launch(start)?;
                let mut rec = Recorder::with_states();
                billiard.run(&mut ball, collisions, &mut rec)?;

                // The start (no wall), then every collision.
                let mut time = 0.0;
                let hits = rec.collisions.iter().zip(&rec.states).map(|(c, s)| {
                    time += c.time();
                    (time, s, c.wall().to_string())
                });
                for (n, (t, s, wall)) in std::iter::once((0.0, &start, String::new()))
                    .chain(hits)
                    .enumerate()
                {
                    let (p, v) = (s.position, s.velocity);
                    csv.row(&[
                        &spec, &alpha, &n, &t, &p.x, &p.y, &v.x, &v.y, &s.spin, &wall,
                    ]);
                }
                let path =
                    std::iter::once(start.position).chain(rec.states.iter().map(|s| s.position));
                grid.push(
                    TablePlot::new(&table)
                        .title(format!("{title}, α = {alpha}"))
                        .trajectory(path),
                );
            }
        }
        let grid = grid.colorbar(Colorbar::new("collision number", 0.0, collisions as f64));
        report.png(
            "trajectories.png",
            &grid,
            args.pick((1200, 1000), (1800, 1500), (2400, 2000)),
        )?;
        report.csv("trajectories.csv", &csv)?;
        let tables: Vec<_> = TABLES
            .iter()
            .map(|(spec, _, p)| json!({"table": spec, "start": p}))
            .collect();
        let doc = json!({
            "collisions": collisions, "theta0": THETA0, "u0": U0, "speed": 1.0, "energy": 0.5,
            "alphas": ALPHAS, "tables": tables, "files": ["trajectories.png", "trajectories.csv"],
        });
        report.json("trajectories.json", &doc)?;
        Ok(())
    })
}
