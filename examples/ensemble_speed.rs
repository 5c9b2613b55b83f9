//! What a λ ensemble costs per IC-step on each engine: the lane kernels
//! against the scalar path, both through `Ensemble::run`, as a user runs
//! them (sampling, chunking, threads and reduction included).
//!
//! ```text
//! cargo run --release --example ensemble_speed -- [--table stadium:a=1 | --table FILE.toml]
//!     [--alpha 0.5] [--ics 2000] [--collisions 20000] [--repeat 3] [--threads N] [--seed S]
//!     [--quick]
//! ```
//!
//! Run it from the repository's root (the default table is the file
//! `docs/tables/mushroom.toml`). `--quick`: 192 initial conditions of 2000
//! collisions, a smoke test rather than a measurement.
//!
//! For each method (finite differences at δ0 = 1e-7, the default, and the
//! exact tangent) it runs `--repeat` rounds, each one run per engine, the
//! engines taking turns going first, and prints the median wall time per
//! IC-step on each engine, their ratio, and the median of the rounds' own
//! ratios (each round's two runs are seconds apart, so that figure is the
//! one to trust on a host whose speed drifts). The scalar engine runs a
//! tenth of the initial conditions (the same first indices). `--table`
//! takes a built-in spec or a table file (`docs/tables/mushroom.toml`, see
//! docs/TABLE_FILES.md); the engines run the concrete table type, so the
//! scalar path is statically dispatched as in a typed ensemble.

use std::process::ExitCode;
use std::time::Instant;

use spinball::analysis::estimators::median;
use spinball::analysis::run::{Engine, Threads};
use spinball::geometry::{Built, TableFile, TableVisitor};
use spinball::prelude::*;
use spinball_figures::{BoxError, run_figure_with};

const NAME: &str = "ensemble_speed";
const ABOUT: &str =
    "Wall ns per IC-step of the λ ensemble on the lane and scalar engines, and their ratio.";
/// The example's own options.
#[derive(Debug, clap::Args)]
struct Options {
    /// built-in spec or table file
    #[arg(
        long,
        value_name = "SPEC|FILE",
        default_value = "docs/tables/mushroom.toml"
    )]
    table: String,
    /// spin parameter α
    #[arg(
        long,
        value_name = "A",
        default_value_t = 0.5,
        allow_negative_numbers = true
    )]
    alpha: f64,
    /// initial conditions on the lane engine (default 2000, quick 192)
    #[arg(long, value_name = "N")]
    ics: Option<u64>,
    /// collisions per trajectory (default 20000, quick 2000)
    #[arg(long, value_name = "T")]
    collisions: Option<u64>,
    /// rounds, one run per engine and method each; medians reported
    #[arg(long, value_name = "R", default_value_t = 3)]
    repeat: usize,
}

/// The run's settings.
struct Bench {
    alpha: f64,
    ics: u64,
    collisions: u64,
    repeat: usize,
    seed: u64,
    threads: Threads,
}

impl Bench {
    /// Initial conditions on the scalar engine: a tenth (at least 2).
    fn scalar_ics(&self) -> u64 {
        (self.ics / 10).max(2)
    }
}

impl TableVisitor for &Bench {
    type Output = Result<(), BoxError>;
    fn visit<B: Boundary + Clone + Send + Sync>(self, table: &B) -> Self::Output {
        let law = SpinLaw::extended(self.alpha)?;
        for method in [Method::FiniteDifference { delta0: 1e-7 }, Method::Tangent] {
            let engines = [
                (Engine::Lanes, self.ics),
                (Engine::Scalar, self.scalar_ics()),
            ];
            let ensembles = engines.map(|(engine, ics)| {
                Ensemble::new(table.clone(), law)
                    .with_seed(self.seed)
                    .with_ics(ics)
                    .with_collisions(self.collisions)
                    .with_method(method)
                    .with_threads(self.threads)
                    .with_engine(engine)
            });
            // Wall ns per IC-step of each round, per engine.
            let mut ns: [Vec<f64>; 2] = Default::default();
            for round in 0..self.repeat {
                // The engines alternate and take turns going first, so that
                // a host whose speed drifts weighs on both alike.
                for k in [round % 2, 1 - round % 2] {
                    let (engine, ics) = engines[k];
                    let clock = Instant::now();
                    let estimate = ensembles[k].run()?;
                    let wall = clock.elapsed().as_secs_f64();
                    if estimate.engine() != engine {
                        return Err(format!("asked for {engine}, ran {}", estimate.engine()).into());
                    }
                    ns[k].push(wall / (ics as f64 * self.collisions as f64) * 1e9);
                }
            }
            let mut cost = [0.0; 2];
            for (k, (engine, _)) in engines.iter().enumerate() {
                cost[k] = median(&ns[k]).ok_or("no run")?;
                println!(
                    "{:<8} {:<7} {:9.3} ns/IC-step",
                    method.name(),
                    engine.name(),
                    cost[k]
                );
            }
            let paired: Vec<f64> = ns[1].iter().zip(&ns[0]).map(|(s, l)| s / l).collect();
            println!(
                "{:<8} lanes ÷ scalar: {:.2}× (median of the rounds' own ratios: {:.2}×)",
                method.name(),
                cost[1] / cost[0],
                median(&paired).ok_or("no run")?
            );
        }
        Ok(())
    }
}

fn main() -> ExitCode {
    run_figure_with(NAME, ABOUT, |args, own: &Options, _| {
        let spec = &own.table;
        let bench = Bench {
            alpha: own.alpha,
            ics: own.ics.unwrap_or(args.pick(192, 2_000, 2_000)),
            collisions: own.collisions.unwrap_or(args.pick(2_000, 20_000, 20_000)),
            repeat: own.repeat.max(1),
            seed: args.seed,
            threads: args.threads,
        };
        let table = if spec.ends_with(".toml") || spec.ends_with(".json") {
            TableFile::load(spec)?
        } else {
            Built::Table(spec.parse::<Table>()?)
        };
        println!(
            "table {spec} ({table}), α {}, {} ICs (scalar {}), {} collisions, {} thread(s), median of {}",
            bench.alpha,
            bench.ics,
            bench.scalar_ics(),
            bench.collisions,
            args.thread_count(),
            bench.repeat
        );
        match table {
            Built::Table(t) => t.visit(&bench),
            Built::Segments(t) => (&bench).visit(&t),
        }
    })
}
