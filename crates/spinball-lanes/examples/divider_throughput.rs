//! Throughput of this core's 512-bit divider and square root, in core
//! cycles: the numbers behind the floor of docs/PERFORMANCE.md.
//!
//! ```text
//! cargo run --release -p spinball-lanes --example divider_throughput -- [--repeat 5]
//! ```
//!
//! The clock is calibrated on the core itself: a single chain of dependent
//! `vaddpd` runs at one instruction per add latency, 4 cycles on every Intel
//! core since Skylake and on AMD Zen 4/5, so its time per instruction over 4
//! is the cycle time at the frequency the core runs now (turbo included).
//! Divisions, square roots and fused multiply-adds then run as 16
//! independent chains, so only their issue rate limits them; the printed
//! cycles per instruction are their reciprocal throughputs. Each figure is
//! the median of `--repeat` runs of ~0.1 s. Needs AVX-512F; elsewhere it
//! says so and exits.

#[cfg(target_arch = "x86_64")]
mod avx512 {
    use std::arch::x86_64::{
        __m512d, _mm512_add_pd, _mm512_div_pd, _mm512_fmadd_pd, _mm512_reduce_add_pd,
        _mm512_set1_pd, _mm512_sqrt_pd,
    };

    /// Independent chains: more than latency × issue rate for every
    /// instruction timed here.
    const CHAINS: usize = 16;

    /// Sum of all lanes of all chains (keeps the work observable).
    #[target_feature(enable = "avx512f")]
    fn total(x: &[__m512d]) -> f64 {
        x.iter().map(|&v| _mm512_reduce_add_pd(v)).sum()
    }

    /// `n` dependent additions in one chain.
    #[target_feature(enable = "avx512f")]
    pub fn add_chain(n: u64) -> f64 {
        let step = _mm512_set1_pd(1e-9);
        let mut x = _mm512_set1_pd(1.0);
        for _ in 0..n {
            x = _mm512_add_pd(x, step);
        }
        total(&[x])
    }

    /// `n × CHAINS` divisions, `CHAINS` independent chains.
    #[target_feature(enable = "avx512f")]
    pub fn div(n: u64) -> f64 {
        let d = _mm512_set1_pd(1.000_000_1);
        let mut x = [_mm512_set1_pd(1.0); CHAINS];
        for _ in 0..n {
            for v in &mut x {
                *v = _mm512_div_pd(*v, d);
            }
        }
        total(&x)
    }

    /// `n × CHAINS` square roots (the chains converge to 1 and stay there).
    #[target_feature(enable = "avx512f")]
    pub fn sqrt(n: u64) -> f64 {
        let mut x = [_mm512_set1_pd(2.0); CHAINS];
        for _ in 0..n {
            for v in &mut x {
                *v = _mm512_sqrt_pd(*v);
            }
        }
        total(&x)
    }

    /// `n × CHAINS` fused multiply-adds.
    #[target_feature(enable = "avx512f")]
    pub fn fma(n: u64) -> f64 {
        // Starting at 2 (not at the fixed point 1 of x·a + b, which the
        // compiler would fold away).
        let (a, b) = (_mm512_set1_pd(0.999_999_9), _mm512_set1_pd(1e-7));
        let mut x = [_mm512_set1_pd(2.0); CHAINS];
        for _ in 0..n {
            for v in &mut x {
                *v = _mm512_fmadd_pd(*v, a, b);
            }
        }
        total(&x)
    }

    pub const PER_ROUND: u64 = CHAINS as u64;
}

#[cfg(target_arch = "x86_64")]
fn main() -> Result<(), Box<dyn std::error::Error>> {
    use std::time::Instant;

    let mut repeat = 5usize;
    let mut args = std::env::args().skip(1);
    while let Some(flag) = args.next() {
        match flag.as_str() {
            "--repeat" => repeat = args.next().ok_or("--repeat needs a value")?.parse()?,
            other => return Err(format!("unknown argument {other}").into()),
        }
    }
    if repeat == 0 {
        return Err("--repeat must be at least 1".into());
    }
    if !std::arch::is_x86_feature_detected!("avx512f") {
        println!("this CPU has no AVX-512F: nothing to measure");
        return Ok(());
    }
    // Median ns per instruction of `f(n)`, which issues `n × per_round` of them.
    let time = |f: fn(u64) -> f64, n: u64, per_round: u64| -> f64 {
        let mut ns: Vec<f64> = (0..repeat)
            .map(|_| {
                let t0 = Instant::now();
                std::hint::black_box(f(std::hint::black_box(n)));
                t0.elapsed().as_secs_f64() * 1e9 / (n * per_round) as f64
            })
            .collect();
        ns.sort_by(f64::total_cmp);
        ns[ns.len() / 2]
    };
    // SAFETY: AVX-512F was detected on this CPU above; it is all these
    // `#[target_feature(enable = "avx512f")]` functions need.
    let add_chain: fn(u64) -> f64 = |n| unsafe { avx512::add_chain(n) };
    // SAFETY: as above.
    let div: fn(u64) -> f64 = |n| unsafe { avx512::div(n) };
    // SAFETY: as above.
    let sqrt: fn(u64) -> f64 = |n| unsafe { avx512::sqrt(n) };
    // SAFETY: as above.
    let fma: fn(u64) -> f64 = |n| unsafe { avx512::fma(n) };

    let cycle_ns = time(add_chain, 30_000_000, 1) / 4.0;
    println!(
        "clock from a dependent vaddpd chain (4-cycle latency): {:.3} GHz",
        1.0 / cycle_ns
    );
    println!("512-bit instruction       ns/instr   cycles/instr   lane-ops/cycle");
    for (name, f, n) in [
        ("vdivpd zmm", div, 500_000),
        ("vsqrtpd zmm", sqrt, 400_000),
        ("vfmadd231pd zmm", fma, 10_000_000),
    ] {
        let ns = time(f, n, avx512::PER_ROUND);
        let cycles = ns / cycle_ns;
        println!(
            "{name:<22} {ns:>11.3} {cycles:>14.2} {:>16.2}",
            8.0 / cycles
        );
    }
    Ok(())
}

#[cfg(not(target_arch = "x86_64"))]
fn main() {
    println!("divider_throughput measures x86-64 AVX-512 instructions only");
}
