#![allow(missing_docs)] // criterion_group! generates undocumented functions
//! Cost of the analysis kernels per trajectory step (one collision of the
//! reference trajectory with everything the method carries along).
//!
//! `cargo bench -p spinball-bench --bench analysis`. Each benchmark runs an
//! ensemble of the stadium (a = 1, α = 0.5) and reports throughput in
//! IC-steps per second; criterion's "time" divided by the element count is
//! the cost of one step:
//! - `fd`: the paper's finite-difference Benettin step (reference + shadow);
//! - `tangent`: the exact-tangent step (one tangent vector);
//! - `spectrum`: the 5-vector exact spectrum step (QR every collision);
//!
//! on 1 and 2 threads.

use std::hint::black_box;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use spinball::analysis::estimators::{SpectrumOptions, lyapunov_spectrum};
use spinball::analysis::run::Threads;
use spinball::prelude::*;

const ICS: u64 = 32;
const COLLISIONS: u64 = 4_000;

fn ensemble_benches(c: &mut Criterion) {
    let stadium = Stadium::new(1.0).expect("valid");
    let law = SpinLaw::new(0.5).expect("valid");
    let mut group = c.benchmark_group("ensemble_step");
    group.sample_size(10);
    group.throughput(Throughput::Elements(ICS * COLLISIONS));
    for threads in [1usize, 2] {
        for method in [Method::default(), Method::Tangent] {
            let ensemble = Ensemble::new(stadium, law)
                .with_ics(ICS)
                .with_collisions(COLLISIONS)
                .with_method(method)
                .with_threads(Threads::Fixed(threads));
            group.bench_function(format!("{}/{threads}t", method.name()), |b| {
                b.iter(|| black_box(ensemble.run().expect("run")))
            });
        }
    }
    group.finish();

    let billiard = Billiard::new(stadium, law);
    let mut group = c.benchmark_group("spectrum_step");
    group.sample_size(10);
    group.throughput(Throughput::Elements(COLLISIONS));
    let start = Sampler::Paper.initial_state(billiard.table(), billiard.law(), 3, 0);
    let options = SpectrumOptions::new(COLLISIONS, Method::Tangent);
    group.bench_function("tangent/1t", |b| {
        b.iter(|| {
            black_box(
                lyapunov_spectrum(&billiard, start, &options, &mut ic_rng(3, 1)).expect("run"),
            )
        })
    });
    group.finish();
}

criterion_group!(benches, ensemble_benches);
criterion_main!(benches);
