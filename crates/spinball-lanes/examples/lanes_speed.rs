//! Nanoseconds per IC-step of every lane kernel on every instruction set this
//! CPU has, against the scalar path.
//!
//! ```text
//! cargo run --release -p spinball-lanes --example lanes_speed -- \
//!     [--ics 4000] [--collisions 20000] [--threads 2] [--table stadium:a=1] \
//!     [--alpha 0.5] [--isa all|avx512|avx2|baseline] [--kernel all|plain|fd|tangent|spectrum] \
//!     [--repeat 1] [--scalar]
//! ```
//!
//! The defaults are the issue's benchmark: stadium `a = 1`, α = 0.5, 4000
//! initial conditions × 20000 collisions on 2 threads. Each line prints the
//! median over `--repeat` runs of the wall time per initial condition and
//! collision (the whole run: all threads together) and of the CPU time per
//! IC-step (summed over threads: the cost per core, which stays meaningful
//! when other processes share the machine; Linux only).

use std::time::Instant;

use spinball_analysis::random_direction;
use spinball_core::{Sampler, SpinLaw, State, TangentVector, ic_rng};
use spinball_geometry::Table;
use spinball_lanes::{Isa, LaneBilliard};

struct Args {
    ics: u64,
    collisions: u64,
    threads: usize,
    table: Table,
    alpha: f64,
    isas: Vec<Isa>,
    kernels: Vec<String>,
    repeat: usize,
    scalar: bool,
}

fn parse() -> Result<Args, Box<dyn std::error::Error>> {
    let mut a = Args {
        ics: 4000,
        collisions: 20_000,
        threads: 2,
        table: "stadium:a=1".parse()?,
        alpha: 0.5,
        isas: Isa::available(),
        kernels: ["plain", "fd", "tangent", "spectrum"]
            .map(String::from)
            .to_vec(),
        repeat: 1,
        scalar: false,
    };
    let mut it = std::env::args().skip(1);
    while let Some(flag) = it.next() {
        if flag == "--scalar" {
            a.scalar = true;
            continue;
        }
        let value = it.next().ok_or(format!("{flag} needs a value"))?;
        match flag.as_str() {
            "--ics" => a.ics = value.parse()?,
            "--collisions" => a.collisions = value.parse()?,
            "--threads" => a.threads = value.parse()?,
            "--table" => a.table = value.parse()?,
            "--alpha" => a.alpha = value.parse()?,
            "--repeat" => a.repeat = value.parse()?,
            "--isa" if value != "all" => a.isas = vec![value.parse::<Isa>()?.checked()?],
            "--isa" => {}
            "--kernel" if value != "all" => a.kernels = vec![value],
            "--kernel" => {}
            _ => return Err(format!("unknown flag {flag}").into()),
        }
    }
    Ok(a)
}

/// CPU time of this process so far (user + system, all threads), from
/// `/proc/self/stat` (10 ms resolution); `None` off Linux.
fn cpu_seconds() -> Option<f64> {
    let stat = std::fs::read_to_string("/proc/self/stat").ok()?;
    // Fields after the parenthesised command name; utime and stime are the
    // 14th and 15th fields overall.
    let rest = stat.rsplit_once(')')?.1;
    let f: Vec<&str> = rest.split_whitespace().collect();
    let utime: f64 = f.get(11)?.parse().ok()?;
    let stime: f64 = f.get(12)?.parse().ok()?;
    Some((utime + stime) / 100.0)
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let a = parse()?;
    let law = SpinLaw::extended(a.alpha)?;
    let mut starts: Vec<State> = Vec::new();
    let mut dirs: Vec<TangentVector> = Vec::new();
    for i in 0..a.ics {
        let mut rng = ic_rng(1, i);
        starts.push(Sampler::Paper.sample(&a.table, &law, &mut rng));
        dirs.push(random_direction(&mut rng));
    }
    let frames: Vec<[TangentVector; 5]> = (0..a.ics as usize)
        .map(|i| {
            std::array::from_fn(|j| {
                let mut z = [0.0; 5];
                z[(i + j) % 5] = 1.0;
                TangentVector::from_array(z)
            })
        })
        .collect();
    let steps = (a.ics * a.collisions) as f64;
    println!(
        "table {} alpha {} ics {} collisions {} threads {} (median of {})",
        a.table, a.alpha, a.ics, a.collisions, a.threads, a.repeat
    );
    for isa in &a.isas {
        let lanes = LaneBilliard::new(a.table, law)?
            .with_isa(*isa)?
            .with_threads(a.threads)?;
        for k in &a.kernels {
            let mut times = Vec::new();
            let mut cpu = Vec::new();
            let mut check = 0.0;
            for _ in 0..a.repeat {
                let c0 = cpu_seconds();
                let t0 = Instant::now();
                check = match k.as_str() {
                    "plain" => lanes
                        .trajectories(&starts, a.collisions)?
                        .iter()
                        .map(|f| f.time)
                        .sum(),
                    "fd" => {
                        lanes
                            .lyapunov_fd(&starts, &dirs, 1e-7, a.collisions)?
                            .iter()
                            .map(|s| s.exponent())
                            .sum::<f64>()
                            / a.ics as f64
                    }
                    "tangent" => {
                        lanes
                            .lyapunov_tangent(&starts, &dirs, a.collisions)?
                            .iter()
                            .map(|s| s.exponent())
                            .sum::<f64>()
                            / a.ics as f64
                    }
                    "spectrum" => {
                        lanes
                            .spectrum(&starts, &frames, a.collisions, 1)?
                            .iter()
                            .map(|s| s.exponents()[0])
                            .sum::<f64>()
                            / a.ics as f64
                    }
                    other => return Err(format!("unknown kernel {other}").into()),
                };
                times.push(t0.elapsed().as_secs_f64());
                if let (Some(c0), Some(c1)) = (c0, cpu_seconds()) {
                    cpu.push(c1 - c0);
                }
            }
            let t = median(times);
            let c = if cpu.is_empty() {
                f64::NAN
            } else {
                median(cpu)
            };
            println!(
                "{:<9} {:<9} wall {:8.3} ns/IC-step  cpu {:8.3} ns/IC-step  {:7.3} s  (check {check:.6})",
                isa.name(),
                k,
                t / steps * 1e9,
                c / steps * 1e9,
                t
            );
        }
    }
    if a.scalar {
        scalar(&a, &law, &starts, &dirs)?;
    }
    Ok(())
}

/// The scalar path (`spinball-core`, `spinball-analysis`) on one thread,
/// over a tenth of the initial conditions: the specification the lanes are
/// tested against, and the speed they replace.
fn scalar(
    a: &Args,
    law: &SpinLaw,
    starts: &[State],
    _dirs: &[TangentVector],
) -> Result<(), Box<dyn std::error::Error>> {
    use spinball_analysis::{
        LyapunovOptions, Method, SpectrumOptions, largest_lyapunov, lyapunov_spectrum,
    };
    use spinball_core::Billiard;
    let Table::Stadium(stadium) = a.table else {
        return Err("--scalar is implemented for the stadium".into());
    };
    let billiard = Billiard::new(stadium, *law);
    let n = (starts.len() / 10).max(1);
    let steps = n as f64 * a.collisions as f64;
    let report = |name: &str, (t0, c0): (Instant, Option<f64>)| {
        let cpu = match (c0, cpu_seconds()) {
            (Some(c0), Some(c1)) => (c1 - c0) / steps * 1e9,
            _ => f64::NAN,
        };
        println!(
            "scalar    {name:<9} wall {:8.3} ns/IC-step  cpu {cpu:8.3} ns/IC-step  (1 thread)",
            t0.elapsed().as_secs_f64() / steps * 1e9
        );
    };
    let start = || (Instant::now(), cpu_seconds());
    let t0 = start();
    for s in starts.iter().take(n) {
        let mut ball = billiard.launch(*s)?;
        for _ in 0..a.collisions {
            billiard.step(&mut ball)?;
        }
    }
    report("plain", t0);
    for method in [Method::default(), Method::Tangent] {
        let t0 = start();
        for s in starts.iter().take(n) {
            let mut rng = ic_rng(1, 0);
            let opts = LyapunovOptions::new(a.collisions, method);
            largest_lyapunov(&billiard, *s, &opts, &mut rng)?;
        }
        report(method.name(), t0);
    }
    let t0 = start();
    for s in starts.iter().take(n) {
        let mut rng = ic_rng(1, 0);
        let opts = SpectrumOptions::new(a.collisions, Method::Tangent);
        lyapunov_spectrum(&billiard, *s, &opts, &mut rng)?;
    }
    report("spectrum", t0);
    Ok(())
}
