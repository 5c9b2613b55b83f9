//! Build your own table from segments and measure its Lyapunov exponent.
//!
//! A mushroom billiard (a semicircular cap on a rectangular stem) has a
//! phase space divided by its geometry: orbits that stay in the cap are
//! regular, those that enter the stem are chaotic. This example builds one
//! from walls, without touching the library, and compares λ for a ball
//! launched in the stem with one circling high in the cap.
//!
//! ```text
//! cargo run --release --example custom_table -- [--alpha 0.0] [--collisions 50000]
//! ```

use std::f64::consts::PI;
use std::process::ExitCode;

use spinball::geometry::{ArcSegment, LineSegment, Segment};
use spinball::prelude::*;

fn mushroom(
    cap: f64,
    half_width: f64,
    height: f64,
) -> Result<SegmentTable, Box<dyn std::error::Error>> {
    let p = DVec2::new;
    let line = |a, b| LineSegment::new(a, b).map(Segment::Line);
    Ok(SegmentTable::new(vec![
        line(p(-half_width, -height), p(half_width, -height))?,
        line(p(half_width, -height), p(half_width, 0.0))?,
        line(p(half_width, 0.0), p(cap, 0.0))?,
        Segment::Arc(ArcSegment::new(DVec2::ZERO, cap, 0.0, PI)?),
        line(p(-cap, 0.0), p(-half_width, 0.0))?,
        line(p(-half_width, 0.0), p(-half_width, -height))?,
    ])?)
}

fn run(alpha: f64, collisions: u64) -> Result<(), Box<dyn std::error::Error>> {
    let billiard = Billiard::new(mushroom(1.0, 0.3, 1.0)?, SpinLaw::new(alpha)?);
    let options = LyapunovOptions::new(collisions, Method::Tangent);
    let starts = [
        (
            "stem (chaotic sea)",
            State::new(DVec2::new(0.1, -0.5), DVec2::new(0.6, 0.8), 0.0),
        ),
        (
            "cap, near-tangent (regular)",
            State::new(DVec2::new(0.0, 0.95), DVec2::new(1.0, 0.0), 0.0),
        ),
    ];
    println!("mushroom (cap 1, stem 0.6 x 1), alpha = {alpha}, {collisions} collisions");
    for (name, start) in starts {
        let lyap = largest_lyapunov(&billiard, start, &options, &mut ic_rng(1, 0))?;
        println!("  {name:<28} lambda = {:.5} per unit time", lyap.exponent);
    }
    Ok(())
}

fn main() -> ExitCode {
    let mut alpha = 0.0;
    let mut collisions = 50_000;
    let mut args = std::env::args().skip(1);
    while let Some(flag) = args.next() {
        let parsed = match flag.as_str() {
            "--quick" => {
                collisions = 2_000;
                Ok(())
            }
            "--alpha" => args
                .next()
                .and_then(|v| v.parse().ok())
                .map(|v| alpha = v)
                .ok_or(flag),
            "--collisions" => args
                .next()
                .and_then(|v| v.parse().ok())
                .map(|v| collisions = v)
                .ok_or(flag),
            _ => Err(flag),
        };
        if let Err(flag) = parsed {
            eprintln!(
                "error: bad or unknown option {flag} (expected --alpha A, --collisions N, --quick)"
            );
            return ExitCode::from(2);
        }
    }
    match run(alpha, collisions) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(2)
        }
    }
}
