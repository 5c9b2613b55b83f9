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
use spinball_plot::cli::Opt;
use spinball_plot::run_figure_with;

const OPTIONS: [Opt; 3] = [
    Opt::value("alpha", "A", "spin parameter (default 0.5)"),
    Opt::value("a", "A", "half-length of the flat walls (default 1)"),
    Opt::value(
        "collisions",
        "N",
        "collisions to print (default 20, 10 with --quick)",
    ),
];

fn main() -> ExitCode {
    let about = "One trajectory in the stadium, collision by collision, with E − E0 and Q.";
    run_figure_with("stadium_trajectory", about, &OPTIONS, |args, _| {
        let alpha = args.extra.get_or("alpha", 0.5)?;
        let a = args.extra.get_or("a", 1.0)?;
        let collisions: u64 = args.extra.get_or("collisions", args.pick(10, 20, 20))?;
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
