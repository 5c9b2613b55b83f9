//! Run one trajectory in the Bunimovich stadium and print each collision with
//! the energy and the conserved quantity Q = v∥ − αu.
//!
//! ```text
//! cargo run --release --example stadium_trajectory -- [--alpha 0.5] [--a 1] [--collisions 20] [--seed 1]
//! ```

use std::process::ExitCode;

use spinball::prelude::*;

fn main() -> ExitCode {
    let mut alpha = 0.5;
    let mut a = 1.0;
    let mut collisions: u64 = 20;
    let mut seed = 1;
    let mut args = std::env::args().skip(1);
    while let Some(flag) = args.next() {
        if flag == "--quick" {
            collisions = 10;
            continue;
        }
        let Some(value) = args.next() else {
            eprintln!("error: {flag} needs a value");
            return ExitCode::from(2);
        };
        let ok = match flag.as_str() {
            "--alpha" => value.parse().map(|v| alpha = v).is_ok(),
            "--a" => value.parse().map(|v| a = v).is_ok(),
            "--collisions" => value.parse().map(|v| collisions = v).is_ok(),
            "--seed" => value.parse().map(|v| seed = v).is_ok(),
            _ => {
                eprintln!(
                    "error: unknown option {flag} (expected --alpha, --a, --collisions, --seed, --quick)"
                );
                return ExitCode::from(2);
            }
        };
        if !ok {
            eprintln!("error: cannot read {flag} {value}");
            return ExitCode::from(2);
        }
    }
    match run(alpha, a, collisions, seed) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(2)
        }
    }
}

fn run(alpha: f64, a: f64, collisions: u64, seed: u64) -> Result<(), Box<dyn std::error::Error>> {
    let billiard = Billiard::new(Stadium::new(a)?, SpinLaw::new(alpha)?);
    let start = Sampler::Paper.initial_state(billiard.table(), billiard.law(), seed, 0);
    let mut ball = billiard.launch(start)?;
    let e0 = billiard.energy(&start);
    println!("stadium a = {a}, alpha = {alpha}, seed {seed}: start {start:?}, E0 = {e0}");
    println!(
        "{:>6} {:>4} {:>10} {:>10} {:>10} {:>10} {:>10} {:>12} {:>10}",
        "n", "wall", "t", "x", "y", "v_par", "u", "E - E0", "Q"
    );
    let mut time = 0.0;
    let mut print = |n: u64, c: &Collision, after: &State| {
        time += c.time();
        println!(
            "{n:>6} {:>4} {time:>10.4} {:>10.5} {:>10.5} {:>10.5} {:>10.5} {:>12.3e} {:>10.6}",
            c.wall(),
            c.point().x,
            c.point().y,
            c.v_par_after,
            c.spin_after,
            billiard.energy(after) - e0,
            c.q,
        );
    };
    for n in 1..=collisions {
        let c = billiard.step(&mut ball)?;
        print(n, &c, ball.state());
    }
    Ok(())
}
