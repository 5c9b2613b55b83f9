//! Escape from a stadium with a hole, and diffusion through a triangular
//! Lorentz gas, against the spin parameter α: the escape rate and the mean
//! escape time (against Kac's prediction), and the diffusion coefficient.
//!
//! ```text
//! cargo run --release --example escape_transport -- [--quick | --paper] [--seed N] [--threads T]
//! ```
//!
//! The stadium (a = 1) has a hole of arc length 0.2 centred on its right
//! cap; balls start from the paper's sampler. The Lorentz gas has spacing
//! w = 1 and disks of radius R = 0.45 (a finite horizon); balls start in
//! its cell from the same sampler, run with exact unwrapped positions.

use std::f64::consts::PI;
use std::process::ExitCode;

use spinball::analysis::escape::{EscapeOptions, EscapeSummary, KacPrediction};
use spinball::analysis::estimators::Fitted;
use spinball::analysis::open::{Budget, OpenEnsemble};
use spinball::analysis::transport::DiffusionSummary;
use spinball::geometry::LorentzGas;
use spinball::prelude::*;
use spinball_figures::run_figure;

fn main() -> ExitCode {
    let about =
        "Escape rate of a stadium with a hole and diffusion in a triangular Lorentz gas against α.";
    run_figure("escape_transport", about, |args, _| {
        let threads = args.threads;
        let alphas = [0.0, 0.4, 1.0];
        let balls: u64 = args.pick(400, 4_000, 20_000);
        let budget = Budget::collisions(args.pick(20_000, 200_000, 1_000_000));
        let h = 0.2;
        println!(
            "stadium a = 1, hole {h} at the right cap, {balls} balls (paper sampler, seed {})",
            args.seed
        );
        for alpha in alphas {
            let table = SegmentTable::stadium_with_hole(1.0, 2.0 + PI / 2.0, h)?;
            let kac = KacPrediction::for_open_table(&table, alpha)?;
            let records = OpenEnsemble::new(Billiard::new(table, SpinLaw::new(alpha)?))
                .with_seed(args.seed)
                .with_indices(0..balls)
                .with_threads(threads)
                .escape_times(budget)?;
            // The summary the command line and Python report: P(t), the
            // rate on the default window, the tail, the mean against Kac.
            let summary = EscapeSummary::new(&records, kac, EscapeOptions::default())?;
            let Fitted::Fit(time) = &summary.time else {
                println!("  α = {alpha}: {summary}");
                continue;
            };
            println!("  α = {alpha}: {}", time.rate);
            // With balls still inside at the budget the mean is the
            // restricted mean over [0, last time]: a lower bound.
            let Some(mean) = time.kac else {
                continue;
            };
            let bound = if mean.measured.complete { "" } else { "≥ " };
            println!(
                "    mean escape time {bound}{:.2} ± {:.2} ({} censored), Kac {:.2}, ratio {bound}{:.3} ± {:.3}; tail: {}",
                mean.measured.mean,
                mean.measured.sem,
                summary.censored,
                mean.predicted,
                mean.ratio,
                mean.ratio_sem,
                time.tail
            );
        }
        let gas = LorentzGas::triangular(1.0, 0.45)?;
        let horizon = gas.horizon();
        let ics: u64 = args.pick(200, 2_000, 10_000);
        let end: f64 = args.pick(200.0, 2_000.0, 10_000.0);
        let times: Vec<f64> = (1..=20).map(|k| end * f64::from(k) / 20.0).collect();
        println!(
            "triangular Lorentz gas w = 1, R = 0.45 ({horizon:?} horizon), {ics} balls to t = {end}"
        );
        for alpha in alphas {
            let records = OpenEnsemble::new(Billiard::new(gas.table()?, SpinLaw::new(alpha)?))
                .with_seed(args.seed)
                .with_indices(0..ics)
                .with_threads(threads)
                .displacements(&times)?;
            let summary = DiffusionSummary::new(&times, &records, horizon.into(), None)?;
            let trend = summary
                .scan
                .fit()
                .and_then(|s| s.trend)
                .map_or("none".to_string(), |t| format!("{:.2} SE", t.z()));
            println!(
                "  α = {alpha}: {} (trend over windows {trend})",
                summary.estimate
            );
        }
        Ok(())
    })
}
