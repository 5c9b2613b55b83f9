//! Plain against multilevel ensembles at one target total error: wall time,
//! stated total error and the deviation from the references of
//! docs/ACCURACY.md, per scene, with the planner's choice and its reason.
//!
//! ```text
//! cargo run --release --example multilevel -- [--quick] [--target 1e-3]
//!     [--repeat N] [--threads N] [--seed S] [--scene K]
//! ```
//!
//! For each scene (stadium a = 1 at α = 0.5 and 0, Sinai L = 2, R = 1 at
//! α = 1; exact tangent dynamics in lanes) a pilot plans, the planner
//! chooses plain or multilevel, and `compare_estimators` runs both toward
//! the target `--repeat` times with seeds `S, S+1, …` in alternating order
//! (the multilevel run adaptively, lengthening its levels where its own
//! bias fit finds the bias at the plain run's length above the target; the
//! plain run at the same length and bias with its stop rule on total
//! error), timed in processor seconds; it prints the medians, the pulls
//! against the references and the speed-up at equal stated error. The
//! `work_precision` example runs the same comparison at several targets
//! for the chart of docs/ACCURACY.md. `--scene K` runs only scene `K`
//! (0, 1, 2 in the order above). `--quick` (CI): target 1%, small
//! pilots, one repeat, a second or two.
//!
//! `--draw-cost` measures instead what one draw of the top level costs on
//! the lane engine (stadium a = 1, α = 0.5, levels up to 25 000
//! collisions, tangent and finite differences): each trajectory read at
//! `T_0`, `T_L−1` and `T_L` by stopping and resuming one run, against
//! rerunning it to each length (how the lane engine read its levels
//! before it could resume), in alternating rounds (`--repeat`, default 5),
//! medians of the process CPU time, and checks that both read the same
//! numbers bitwise.

use spinball::analysis::estimators::Method;
use spinball::analysis::precision::{
    EnsembleLevels, LevelSamples, Measurement, Planner, compare_estimators, default_levels,
    process_cpu_seconds,
};
use spinball::analysis::run::{Ensemble, Threads};
use spinball::prelude::*;

/// Scene, α, λ_ref ± SEM (docs/ACCURACY.md, 16 000-IC tangent references).
const SCENES: [(&str, f64, f64, f64); 3] = [
    ("stadium:a=1", 0.5, 0.18212, 0.00047),
    ("sinai:L=2,R=1", 1.0, 0.10296, 0.00031),
    ("stadium:a=1", 0.0, 0.42965, 0.00007),
];

struct Options {
    quick: bool,
    target: f64,
    repeat: u64,
    threads: Threads,
    seed: u64,
    draw_cost: bool,
    scene: Option<usize>,
}

fn options() -> Result<Options, String> {
    let mut o = Options {
        quick: false,
        target: 1e-3,
        repeat: 3,
        threads: Threads::All,
        seed: 2030,
        draw_cost: false,
        scene: None,
    };
    let mut explicit_repeat = false;
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        let mut value = |name: &str| args.next().ok_or_else(|| format!("{name} needs a value"));
        match a.as_str() {
            "--quick" => o.quick = true,
            "--draw-cost" => o.draw_cost = true,
            "--target" => {
                o.target = value("--target")?
                    .parse()
                    .map_err(|e| format!("--target: {e}"))?
            }
            "--repeat" => {
                explicit_repeat = true;
                o.repeat = value("--repeat")?
                    .parse()
                    .map_err(|e| format!("--repeat: {e}"))?
            }
            "--scene" => {
                o.scene = Some(
                    value("--scene")?
                        .parse()
                        .map_err(|e| format!("--scene: {e}"))?,
                );
            }
            "--seed" => {
                o.seed = value("--seed")?
                    .parse()
                    .map_err(|e| format!("--seed: {e}"))?
            }
            "--threads" => {
                o.threads = Threads::Fixed(
                    value("--threads")?
                        .parse()
                        .map_err(|e| format!("--threads: {e}"))?,
                );
            }
            other => return Err(format!("unknown argument {other}")),
        }
    }
    if o.quick {
        o.target = 1e-2;
        o.repeat = 1;
    } else if o.draw_cost && !explicit_repeat {
        o.repeat = 5;
    }
    if !(o.target > 0.0 && o.target.is_finite()) || o.repeat == 0 {
        return Err("--target must be > 0 and --repeat >= 1".into());
    }
    Ok(o)
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    let n = v.len();
    if n % 2 == 1 {
        v[n / 2]
    } else {
        0.5 * (v[n / 2 - 1] + v[n / 2])
    }
}

/// `--draw-cost`: see the module docs.
fn draw_cost(o: &Options) -> Result<(), Box<dyn std::error::Error>> {
    let n: u64 = if o.quick { 96 } else { 960 };
    let levels = default_levels(if o.quick { 2_000 } else { 25_000 }).expect("four levels");
    let top = levels.len() - 1;
    let reads = [levels[0], levels[top - 1], levels[top]];
    println!(
        "draw cost of level {top} (reads {reads:?}), {n} ICs, stadium a = 1, α = 0.5, lanes; {} rounds, medians of process CPU time",
        o.repeat
    );
    for method in [Method::Tangent, Method::default()] {
        let scene = Ensemble::new(Stadium::new(1.0)?, SpinLaw::new(0.5)?)
            .with_method(method)
            .with_threads(o.threads)
            .with_seed(o.seed);
        let source = EnsembleLevels::new(scene.clone(), levels.clone())?;
        let seeded = scene.with_seed(source.level_seed(top));
        let (mut resumed, mut rerun) = (Vec::new(), Vec::new());
        for _ in 0..o.repeat {
            let c = process_cpu_seconds();
            let draws = LevelSamples::run(&source, top, 0..n)?.draws;
            resumed.push(
                process_cpu_seconds()
                    .zip(c)
                    .map_or(f64::NAN, |(b, a)| b - a),
            );
            let c = process_cpu_seconds();
            let runs = reads
                .iter()
                .map(|&t| seeded.clone().with_collisions(t).trajectories(0..n))
                .collect::<Result<Vec<_>, _>>()?;
            rerun.push(
                process_cpu_seconds()
                    .zip(c)
                    .map_or(f64::NAN, |(b, a)| b - a),
            );
            for (i, d) in draws.iter().enumerate() {
                let same = [d.short, d.coarse, d.fine]
                    .iter()
                    .zip(&runs)
                    .all(|(x, r)| x.to_bits() == r[i].exponent.to_bits());
                assert!(same, "draw {i} differs: {d:?}");
            }
        }
        let (a, b) = (median(resumed), median(rerun));
        let per = |s: f64| 1e9 * s / (n as f64 * levels[top] as f64);
        println!(
            "  {method:?}: resumed {a:.2} s ({:.1} ns per IC-step of T_L), rerun {b:.2} s ({:.1} ns); rerun/resumed {:.2}",
            per(a),
            per(b),
            b / a
        );
    }
    Ok(())
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let o = options()?;
    if o.draw_cost {
        return draw_cost(&o);
    }
    let (pilot_ics, pilot_t, ml_pilot) = if o.quick {
        (64, vec![250, 500, 1_000, 2_000], 32)
    } else {
        (256, vec![1_000, 2_000, 4_000, 8_000], 64)
    };
    println!(
        "target {:.2}% total error, {} repeat(s), medians of processor time; times at target scaled as t·(error/target)²",
        100.0 * o.target,
        o.repeat
    );
    for (k, (spec, alpha, lref, lref_sem)) in SCENES.into_iter().enumerate() {
        if o.scene.is_some_and(|s| s != k) {
            continue;
        }
        let table: Table = spec.parse()?;
        let scene = Ensemble::new(table, SpinLaw::new(alpha)?)
            .with_method(Method::Tangent)
            .with_threads(o.threads)
            .with_seed(o.seed + 1000);
        let planner = Planner::pilot(
            &scene.clone().with_ics(pilot_ics),
            &[Method::Tangent],
            &pilot_t,
        )?;
        let reference = Measurement::new(lref, lref_sem);
        let seeds = o.seed..o.seed + o.repeat;
        let c = compare_estimators(&scene, &planner, reference, o.target, ml_pilot, seeds)?;
        println!("\n{spec} α = {alpha} (λ_ref {lref} ± {lref_sem}) {c}");
        if let Some(e) = &c.levels {
            print!(
                "  multilevel, first repeat:\n    {}",
                e.to_string().replace('\n', "\n    ")
            );
            println!();
        }
    }
    Ok(())
}
