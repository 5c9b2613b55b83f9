//! The paper's conserved-quantity figure (appendix C): the distribution of
//! `|ΔQ| = |Q_{n+1} − Q_n|` between consecutive collisions in the stadium
//! (a = 1) at α = 0.5, split by what the two walls have in common.
//!
//! ```text
//! cargo run --release --example fig_q_conservation -- [--quick | --paper] [--out DIR] [--seed N]
//! ```
//!
//! One trajectory from the paper sampler (initial condition 0 of the seed),
//! 2000 collisions with `--quick`, 10⁴ (the paper's) otherwise. Pairs are
//! sorted by `spinball_analysis::PairClass`: the same wall twice (two hits in
//! a row on one cap: `ΔQ = 0` to rounding, the circle's angular momentum),
//! facing walls (bottom ↔ top flat: opposite oriented tangents, `ΔQ = −2v∥`
//! exactly) and turned tangents (flat ↔ cap, cap → other cap: `O(1)`). The
//! right panel shows the quantities that are at machine precision: `Q`
//! through each collision, `ΔQ + 2v∥` for facing walls, and the same-wall
//! population again.
//!
//! Writes `q_conservation.png`, `q_pairs.csv` (every pair),
//! `q_histogram.csv` (counts per quarter decade) and `q_conservation.json`
//! (counts, shares, medians and maxima, and the wall-transition fractions
//! under the three rules of `WallStatistics`).

use std::error::Error;
use std::fmt::Write as _;
use std::process::ExitCode;
use std::time::Instant;

use serde_json::json;
use spinball_analysis::{
    DeltaQPopulation, PairClass, TransitionRule, q_pair_statistics, wall_statistics,
};
use spinball_core::{Billiard, Sampler, SpinLaw};
use spinball_geometry::Stadium;
use spinball_plot::cli::FigureArgs;
use spinball_plot::{Grid, Legend, LineKind, LinePlot, Plot, RGBColor, Series};

const NAME: &str = "fig_q_conservation";
const ABOUT: &str =
    "|ΔQ| between consecutive collisions by pair class, stadium a = 1, α = 0.5 (paper appendix C).";
const ALPHA: f64 = 0.5;
/// Where exact zeros are drawn (log10 |ΔQ|).
const ZERO_AT: f64 = -19.5;

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

/// Counts per log10 bin of a population, from its first to its last
/// occupied bin; exact zeros (and values below the histogram) as a separate
/// point at `ZERO_AT`, not joined to the rest.
fn curve(p: &DeltaQPopulation) -> Vec<(f64, f64)> {
    let h = &p.log10;
    let mut pts = Vec::new();
    if h.underflow() > 0 {
        pts.push((ZERO_AT, h.underflow() as f64));
        pts.push((f64::NAN, f64::NAN));
    }
    let counts = h.counts();
    if let (Some(a), Some(b)) = (
        counts.iter().position(|&c| c > 0),
        counts.iter().rposition(|&c| c > 0),
    ) {
        pts.extend((a..=b).map(|i| (h.center(i), counts[i] as f64)));
    }
    pts
}

fn run(args: &FigureArgs) -> Result<(), Box<dyn Error>> {
    let t0 = Instant::now();
    let collisions: u64 = args.pick(2_000, 10_000, 10_000);
    let billiard = Billiard::new(Stadium::new(1.0)?, SpinLaw::new(ALPHA)?);
    let start = Sampler::Paper.initial_state(billiard.table(), billiard.law(), args.seed, 0);
    let q = q_pair_statistics(&billiard, start, collisions, true)?;
    let walls = wall_statistics(&billiard, start, collisions)?;

    let classes = [
        (
            PairClass::SameWall,
            "same wall (cap → same cap)",
            RGBColor(0, 114, 178),
        ),
        (
            PairClass::FacingWalls,
            "facing walls (flat ↔ flat)",
            RGBColor(230, 159, 0),
        ),
        (
            PairClass::Turned,
            "tangent turns (flat ↔ cap, cap → cap)",
            RGBColor(213, 94, 0),
        ),
    ];
    let mut left = LinePlot::new()
        .title(format!(
            "|ΔQ| between consecutive collisions ({} pairs)",
            q.pair_count()
        ))
        .x_label("log₁₀ |ΔQ|   (exact zeros at −19.5)")
        .y_label("pairs per quarter decade")
        .x_range(-20.0, 1.5)
        .legend(Legend::UpperMiddle);
    for (class, label, color) in classes {
        let p = q.population(class);
        left = left.series(
            Series::new(
                format!(
                    "{label}: {} ({:.0} %)",
                    p.count,
                    100.0 * q.share(class).unwrap_or(0.0)
                ),
                curve(p),
            )
            .color(color)
            .marker_radius(5),
        );
    }
    let right = LinePlot::new()
        .title("What is conserved to rounding")
        .x_label("log₁₀ |·|   (exact zeros at −19.5)")
        .y_label("count per quarter decade")
        .x_range(-20.0, -12.0)
        .legend(Legend::UpperRight)
        .series(
            Series::new(
                "|Q after − Q before| through a collision",
                curve(&q.through_collision),
            )
            .color(RGBColor(0, 158, 115))
            .marker_radius(5),
        )
        .series(
            Series::new("|ΔQ + 2v∥|, facing walls", curve(&q.facing_residual))
                .color(RGBColor(230, 159, 0))
                .kind(LineKind::Dashed)
                .marker_radius(5),
        )
        .series(
            Series::new("|ΔQ|, same wall", curve(q.population(PairClass::SameWall)))
                .color(RGBColor(0, 114, 178))
                .kind(LineKind::Dotted)
                .marker_radius(5),
        );
    let grid = Grid::new(1, 2)
        .title(format!(
            "Conserved quantity Q = v∥ − αu, stadium a = 1, α = {ALPHA}, one trajectory of {collisions} collisions"
        ))
        .panel(left)
        .panel(right);
    let png = args.output("q_conservation.png")?;
    let (w, h) = args.pick((1600, 700), (2000, 850), (2400, 1000));
    grid.save_png(&png, w, h)?;

    // Data.
    let mut csv = String::from("collision,class,dq,v_par_before_flight\n");
    for p in &q.pairs {
        let _ = writeln!(
            csv,
            "{},{},{:.17e},{:.17e}",
            p.collision,
            p.class.name(),
            p.dq,
            p.v_par
        );
    }
    std::fs::write(args.output("q_pairs.csv")?, csv)?;
    let mut hist = String::from("population,log10_lo,log10_hi,count\n");
    let named: [(&str, &DeltaQPopulation); 5] = [
        ("same_wall", q.population(PairClass::SameWall)),
        ("facing_walls", q.population(PairClass::FacingWalls)),
        ("turned", q.population(PairClass::Turned)),
        ("through_collision", &q.through_collision),
        ("facing_residual", &q.facing_residual),
    ];
    for (name, p) in named {
        let h = &p.log10;
        let _ = writeln!(hist, "{name},-inf,{},{}", h.lo(), h.underflow());
        let edges = h.edges();
        for (i, &c) in h.counts().iter().enumerate() {
            let _ = writeln!(hist, "{name},{},{},{c}", edges[i], edges[i + 1]);
        }
    }
    std::fs::write(args.output("q_histogram.csv")?, hist)?;
    let pop = |p: &DeltaQPopulation| {
        json!({"count": p.count, "median": p.median(), "max": p.max,
               "exact_or_below_1e-20": p.log10.underflow()})
    };
    let doc = json!({
        "figure": NAME, "mode": args.mode.to_string(), "table": "stadium:a=1", "alpha": ALPHA,
        "collisions": collisions, "sampler": "paper", "seed": args.seed, "ic_index": 0,
        "pairs": q.pair_count(),
        "classes": {
            "same_wall": pop(q.population(PairClass::SameWall)),
            "facing_walls": pop(q.population(PairClass::FacingWalls)),
            "turned": pop(q.population(PairClass::Turned)),
        },
        "shares": {
            "same_wall": q.share(PairClass::SameWall),
            "facing_walls": q.share(PairClass::FacingWalls),
            "turned": q.share(PairClass::Turned),
        },
        "through_collision": pop(&q.through_collision),
        "facing_residual": pop(&q.facing_residual),
        "transition_fraction": {
            "tangent": walls.transition_fraction(TransitionRule::Tangent),
            "direction": walls.transition_fraction(TransitionRule::Direction),
            "wall": walls.transition_fraction(TransitionRule::Wall),
        },
        "curved_fraction": walls.curved_fraction(),
        "version": env!("CARGO_PKG_VERSION"),
    });
    std::fs::write(
        args.output("q_conservation.json")?,
        serde_json::to_string_pretty(&doc)? + "\n",
    )?;

    for (class, label, _) in classes {
        let p = q.population(class);
        println!(
            "  {label:<40} {:5} pairs, median |ΔQ| {:.1e}, max {:.1e}",
            p.count,
            p.median().unwrap_or(f64::NAN),
            p.max
        );
    }
    println!(
        "  through a collision: max {:.1e}; facing walls |ΔQ + 2v∥|: max {:.1e}; f_trans (wall rule) {:.3}",
        q.through_collision.max,
        q.facing_residual.max,
        walls
            .transition_fraction(TransitionRule::Wall)
            .unwrap_or(f64::NAN)
    );
    println!(
        "{NAME} ({} mode): wrote {} and CSV/JSON in {:.2} s",
        args.mode,
        png.display(),
        t0.elapsed().as_secs_f64()
    );
    Ok(())
}
