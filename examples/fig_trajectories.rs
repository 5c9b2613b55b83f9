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

use std::error::Error;
use std::fmt::Write as _;
use std::process::ExitCode;
use std::time::Instant;

use spinball_core::{Billiard, Recorder, SpinLaw, State};
use spinball_geometry::{DVec2, Table};
use spinball_plot::cli::FigureArgs;
use spinball_plot::{Colorbar, Grid, Plot, TablePlot};

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
    let args = FigureArgs::parse_or_exit(NAME, ABOUT);
    match run(&args) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("{NAME}: {e}");
            ExitCode::FAILURE
        }
    }
}

fn run(args: &FigureArgs) -> Result<(), Box<dyn Error>> {
    let t0 = Instant::now();
    let collisions: u64 = args.pick(200, 500, 500);
    let (width, height) = args.pick((1200, 1000), (1800, 1500), (2400, 2000));

    let mut grid = Grid::new(TABLES.len(), ALPHAS.len()).title(format!(
        "Trajectories, {collisions} collisions (θ₀ = {THETA0}, u₀ = {U0})"
    ));
    let mut csv = String::from("table,alpha,n,time,x,y,vx,vy,u,wall\n");
    for (spec, title, start) in TABLES {
        let table: Table = spec.parse()?;
        let start = State::new(DVec2::from(start), DVec2::from_angle(THETA0), U0);
        for alpha in ALPHAS {
            let billiard = Billiard::new(table, SpinLaw::new(alpha)?);
            let mut ball = billiard.launch(start)?;
            let mut rec = Recorder::with_states();
            billiard.run(&mut ball, collisions, &mut rec)?;

            let mut time = 0.0;
            push_row(&mut csv, spec, alpha, 0, time, &start, None);
            for (n, (c, s)) in rec.collisions.iter().zip(&rec.states).enumerate() {
                time += c.time();
                push_row(&mut csv, spec, alpha, n as u64 + 1, time, s, Some(c.wall()));
            }
            let path = std::iter::once(start.position).chain(rec.states.iter().map(|s| s.position));
            grid.push(
                TablePlot::new(&table)
                    .title(format!("{title}, α = {alpha}"))
                    .trajectory(path),
            );
        }
    }
    let grid = grid.colorbar(Colorbar::new("collision number", 0.0, collisions as f64));

    let png = args.output("trajectories.png")?;
    grid.save_png(&png, width, height)?;
    std::fs::write(args.output("trajectories.csv")?, csv)?;
    std::fs::write(args.output("trajectories.json")?, summary(args, collisions))?;
    println!(
        "{NAME} ({} mode): wrote {} and CSV/JSON in {:.2} s",
        args.mode,
        png.display(),
        t0.elapsed().as_secs_f64()
    );
    Ok(())
}

fn push_row(
    csv: &mut String,
    spec: &str,
    alpha: f64,
    n: u64,
    t: f64,
    s: &State,
    wall: Option<u32>,
) {
    let wall = wall.map_or(String::new(), |w| w.to_string());
    let _ = writeln!(
        csv,
        "\"{spec}\",{alpha},{n},{t:.17e},{:.17e},{:.17e},{:.17e},{:.17e},{:.17e},{wall}",
        s.position.x, s.position.y, s.velocity.x, s.velocity.y, s.spin
    );
}

fn summary(args: &FigureArgs, collisions: u64) -> String {
    let tables: Vec<String> = TABLES
        .iter()
        .map(|(spec, _, p)| {
            format!(
                "    {{\"table\": \"{spec}\", \"start\": [{}, {}]}}",
                p[0], p[1]
            )
        })
        .collect();
    format!(
        "{{\n  \"figure\": \"{NAME}\",\n  \"mode\": \"{}\",\n  \"collisions\": {collisions},\n  \
         \"theta0\": {THETA0},\n  \"u0\": {U0},\n  \"speed\": 1.0,\n  \"energy\": 0.5,\n  \
         \"alphas\": {ALPHAS:?},\n  \"tables\": [\n{}\n  ],\n  \
         \"files\": [\"trajectories.png\", \"trajectories.csv\"],\n  \"version\": \"{}\"\n}}\n",
        args.mode,
        tables.join(",\n"),
        env!("CARGO_PKG_VERSION")
    )
}
