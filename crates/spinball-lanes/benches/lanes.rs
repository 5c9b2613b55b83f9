//! Criterion benches: every lane kernel on every instruction set this CPU
//! has, for the case (stadium `a = 1`, α = 0.5), and the plain
//! kernel on every table at the detected level.
//!
//! `cargo bench -p spinball-lanes --bench lanes`. Throughput is reported in
//! IC-steps (one initial condition advanced by one collision) per second, on
//! one thread; `examples/lanes_speed.rs` measures the full 4000 × 20000 run
//! on two threads.
#![allow(missing_docs)] // criterion_group! generates undocumented functions

use std::hint::black_box;
use std::time::Duration;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use spinball_core::{Sampler, SpinLaw, State, TangentVector, ic_rng, random_direction};
use spinball_geometry::{Circle, Rectangle, Sinai, Stadium, Table};
use spinball_lanes::{Isa, LaneBilliard};

/// Initial conditions per iteration (a multiple of every lane count).
const ICS: u64 = 192;
/// Collisions per initial condition and iteration.
const COLLISIONS: u64 = 2_000;

fn inputs(table: &Table, law: &SpinLaw) -> (Vec<State>, Vec<TangentVector>) {
    (0..ICS)
        .map(|i| {
            let mut rng = ic_rng(9, i);
            let s = Sampler::Paper.sample(table, law, &mut rng);
            (s, random_direction(&mut rng))
        })
        .unzip()
}

fn frames(dirs: &[TangentVector]) -> Vec<[TangentVector; 5]> {
    (0..dirs.len())
        .map(|i| {
            std::array::from_fn(|j| {
                let mut z = [0.0; 5];
                z[(i + j) % 5] = 1.0;
                TangentVector::from_array(z)
            })
        })
        .collect()
}

fn kernels(c: &mut Criterion) {
    let table = Table::from(Stadium::new(1.0).expect("valid"));
    let law = SpinLaw::new(0.5).expect("valid");
    let (starts, dirs) = inputs(&table, &law);
    let frames = frames(&dirs);
    for kernel in ["plain", "fd", "tangent", "spectrum"] {
        let mut g = c.benchmark_group(format!("lanes/stadium/{kernel}"));
        g.throughput(Throughput::Elements(ICS * COLLISIONS))
            .sample_size(10)
            .measurement_time(Duration::from_secs(3));
        for isa in Isa::available() {
            let lanes = LaneBilliard::new(table, law)
                .unwrap()
                .with_isa(isa)
                .expect("available");
            g.bench_function(BenchmarkId::from_parameter(isa), |b| match kernel {
                "plain" => b.iter(|| lanes.trajectories(black_box(&starts), COLLISIONS)),
                "fd" => b.iter(|| lanes.lyapunov_fd(black_box(&starts), &dirs, 1e-7, COLLISIONS)),
                "tangent" => {
                    b.iter(|| lanes.lyapunov_tangent(black_box(&starts), &dirs, COLLISIONS))
                }
                _ => b.iter(|| lanes.spectrum(black_box(&starts), &frames, COLLISIONS, 1)),
            });
        }
        g.finish();
    }
}

fn tables(c: &mut Criterion) {
    let law = SpinLaw::new(0.5).expect("valid");
    let mut g = c.benchmark_group(format!("lanes/plain/{}", Isa::detect()));
    g.throughput(Throughput::Elements(ICS * COLLISIONS))
        .sample_size(10)
        .measurement_time(Duration::from_secs(3));
    let tables: [Table; 4] = [
        Circle::unit().into(),
        Rectangle::square().into(),
        Stadium::new(1.0).expect("valid").into(),
        Sinai::new(2.0, 1.0).expect("valid").into(),
    ];
    for table in tables {
        let (starts, _) = inputs(&table, &law);
        let lanes = LaneBilliard::new(table, law).unwrap();
        g.bench_function(BenchmarkId::from_parameter(table.name()), |b| {
            b.iter(|| lanes.trajectories(black_box(&starts), COLLISIONS))
        });
    }
    g.finish();
}

criterion_group!(benches, kernels, tables);
criterion_main!(benches);
