//! The paper's FTLE figure (§V): finite-time Lyapunov exponent distributions
//! of the stadium (a = 1) at six α, with mean, median and the conditional
//! mean of the chaotic part, plus the paper's description of the regular
//! peak at α = 0.5 (share of flat-wall collisions and initial |v∥| of
//! regular against chaotic orbits).
//!
//! ```text
//! cargo run --release --example fig_ftle -- [--quick | --paper] [--out DIR] [--seed N]
//! ```
//!
//! | mode      | ICs per α | collisions | wall time (2 cores) |
//! |-----------|-----------|------------|---------------------|
//! | `--quick` | 100       | 2 000      | < 1 s               |
//! | default   | 2 000     | 5·10⁴      | about 10 s          |
//! | `--paper` | 10⁵       | 5·10⁴      | about 5 minutes     |
//!
//! Paper sampler, finite-difference Benettin (δ0 = 1e-7), chaos threshold
//! 0.01. Writes `ftle.png` (2 × 3 histograms), `ftle.csv` (every FTLE),
//! `ftle_summary.csv` (per α: mean, SEM, median, std, conditional mean,
//! chaotic fraction and its band over thresholds 0.001–0.05) and `ftle.json`
//! (the same plus the regular/chaotic comparison at α = 0.5).

use std::error::Error;
use std::fmt::Write as _;
use std::process::ExitCode;
use std::time::Instant;

use serde_json::json;
use spinball_analysis::{
    CHAOS_THRESHOLD, ClassSummary, Ensemble, LyapunovEstimate, THRESHOLD_BAND, Threads,
    compare_classes, trajectory_profiles,
};
use spinball_core::{Billiard, SpinLaw};
use spinball_geometry::Stadium;
use spinball_plot::cli::FigureArgs;
use spinball_plot::{Grid, Histogram, Legend, LineKind, Marker, Plot, RGBColor};

const NAME: &str = "fig_ftle";
const ABOUT: &str = "FTLE distributions of the stadium (a = 1) at six α with mean, median and conditional mean (paper §V, Fig. 4).";
const ALPHAS: [f64; 6] = [0.0, 0.1, 0.3, 0.5, 0.7, 1.0];
/// α at which the paper describes the regular peak.
const ISLAND_ALPHA: f64 = 0.5;

fn main() -> ExitCode {
    let args = FigureArgs::parse_or_exit(NAME, ABOUT);
    match run(&args) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("{NAME}: {e}");
            ExitCode::FAILURE
        }
    }
}

fn run(args: &FigureArgs) -> Result<(), Box<dyn Error>> {
    let t0 = Instant::now();
    let ics: u64 = args.pick(100, 2_000, 100_000);
    let collisions: u64 = args.pick(2_000, 50_000, 50_000);
    let stadium = Stadium::new(1.0)?;

    let mut estimates = Vec::new();
    for alpha in ALPHAS {
        let estimate = Ensemble::new(stadium, SpinLaw::new(alpha)?)
            .with_ics(ics)
            .with_collisions(collisions)
            .with_seed(args.seed)
            .run()?;
        println!("  {estimate}");
        estimates.push(estimate);
    }

    // Who is regular at α = 0.5: the same initial conditions, re-run without
    // a shadow to count flat-wall collisions.
    let island = estimates
        .iter()
        .find(|e| e.alpha == ISLAND_ALPHA)
        .ok_or("α = 0.5 missing")?;
    let billiard = Billiard::new(stadium, SpinLaw::new(ISLAND_ALPHA)?);
    let profiles = trajectory_profiles(
        &billiard,
        island
            .sampler
            .ok_or("sampled initial conditions expected")?,
        args.seed,
        island.indices(),
        collisions,
        Threads::All,
    )?;
    let classes = compare_classes(&island.trajectories, &profiles, CHAOS_THRESHOLD)?;

    // Figure.
    let mut grid = Grid::new(2, 3).title(format!(
        "FTLE distributions, stadium a = 1 ({ics} ICs × {collisions} collisions, finite differences)"
    ));
    for e in &estimates {
        grid.push(panel(e)?);
    }
    let png = args.output("ftle.png")?;
    let (w, h) = args.pick((1500, 900), (2100, 1260), (2700, 1620));
    grid.save_png(&png, w, h)?;

    // Data.
    let mut csv = String::from("alpha,index,ftle,per_collision,time,collisions\n");
    for e in &estimates {
        for t in &e.trajectories {
            let _ = writeln!(
                csv,
                "{},{},{:.10e},{:.10e},{:.10e},{}",
                e.alpha, t.index, t.exponent, t.per_collision, t.time, t.collisions
            );
        }
    }
    std::fs::write(args.output("ftle.csv")?, csv)?;
    let mut summary = String::from(
        "alpha,ics,collisions,mean,sem,median,std,conditional_mean,chaotic_fraction,chaotic_fraction_sem,band_min,band_max,wall_s\n",
    );
    let mut rows = Vec::new();
    for e in &estimates {
        let band = e.ftle()?.chaotic_fraction_band(&THRESHOLD_BAND);
        let _ = writeln!(
            summary,
            "{},{},{},{:.6},{:.6},{:.6},{:.6},{:.6},{:.5},{:.5},{:.5},{:.5},{:.2}",
            e.alpha,
            e.n_ics,
            e.collisions_per_ic,
            e.mean,
            e.sem,
            e.median,
            e.std,
            e.conditional_mean.unwrap_or(f64::NAN),
            e.chaotic_fraction,
            e.chaotic_fraction_sem,
            band.min,
            band.max,
            e.wall_time_s
        );
        rows.push(json!({
            "alpha": e.alpha, "ics": e.n_ics, "collisions": e.collisions_per_ic,
            "mean": e.mean, "sem": e.sem, "median": e.median, "std": e.std,
            "conditional_mean": e.conditional_mean, "chaotic_fraction": e.chaotic_fraction,
            "chaotic_fraction_sem": e.chaotic_fraction_sem,
            "chaotic_fraction_band": [band.min, band.max],
            "collision_rate": e.collision_rate, "wall_time_s": e.wall_time_s,
        }));
    }
    std::fs::write(args.output("ftle_summary.csv")?, summary)?;
    let class_json = |c: &ClassSummary| {
        json!({
            "n": c.n,
            "ftle": [c.ftle.mean, c.ftle.sem],
            "flat_share": [c.flat_share.mean, c.flat_share.sem],
            "abs_initial_vx": [c.abs_initial_vx.mean, c.abs_initial_vx.sem],
            "abs_first_v_par": [c.abs_first_v_par.mean, c.abs_first_v_par.sem],
            "abs_initial_spin": [c.abs_initial_spin.mean, c.abs_initial_spin.sem],
        })
    };
    let doc = json!({
        "figure": NAME, "mode": args.mode.to_string(), "table": "stadium:a=1",
        "sampler": "paper", "method": "fd", "delta0": 1e-7, "seed": args.seed,
        "threshold": CHAOS_THRESHOLD, "threshold_band": THRESHOLD_BAND,
        "results": rows,
        "islands": {
            "alpha": ISLAND_ALPHA, "threshold": classes.threshold,
            "note": "regular: FTLE <= threshold; values are [mean, SEM]",
            "regular": class_json(&classes.regular),
            "chaotic": class_json(&classes.chaotic),
        },
        "version": env!("CARGO_PKG_VERSION"),
    });
    std::fs::write(
        args.output("ftle.json")?,
        serde_json::to_string_pretty(&doc)? + "\n",
    )?;

    let (r, c) = (&classes.regular, &classes.chaotic);
    println!(
        "  α = {ISLAND_ALPHA}: regular {} ICs, flat share {:.3} ± {:.3}, |v_x(0)| {:.3}, |v∥| first hit {:.3}; \
         chaotic {} ICs, flat share {:.3} ± {:.3}, |v_x(0)| {:.3}, |v∥| first hit {:.3}",
        r.n,
        r.flat_share.mean,
        r.flat_share.sem,
        r.abs_initial_vx.mean,
        r.abs_first_v_par.mean,
        c.n,
        c.flat_share.mean,
        c.flat_share.sem,
        c.abs_initial_vx.mean,
        c.abs_first_v_par.mean,
    );
    println!(
        "{NAME} ({} mode): wrote {} and CSV/JSON in {:.1} s",
        args.mode,
        png.display(),
        t0.elapsed().as_secs_f64()
    );
    Ok(())
}

/// One histogram with the paper's three lines.
fn panel(e: &LyapunovEstimate) -> Result<Histogram, Box<dyn Error>> {
    let ftle = e.ftle()?;
    let std = ftle.std().unwrap_or(f64::NAN);
    let mut h = Histogram::new(ftle.exponents().iter().copied())
        .bins(60)
        .density(true)
        .title(format!(
            "α = {}   (std {:.3}, f_ch {:.1} %)",
            e.alpha,
            std,
            100.0 * e.chaotic_fraction
        ))
        .x_label("FTLE λ (1/time)")
        .y_label("probability density")
        .color(RGBColor(150, 170, 200))
        .legend(Legend::UpperLeft)
        .marker(Marker::new(format!("mean {:.3}", e.mean), e.mean).color(RGBColor(0, 0, 0)))
        .marker(
            Marker::new(format!("median {:.3}", e.median), e.median)
                .color(RGBColor(0, 90, 200))
                .kind(LineKind::Dashed),
        );
    if let Some(cm) = e.conditional_mean {
        h = h.marker(
            Marker::new(format!("cond. mean {cm:.3}"), cm)
                .color(RGBColor(0, 150, 60))
                .kind(LineKind::Dotted),
        );
    }
    Ok(h)
}
