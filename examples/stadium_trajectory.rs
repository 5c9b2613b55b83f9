//! Run one trajectory in the Bunimovich stadium and print each collision with
//! the energy and the conserved quantity Q = v∥ − αu.
//!
//! ```text
//! cargo run --release --example stadium_trajectory -- [--alpha 0.5] [--a 1] [--collisions 20] [--seed N] [--quick]
//! ```
//!
//! The initial condition is number 0 of the seed from the paper's sampler.
//! `--quick` prints 10 collisions unless `--collisions` says otherwise.

use std::process::ExitCode;

use spinball::prelude::*;
use spinball_figures::run_figure_with;

/// The example's own options.
#[derive(Debug, clap::Args)]
struct Options {
    /// spin parameter
    #[arg(
        long,
        value_name = "A",
        default_value_t = 0.5,
        allow_negative_numbers = true
    )]
    alpha: f64,
    /// half-length of the flat walls
    #[arg(
        long,
        value_name = "A",
        default_value_t = 1.0,
        allow_negative_numbers = true
    )]
    a: f64,
    /// collisions to print (default 20, 10 with --quick)
    #[arg(long, value_name = "N")]
    collisions: Option<u64>,
}

fn main() -> ExitCode {
    let about = "One trajectory in the stadium, collision by collision, with E − E0 and Q.";
    run_figure_with("stadium_trajectory", about, |args, own: &Options, _| {
        let (alpha, a) = (own.alpha, own.a);
        let collisions: u64 = own.collisions.unwrap_or(args.pick(10, 20, 20));
        let billiard = Billiard::new(Stadium::new(a)?, SpinLaw::new(alpha)?);
        let start = Sampler::Paper.initial_state(billiard.table(), billiard.law(), args.seed, 0);
        let mut ball = billiard.launch(start)?;
        let e0 = billiard.energy(&start);
        println!(
            "stadium a = {a}, alpha = {alpha}, seed {}: start {start:?}, E0 = {e0}",
            args.seed
        );
        println!(
            "{:>6} {:>4} {:>10} {:>10} {:>10} {:>10} {:>10} {:>12} {:>10}",
            "n", "wall", "t", "x", "y", "v_par", "u", "E - E0", "Q"
        );
        let mut time = 0.0;
        for n in 1..=collisions {
            let c = billiard.step(&mut ball)?;
            time += c.time();
            println!(
                "{n:>6} {:>4} {time:>10.4} {:>10.5} {:>10.5} {:>10.5} {:>10.5} {:>12.3e} {:>10.6}",
                c.wall(),
                c.point().x,
                c.point().y,
                c.v_par_after,
                c.spin_after,
                billiard.energy(ball.state()) - e0,
                c.q,
            );
        }
        Ok(())
    })
}
