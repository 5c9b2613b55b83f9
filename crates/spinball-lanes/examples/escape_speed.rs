//! Nanoseconds per collision of escape runs on the stadium with a hole:
//! the scalar path (`Billiard::advance`, one ball at a time) against the
//! lane escape kernel on every instruction set this CPU has.
//!
//! ```text
//! cargo run --release -p spinball-lanes --example escape_speed -- \
//!     [--ics 4000] [--hole 0.1] [--collisions 10000] [--alpha 0.5] [--repeat 3] [--quick]
//! ```
//!
//! The stadium `a = 1` with a hole of arc length `--hole` in the middle of
//! its right cap; the paper's sampler draws `--ics` starts (seed 1), each
//! run until it escapes or `--collisions` collisions, on one thread. Each
//! line prints the median over `--repeat` runs of the wall time per
//! collision (collisions summed over all balls; an escape counts as one
//! more flight), the CPU model and the load average at the start (the
//! machine may be shared). The lanes' records are checked bitwise against
//! the scalar ones. A lane chunk runs until its longest-lived ball ends,
//! so the lanes' gain shrinks as escapes get faster than the budget.

use std::time::Instant;

use spinball_core::{Billiard, Event, Sampler, SpinLaw, State, ic_rng};
use spinball_geometry::SegmentTable;
use spinball_lanes::{Escape, Isa, LaneBilliard};

struct Options {
    ics: u64,
    hole: f64,
    collisions: u64,
    alpha: f64,
    repeat: usize,
}

fn options() -> Result<Options, Box<dyn std::error::Error>> {
    let mut o = Options {
        ics: 4000,
        hole: 0.1,
        collisions: 10_000,
        alpha: 0.5,
        repeat: 3,
    };
    let args: Vec<String> = std::env::args().skip(1).collect();
    let mut i = 0;
    while i < args.len() {
        let value = || args.get(i + 1).ok_or(format!("{} needs a value", args[i]));
        match args[i].as_str() {
            "--quick" => {
                o.ics = 200;
                o.collisions = 2000;
                o.repeat = 1;
                i += 1;
                continue;
            }
            "--ics" => o.ics = value()?.parse()?,
            "--hole" => o.hole = value()?.parse()?,
            "--collisions" => o.collisions = value()?.parse()?,
            "--alpha" => o.alpha = value()?.parse()?,
            "--repeat" => o.repeat = value()?.parse()?,
            other => return Err(format!("unknown option {other}").into()),
        }
        i += 2;
    }
    Ok(o)
}

/// The scalar escape record of one ball (`Billiard::advance` until an
/// escape or the collision budget).
fn scalar(billiard: &Billiard<&SegmentTable>, start: State, collisions: u64) -> Escape {
    let mut ball = billiard.launch(start).expect("the sampler's starts launch");
    let mut e = Escape {
        time: 0.0,
        collisions: 0,
        exit: None,
    };
    while e.collisions < collisions {
        let event = billiard.advance(&mut ball).expect("no step fails here");
        e.time += event.time();
        match event {
            Event::Escape(exit) => {
                e.exit = Some(exit);
                break;
            }
            _ => e.collisions += 1,
        }
    }
    e
}

/// The median of `runs` timings of `f`, in seconds, and its last result.
fn timed<T>(runs: usize, mut f: impl FnMut() -> T) -> (f64, T) {
    let mut times = Vec::new();
    let mut out = None;
    for _ in 0..runs.max(1) {
        let t0 = Instant::now();
        out = Some(f());
        times.push(t0.elapsed().as_secs_f64());
    }
    times.sort_by(f64::total_cmp);
    (times[times.len() / 2], out.expect("at least one run"))
}

fn cpu_model() -> String {
    std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("model name"))
                .and_then(|l| l.split(':').nth(1))
                .map(|m| m.trim().to_string())
        })
        .unwrap_or_else(|| "unknown CPU".into())
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let o = options()?;
    let table = SegmentTable::stadium_with_hole(1.0, 2.0 + 0.5 * std::f64::consts::PI, o.hole)?;
    let law = SpinLaw::new(o.alpha)?;
    let billiard = Billiard::new(&table, law);
    let starts: Vec<State> = (0..o.ics)
        .map(|i| Sampler::Paper.sample(&table, &law, &mut ic_rng(1, i)))
        .collect();
    let load = std::fs::read_to_string("/proc/loadavg").unwrap_or_default();
    println!(
        "escape on the stadium a = 1 with a hole of {} on its cap, α = {}, {} starts, budget {} collisions, 1 thread",
        o.hole, o.alpha, o.ics, o.collisions
    );
    println!(
        "CPU: {}; load average at start: {}",
        cpu_model(),
        load.split_whitespace()
            .take(3)
            .collect::<Vec<_>>()
            .join(" ")
    );
    let (secs, reference) = timed(o.repeat, || {
        starts
            .iter()
            .map(|s| scalar(&billiard, *s, o.collisions))
            .collect::<Vec<_>>()
    });
    let flights: u64 = reference
        .iter()
        .map(|e| e.collisions + u64::from(!e.is_censored()))
        .sum();
    let censored = reference.iter().filter(|e| e.is_censored()).count();
    println!(
        "{} flights, {censored} of {} balls censored",
        flights,
        reference.len()
    );
    let scalar_ns = secs * 1e9 / flights as f64;
    println!(
        "scalar      {scalar_ns:7.2} ns/collision (median of {})",
        o.repeat
    );
    for isa in Isa::available() {
        let lanes = LaneBilliard::new_open(&table, law)?.with_isa(isa)?;
        let (secs, got) = timed(o.repeat, || {
            lanes.escape_times(&starts, o.collisions, f64::INFINITY)
        });
        let got = got?;
        let same = got.iter().zip(&reference).all(|(a, b)| {
            a.collisions == b.collisions && a.exit == b.exit && a.time.to_bits() == b.time.to_bits()
        });
        assert!(same, "lanes and scalar records differ on {isa}");
        let ns = secs * 1e9 / flights as f64;
        println!(
            "lanes {:<7} {ns:7.2} ns/collision, {:.2}× the scalar speed (records bitwise equal)",
            isa.to_string(),
            scalar_ns / ns
        );
    }
    Ok(())
}
