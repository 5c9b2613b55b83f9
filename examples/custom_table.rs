//! Build your own table from segments and measure λ(α) with error bars,
//! through the same ensemble API as the built-in tables.
//!
//! A mushroom billiard (a semicircular cap on a rectangular stem) has a
//! phase space divided by its geometry: orbits that stay in the cap are
//! regular, those that enter the stem are chaotic. The ensemble runs in the
//! vector-lane kernels (a `SegmentTable` has a lane form) and says so.
//!
//! ```text
//! cargo run --release --example custom_table -- [--quick] [--seed N]
//! ```

use std::f64::consts::PI;

use spinball::analysis::report::SweepRow;
use spinball::analysis::run::AlphaSweep;
use spinball::geometry::{ArcSegment, DVec2, LineSegment, Segment};
use spinball::prelude::*;
use spinball_figures::FigureArgs;

/// Cap radius 1 on a stem of half-width `w` and height `h`.
fn mushroom(w: f64, h: f64) -> Result<SegmentTable, Box<dyn std::error::Error>> {
    let p = DVec2::new;
    let line = |a, b| LineSegment::new(a, b).map(Segment::Line);
    Ok(SegmentTable::new(vec![
        line(p(-w, -h), p(w, -h))?,
        line(p(w, -h), p(w, 0.0))?,
        line(p(w, 0.0), p(1.0, 0.0))?,
        Segment::Arc(ArcSegment::new(DVec2::ZERO, 1.0, 0.0, PI)?),
        line(p(-1.0, 0.0), p(-w, 0.0))?,
        line(p(-w, 0.0), p(-w, -h))?,
    ])?)
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args = FigureArgs::parse_or_exit(
        "custom_table",
        "λ(α) of a mushroom billiard built from segments, with error bars",
    );
    let table = mushroom(0.3, 1.0)?;
    let template = Ensemble::new(table, SpinLaw::specular())
        .with_seed(args.seed)
        .with_ics(args.pick(64, 2_000, 10_000))
        .with_collisions(args.pick(2_000, 20_000, 50_000))
        .with_method(Method::Tangent)
        .with_threads(args.threads);
    let sweep = AlphaSweep::new(template, &[0.0, 0.25, 0.5, 1.0])?;
    println!("mushroom (cap 1, stem 0.6 × 1), exact tangent method");
    println!("{}", SweepRow::table_header());
    for estimate in sweep.run()? {
        println!("{}", SweepRow::from_estimate(&estimate)?.table_line());
        println!("    engine: {}, {estimate}", estimate.engine());
    }
    Ok(())
}
