//! Nanoseconds per IC-step of every lane kernel on every instruction set this
//! CPU has, against the scalar path.
//!
//! ```text
//! cargo run --release -p spinball-lanes --example lanes_speed -- \
//!     [--ics 4000] [--collisions 20000] [--threads 2] [--table stadium:a=1] \
//!     [--alpha 0.5] [--isa all|avx512|avx2|baseline] [--kernel all|plain|fd|tangent|spectrum] \
//!     [--repeat 1] [--scalar] [--qr-interval 1]
//! ```
//!
//! The defaults are the issue's benchmark: stadium `a = 1`, α = 0.5, 4000
//! initial conditions × 20000 collisions on 2 threads.
//!
//! `--table` takes a built-in table's spec (`stadium:a=1`, `sinai:L=2,R=1`,
//! ...) or one of these tables built from segments (`SegmentTable`):
//! `segments:stadium` (the stadium `a = 1`: two lines and two half-circle
//! arcs), `segments:sinai` (the Sinai table `L = 2, R = 1`: four lines and a
//! circular hole), `segments:mushroom` (the mushroom of the `SegmentTable`
//! docs) and `segments:gon20` (a non-convex 20-gon, no two walls parallel). Each line prints the
//! median over `--repeat` runs of the wall time per initial condition and
//! collision (the whole run: all threads together) and of the CPU time per
//! IC-step (summed over threads: the cost per core, which stays meaningful
//! when other processes share the machine; Linux only). `--qr-interval k`
//! runs the lane spectrum kernel with Gram–Schmidt every `k` collisions
//! (the scalar reference keeps one per collision).

use std::time::Instant;

use spinball_core::{Sampler, SpinLaw, State, TangentVector, ic_rng, random_direction};
use spinball_geometry::{
    ArcSegment, Boundary, DVec2, LineSegment, Segment, SegmentTable, Table, TableVisitor,
};
use spinball_lanes::{Isa, LaneBilliard};

/// The table to run: a built-in one or one built from segments.
enum Subject {
    Builtin(Table),
    Segments(SegmentTable),
}

impl Subject {
    fn parse(spec: &str) -> Result<Subject, Box<dyn std::error::Error>> {
        use std::f64::consts::{FRAC_PI_2, PI, TAU};
        let p = DVec2::new;
        let line = |a, b| LineSegment::new(a, b).map(Segment::Line);
        let arc = |c, r, start, sweep| ArcSegment::new(c, r, start, sweep).map(Segment::Arc);
        let table = match spec {
            "segments:stadium" => SegmentTable::new(vec![
                line(p(-1.0, -1.0), p(1.0, -1.0))?,
                arc(p(1.0, 0.0), 1.0, -FRAC_PI_2, PI)?,
                line(p(1.0, 1.0), p(-1.0, 1.0))?,
                arc(p(-1.0, 0.0), 1.0, FRAC_PI_2, PI)?,
            ])?,
            "segments:sinai" => SegmentTable::with_holes(
                vec![
                    line(p(-2.0, -2.0), p(2.0, -2.0))?,
                    line(p(2.0, -2.0), p(2.0, 2.0))?,
                    line(p(2.0, 2.0), p(-2.0, 2.0))?,
                    line(p(-2.0, 2.0), p(-2.0, -2.0))?,
                ],
                vec![vec![arc(DVec2::ZERO, 1.0, 0.0, -TAU)?]],
            )?,
            "segments:mushroom" => {
                let (r, w, h) = (1.0, 0.3, 1.0);
                SegmentTable::new(vec![
                    line(p(-w, -h), p(w, -h))?,
                    line(p(w, -h), p(w, 0.0))?,
                    line(p(w, 0.0), p(r, 0.0))?,
                    arc(DVec2::ZERO, r, 0.0, PI)?,
                    line(p(-r, 0.0), p(-w, 0.0))?,
                    line(p(-w, 0.0), p(-w, -h))?,
                ])?
            }
            "segments:gon20" => {
                // Star-shaped, radii alternating about 1 and 0.8: no two
                // walls parallel, so none is cast as a pair.
                let v: Vec<DVec2> = (0..20)
                    .map(|k| {
                        let radius = if k % 2 == 0 {
                            1.0
                        } else {
                            0.8 + 0.01 * k as f64
                        };
                        DVec2::from_angle(TAU * k as f64 / 20.0) * radius
                    })
                    .collect();
                SegmentTable::polygon(&v)?
            }
            other => return Ok(Subject::Builtin(other.parse()?)),
        };
        Ok(Subject::Segments(table))
    }
}

struct Args {
    ics: u64,
    collisions: u64,
    threads: usize,
    table: String,
    alpha: f64,
    isas: Vec<Isa>,
    kernels: Vec<String>,
    repeat: usize,
    scalar: bool,
    qr_interval: u32,
}

fn parse() -> Result<Args, Box<dyn std::error::Error>> {
    let mut a = Args {
        ics: 4000,
        collisions: 20_000,
        threads: 2,
        table: "stadium:a=1".to_string(),
        alpha: 0.5,
        isas: Isa::available(),
        kernels: ["plain", "fd", "tangent", "spectrum"]
            .map(String::from)
            .to_vec(),
        repeat: 1,
        scalar: false,
        qr_interval: 1,
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
            "--table" => a.table = value,
            "--alpha" => a.alpha = value.parse()?,
            "--repeat" => a.repeat = value.parse()?,
            "--qr-interval" => a.qr_interval = value.parse()?,
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

type Outcome = Result<(), Box<dyn std::error::Error>>;

fn main() -> Outcome {
    let a = parse()?;
    match Subject::parse(&a.table)? {
        // The concrete built-in table, so the scalar path runs with static
        // dispatch as the ensembles do.
        Subject::Builtin(table) => table.visit(Bench { a: &a }),
        Subject::Segments(table) => bench(&a, &table),
    }
}

/// [`bench`] with the concrete built-in table.
struct Bench<'a> {
    a: &'a Args,
}

impl TableVisitor for Bench<'_> {
    type Output = Outcome;
    fn visit<B: Boundary + Clone + Send + Sync>(self, table: &B) -> Outcome {
        bench(self.a, table)
    }
}

fn bench<B: Boundary + Clone + Sync>(a: &Args, table: &B) -> Outcome {
    let law = SpinLaw::extended(a.alpha)?;
    let mut starts: Vec<State> = Vec::new();
    let mut dirs: Vec<TangentVector> = Vec::new();
    for i in 0..a.ics {
        let mut rng = ic_rng(1, i);
        starts.push(Sampler::Paper.sample(table, &law, &mut rng));
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
        let lanes = LaneBilliard::new(table.clone(), law)?
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
                            .spectrum(&starts, &frames, a.collisions, a.qr_interval)?
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
        scalar(a, table, &law, &starts, &dirs)?;
    }
    Ok(())
}

/// The scalar path on one thread, over a tenth of the initial conditions,
/// for the kernels asked for (median of `--repeat` runs): the
/// specification the lanes are tested against, and the speed they replace.
/// `Billiard::step` for the plain map; the finite-difference, tangent and
/// spectrum loops are those of `spinball-analysis`'s `largest_lyapunov` and
/// `lyapunov_spectrum`, written out here with `spinball-core` (this crate
/// sits below `spinball-analysis`).
fn scalar<B: Boundary + Clone>(
    a: &Args,
    table: &B,
    law: &SpinLaw,
    starts: &[State],
    dirs: &[TangentVector],
) -> Outcome {
    use spinball_core::{Ball, Billiard};
    let billiard = Billiard::new(table.clone(), *law);
    let n = (starts.len() / 10).max(1);
    let steps = n as f64 * a.collisions as f64;
    let offset = |z: &State, d: TangentVector| {
        let (z, d) = (z.to_array(), d.to_array());
        State::from_array(std::array::from_fn(|i| z[i] + d[i]))
    };
    for k in &a.kernels {
        let mut times = Vec::new();
        let mut cpu = Vec::new();
        for _ in 0..a.repeat {
            let c0 = cpu_seconds();
            let t0 = Instant::now();
            for (s, dir) in starts.iter().zip(dirs).take(n) {
                let mut ball = billiard.launch(*s)?;
                match k.as_str() {
                    "plain" => {
                        for _ in 0..a.collisions {
                            billiard.step(&mut ball)?;
                        }
                    }
                    "fd" => {
                        const DELTA0: f64 = 1e-7;
                        let mut shadow = Ball::new(offset(s, *dir * DELTA0), law)?;
                        let mut logs = LogSum::default();
                        for _ in 0..a.collisions {
                            billiard.step(&mut ball)?;
                            billiard.step(&mut shadow)?;
                            let (p, q) = (ball.state().to_array(), shadow.state().to_array());
                            let d = TangentVector::from_array(std::array::from_fn(|i| q[i] - p[i]));
                            let dist = d.norm();
                            logs.push(dist / DELTA0);
                            shadow = Ball::new(offset(ball.state(), d * (DELTA0 / dist)), law)?;
                        }
                        std::hint::black_box(logs.total());
                    }
                    "tangent" => {
                        let mut v = [*dir];
                        let mut logs = LogSum::default();
                        for _ in 0..a.collisions {
                            billiard.step_tangent(&mut ball, &mut v)?;
                            let norm = v[0].norm();
                            logs.push(norm);
                            v[0] = v[0] * (1.0 / norm);
                        }
                        std::hint::black_box(logs.total());
                    }
                    "spectrum" => {
                        let mut v: [TangentVector; 5] = std::array::from_fn(|j| {
                            let mut z = [0.0; 5];
                            z[j] = 1.0;
                            TangentVector::from_array(z)
                        });
                        let mut logs = [LogSum::default(); 5];
                        for _ in 0..a.collisions {
                            billiard.step_tangent(&mut ball, &mut v)?;
                            for i in 0..5 {
                                for j in 0..i {
                                    let p = v[i].dot(&v[j]);
                                    v[i] = v[i] - v[j] * p;
                                }
                                let norm = v[i].norm();
                                v[i] = v[i] * (1.0 / norm);
                                logs[i].push(norm);
                            }
                        }
                        std::hint::black_box(logs[0].total());
                    }
                    other => return Err(format!("unknown kernel {other}").into()),
                }
            }
            times.push(t0.elapsed().as_secs_f64());
            if let (Some(c0), Some(c1)) = (c0, cpu_seconds()) {
                cpu.push(c1 - c0);
            }
        }
        let c = if cpu.is_empty() {
            f64::NAN
        } else {
            median(cpu)
        };
        println!(
            "scalar    {k:<9} wall {:8.3} ns/IC-step  cpu {:8.3} ns/IC-step  (1 thread)",
            median(times) / steps * 1e9,
            c / steps * 1e9
        );
    }
    Ok(())
}

/// `Σ ln` of growth factors with one `ln` per `1e±150` of their product (as
/// the scalar path keeps it).
#[derive(Clone, Copy)]
struct LogSum {
    product: f64,
    sum: f64,
}

impl Default for LogSum {
    fn default() -> Self {
        LogSum {
            product: 1.0,
            sum: 0.0,
        }
    }
}

impl LogSum {
    fn push(&mut self, factor: f64) {
        self.product *= factor;
        if !(1e-150..=1e150).contains(&self.product) {
            self.sum += self.product.ln();
            self.product = 1.0;
        }
    }
    fn total(&self) -> f64 {
        self.sum + self.product.ln()
    }
}
