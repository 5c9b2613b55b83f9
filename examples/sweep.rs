//! λ(α) on one table: the machine interface for scripts and other tools.
//!
//! ```text
//! cargo run --release --example sweep -- --table stadium:a=1 --alphas 0,0.5,1 \
//!     --ics 1000 --collisions 10000 --method fd --seed 1 --json sweep.json \
//!     [--sampler paper|microcanonical] [--threads T] [--extended]
//! ```
//!
//! For every α it runs an [`Ensemble`] of `--ics` initial conditions
//! (indices `0..N` of seed `--seed`) for `--collisions` collisions each,
//! prints a row of a table, and (re)writes the JSON file after each point so
//! a long sweep leaves its finished points behind:
//!
//! ```json
//! {"table": "stadium:a=1", "method": "fd", "sampler": "paper", "seed": 1,
//!  "delta0": 1e-7, "threshold": 0.01, "version": "0.1.0",
//!  "points": [{"alpha": 0.5, "mean": 0.18, "sem": 0.002, "median": 0.2,
//!              "chaotic_fraction": 0.9, "n_ics": 1000, "n_collisions": 10000,
//!              "wall_time_s": 1.1, "std": 0.05, "conditional_mean": 0.2,
//!              "collision_rate": 1.2}]}
//! ```
//!
//! `n_collisions` is the number of collisions **per initial condition**;
//! `wall_time_s` the time spent on that point. Exponents are per unit time.
//! Results are bitwise the same for any `--threads`.
//!
//! SPEC is `circle`, `rectangle:L=1,H=1`, `stadium:a=1` or `sinai:L=2,R=1`
//! (any values). α must lie in the physical range [0, 1] unless
//! `--extended` is given. Bad arguments print a message and exit with code 2;
//! a failure while computing exits with code 1.

use std::path::PathBuf;
use std::process::ExitCode;

use serde_json::{Value, json};
use spinball_analysis::{Ensemble, LyapunovEstimate, Method, Threads};
use spinball_core::{Sampler, SpinLaw, SpinLawError};
use spinball_geometry::Table;

const USAGE: &str = "\
usage: sweep --table SPEC --alphas A,B,... --ics N --collisions M --method fd|tangent
             --seed S --json PATH [--sampler paper|microcanonical] [--threads T] [--extended]

  --table SPEC     circle | rectangle:L=1,H=1 | stadium:a=1 | sinai:L=2,R=1 (any values)
  --alphas LIST    comma-separated spin parameters, 0 <= alpha <= 1
  --ics N          initial conditions per alpha (>= 2)
  --collisions M   collisions per initial condition (>= 1)
  --method NAME    fd (the paper's finite differences, delta0 = 1e-7) or tangent (exact)
  --seed S         seed of the initial conditions (unsigned integer)
  --json PATH      where to write the results
  --sampler NAME   paper (default) or microcanonical
  --threads T      worker threads (default: all cores); results do not depend on it
  --extended       allow alpha > 1 (mathematical extension towards no-slip)";

/// The command line, read.
struct Args {
    table: Table,
    laws: Vec<SpinLaw>,
    ics: u64,
    collisions: u64,
    method: Method,
    seed: u64,
    json: PathBuf,
    sampler: Sampler,
    threads: Threads,
}

fn parse_args(raw: &[String]) -> Result<Args, String> {
    let mut values: Vec<(&str, String)> = Vec::new();
    let mut extended = false;
    let mut it = raw.iter();
    while let Some(arg) = it.next() {
        let Some(flag) = arg.strip_prefix("--") else {
            return Err(format!("unexpected argument `{arg}`"));
        };
        let (name, inline) = match flag.split_once('=') {
            Some((n, v)) => (n, Some(v.to_string())),
            None => (flag, None),
        };
        const KNOWN: [&str; 9] = [
            "table",
            "alphas",
            "ics",
            "collisions",
            "method",
            "seed",
            "json",
            "sampler",
            "threads",
        ];
        if name == "extended" {
            if inline.is_some() {
                return Err("--extended takes no value".into());
            }
            extended = true;
            continue;
        }
        let Some(&name) = KNOWN.iter().find(|k| **k == name) else {
            return Err(format!("unknown option `--{name}`"));
        };
        if values.iter().any(|(n, _)| *n == name) {
            return Err(format!("--{name} given twice"));
        }
        let value = match inline {
            Some(v) => v,
            None => it
                .next()
                .filter(|v| !v.starts_with("--"))
                .ok_or_else(|| format!("--{name} needs a value"))?
                .clone(),
        };
        values.push((name, value));
    }
    let get = |name: &str| {
        values
            .iter()
            .find(|(n, _)| *n == name)
            .map(|(_, v)| v.as_str())
    };
    let required = |name: &str| get(name).ok_or_else(|| format!("missing --{name}"));

    let table: Table = required("table")?
        .parse()
        .map_err(|e| format!("--table: {e}"))?;
    let laws = required("alphas")?
        .split(',')
        .map(|a| {
            let a = a.trim();
            let alpha: f64 = a
                .parse()
                .map_err(|_| format!("--alphas: `{a}` is not a number"))?;
            let law = if extended {
                SpinLaw::extended(alpha)
            } else {
                SpinLaw::new(alpha)
            };
            law.map_err(|e| match e {
                SpinLawError::Unphysical(_) => {
                    format!(
                        "--alphas: alpha = {alpha} is outside [0, 1]; pass --extended to allow it"
                    )
                }
                e => format!("--alphas: {e}"),
            })
        })
        .collect::<Result<Vec<SpinLaw>, String>>()?;
    let integer = |name: &str, min: u64| -> Result<u64, String> {
        let v = required(name)?;
        let n: u64 = v
            .parse()
            .map_err(|_| format!("--{name}: `{v}` is not a non-negative integer"))?;
        if n < min {
            return Err(format!("--{name} must be at least {min}, got {n}"));
        }
        Ok(n)
    };
    let ics = integer("ics", 2)?;
    let collisions = integer("collisions", 1)?;
    let seed = integer("seed", 0)?;
    let method: Method = required("method")?
        .parse()
        .map_err(|e| format!("--method: {e}"))?;
    let sampler = match get("sampler") {
        Some(s) => s.parse().map_err(|e| format!("--sampler: {e}"))?,
        None => Sampler::Paper,
    };
    let threads = match get("threads") {
        Some(_) => Threads::Fixed(integer("threads", 1)? as usize),
        None => Threads::All,
    };
    let json = PathBuf::from(required("json")?);
    Ok(Args {
        table,
        laws,
        ics,
        collisions,
        method,
        seed,
        json,
        sampler,
        threads,
    })
}

fn point(est: &LyapunovEstimate) -> Value {
    json!({
        "alpha": est.alpha,
        "mean": est.mean,
        "sem": est.sem,
        "median": est.median,
        "chaotic_fraction": est.chaotic_fraction,
        "n_ics": est.n_ics,
        "n_collisions": est.collisions_per_ic,
        "wall_time_s": est.wall_time_s,
        "std": est.std,
        "conditional_mean": est.conditional_mean,
        "collision_rate": est.collision_rate,
    })
}

fn document(args: &Args, points: &[Value]) -> Value {
    let delta0 = match args.method {
        Method::FiniteDifference { delta0 } => Some(delta0),
        _ => None,
    };
    json!({
        "table": args.table.to_string(),
        "method": args.method.name(),
        "sampler": args.sampler.name(),
        "seed": args.seed,
        "delta0": delta0,
        "threshold": spinball_analysis::CHAOS_THRESHOLD,
        "version": env!("CARGO_PKG_VERSION"),
        "points": points,
    })
}

fn write(path: &PathBuf, doc: &Value) -> Result<(), String> {
    let text = serde_json::to_string_pretty(doc).map_err(|e| e.to_string())?;
    std::fs::write(path, text + "\n").map_err(|e| format!("cannot write {}: {e}", path.display()))
}

fn main() -> ExitCode {
    let raw: Vec<String> = std::env::args().skip(1).collect();
    if raw.iter().any(|a| a == "-h" || a == "--help") {
        println!("{USAGE}");
        return ExitCode::SUCCESS;
    }
    let args = match parse_args(&raw) {
        Ok(a) => a,
        Err(msg) => {
            eprintln!("error: {msg}\n\n{USAGE}");
            return ExitCode::from(2);
        }
    };
    // Fail on an unwritable path now, not after the computation.
    let mut points = Vec::new();
    if let Err(msg) = write(&args.json, &document(&args, &points)) {
        eprintln!("error: --json: {msg}");
        return ExitCode::from(2);
    }

    println!(
        "{} | {} | sampler {} | seed {} | {} ICs x {} collisions",
        args.table,
        args.method.name(),
        args.sampler,
        args.seed,
        args.ics,
        args.collisions
    );
    println!(
        "{:>8} {:>10} {:>9} {:>10} {:>7} {:>9}",
        "alpha", "lambda", "SEM", "median", "f_ch", "time/s"
    );
    for &law in &args.laws {
        let alpha = law.alpha();
        let estimate = Ensemble::new(args.table, law)
            .with_sampler(args.sampler)
            .with_seed(args.seed)
            .with_ics(args.ics)
            .with_collisions(args.collisions)
            .with_method(args.method)
            .with_threads(args.threads)
            .run();
        let est = match estimate {
            Ok(est) => est,
            Err(e) => {
                eprintln!("error: alpha = {alpha}: {e}");
                return ExitCode::FAILURE;
            }
        };
        println!(
            "{:>8} {:>10.5} {:>9.5} {:>10.5} {:>7.3} {:>9.2}",
            alpha, est.mean, est.sem, est.median, est.chaotic_fraction, est.wall_time_s
        );
        points.push(point(&est));
        if let Err(msg) = write(&args.json, &document(&args, &points)) {
            eprintln!("error: {msg}");
            return ExitCode::FAILURE;
        }
    }
    println!("wrote {}", args.json.display());
    ExitCode::SUCCESS
}
