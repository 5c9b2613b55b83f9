#![allow(missing_docs)] // criterion_group! generates undocumented functions
//! Cost of one collision step per table, and of one exact-tangent step.
//!
//! `cargo bench -p spinball-bench --bench collision`. Each iteration advances one ball by one
//! collision (cast + spin law + energy-shell restore); the ball keeps going
//! from where it stopped, so the bench samples the table's natural mix of
//! walls.

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use spinball::dynamics::{Ball, TangentVector};
use spinball::prelude::*;

fn ball_for<B: Boundary>(billiard: &Billiard<B>) -> Ball {
    let start = Sampler::Paper.initial_state(billiard.table(), billiard.law(), 7, 0);
    billiard.launch(start).expect("valid start")
}

fn bench_table<B: Boundary>(c: &mut Criterion, name: &str, table: B) {
    let billiard = Billiard::new(table, SpinLaw::new(0.5).expect("valid"));
    let mut ball = ball_for(&billiard);
    c.bench_function(&format!("step/{name}"), |b| {
        b.iter(|| black_box(billiard.step(black_box(&mut ball)).expect("step")))
    });
    let mut ball = ball_for(&billiard);
    let mut tv = [TangentVector::from_array([0.3, -0.2, 0.5, 0.1, 0.4])];
    c.bench_function(&format!("tangent_step/{name}"), |b| {
        b.iter(|| {
            let c = billiard
                .step_tangent(black_box(&mut ball), &mut tv)
                .expect("step");
            let n = tv[0].norm();
            tv[0] = tv[0] * (1.0 / n);
            black_box(c)
        })
    });
}

fn collisions(c: &mut Criterion) {
    bench_table(c, "circle", Circle::unit());
    bench_table(c, "rectangle", Rectangle::square());
    bench_table(c, "stadium", Stadium::new(1.0).expect("valid"));
    bench_table(c, "sinai", Sinai::new(2.0, 1.0).expect("valid"));
}

criterion_group!(benches, collisions);
criterion_main!(benches);
