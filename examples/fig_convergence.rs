//! The paper's convergence checks (appendix A): single-trajectory LCN traces
//! λ(t) for the four tables at five α (its Fig. of LCN traces), and the
//! ensemble-averaged λ against the number of collisions for the stadium and
//! Sinai tables (its Table I).
//!
//! ```text
//! cargo run --release --example fig_convergence -- [--quick | --paper] [--out DIR] [--seed N]
//! ```
//!
//! | mode      | traces            | Table I: ICs × collisions                 |
//! |-----------|-------------------|-------------------------------------------|
//! | `--quick` | 10⁴ collisions    | 20 × {500, 10³, 2·10³, 5·10³}             |
//! | default   | 10⁵ (paper)       | 2000 × {10⁴, 5·10⁴, 10⁵, 5·10⁵}           |
//! | `--paper` | 10⁵               | 10⁴ × {10⁴, 5·10⁴, 10⁵, 5·10⁵} (paper)    |
//!
//! Traces: θ0 = 0.8, u0 = 0, speed 1, from (0.3, 0.2) (Sinai: (−1.5, 0.2)),
//! as in `fig_trajectories`; the rectangle is L = H = 1 as in the paper's
//! Lyapunov runs; the shadow direction is drawn from the seed. Table I: paper
//! sampler, the same initial conditions in every column (one ensemble run
//! per column in the lane kernels; with the scalar engine one nested run,
//! see `spinball_analysis::convergence_estimates`). All finite-difference
//! Benettin, δ0 = 1e-7.
//!
//! Writes `lcn_traces.png` (2 × 2, log–log), `lcn_traces.csv`,
//! `convergence_table.png` (λ against collisions with SEM bars and the
//! paper's values), `convergence_table.csv`, `convergence_table.md` (mean(SEM)
//! like the paper, ours beside theirs) and `convergence.json`.

use std::error::Error;
use std::fmt::Write as _;
use std::process::ExitCode;
use std::time::Instant;

use serde_json::json;
use spinball_analysis::{
    Ensemble, LcnTrace, LyapunovEstimate, Method, convergence_estimates, format_mean_sem, lcn_trace,
};
use spinball_core::{Billiard, SpinLaw, State, ic_rng};
use spinball_geometry::{Boundary, DVec2, Table, TableVisitor};
use spinball_plot::cli::FigureArgs;
use spinball_plot::{Grid, Legend, LineKind, LinePlot, Plot, RGBColor, Series, viridis};

const NAME: &str = "fig_convergence";
const ABOUT: &str = "LCN traces λ(t) for four tables at five α, and the paper's Table I (λ vs number of collisions).";
const TRACE_ALPHAS: [f64; 5] = [0.0, 0.1, 0.3, 0.5, 1.0];
const THETA0: f64 = 0.8;
const U0: f64 = 0.0;
const TRACE_TABLES: [(&str, &str, [f64; 2]); 4] = [
    ("circle:R=1", "circle R = 1", [0.3, 0.2]),
    ("rectangle:L=1,H=1", "rectangle L = H = 1", [0.3, 0.2]),
    ("stadium:a=1", "stadium a = 1", [0.3, 0.2]),
    ("sinai:L=2,R=1", "Sinai L = 2, R = 1", [-1.5, 0.2]),
];
const TABLE_ALPHAS: [f64; 3] = [0.1, 0.5, 1.0];
const TABLE_TABLES: [(&str, &str); 2] = [("stadium:a=1", "Stadium"), ("sinai:L=2,R=1", "Sinai")];
/// The paper's Table I: (table, α, values at 10⁴, 5·10⁴, 10⁵, 5·10⁵).
const PAPER_TABLE: [(&str, f64, [&str; 4]); 6] = [
    (
        "stadium:a=1",
        0.1,
        ["0.281(0)", "0.280(0)", "0.279(0)", "0.280(0)"],
    ),
    (
        "stadium:a=1",
        0.5,
        ["0.183(1)", "0.183(1)", "0.183(1)", "0.183(1)"],
    ),
    (
        "stadium:a=1",
        1.0,
        ["0.147(1)", "0.147(1)", "0.146(1)", "0.147(1)"],
    ),
    (
        "sinai:L=2,R=1",
        0.1,
        ["0.211(0)", "0.211(0)", "0.210(0)", "0.210(0)"],
    ),
    (
        "sinai:L=2,R=1",
        0.5,
        ["0.120(0)", "0.119(0)", "0.119(0)", "0.119(0)"],
    ),
    (
        "sinai:L=2,R=1",
        1.0,
        ["0.103(0)", "0.103(0)", "0.102(0)", "0.102(0)"],
    ),
];
const PAPER_COLLISIONS: [u64; 4] = [10_000, 50_000, 100_000, 500_000];

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

/// `lcn_trace` with the concrete table type.
struct Trace {
    law: SpinLaw,
    start: State,
    collisions: u64,
    seed: u64,
}

impl TableVisitor for Trace {
    type Output = Result<LcnTrace, spinball_analysis::AnalysisError>;
    fn visit<B: Boundary + Clone + Send + Sync>(self, table: &B) -> Self::Output {
        let billiard = Billiard::new(table.clone(), self.law);
        lcn_trace(
            &billiard,
            self.start,
            self.collisions,
            Method::default(),
            40,
            &mut ic_rng(self.seed, 0),
        )
    }
}

fn run(args: &FigureArgs) -> Result<(), Box<dyn Error>> {
    let t0 = Instant::now();
    let trace_len: u64 = args.pick(10_000, 100_000, 100_000);
    let ics: u64 = args.pick(20, 2_000, 10_000);
    let checkpoints: Vec<u64> = args.pick(
        vec![500, 1_000, 2_000, 5_000],
        PAPER_COLLISIONS.to_vec(),
        PAPER_COLLISIONS.to_vec(),
    );

    // 1. LCN traces.
    let mut grid = Grid::new(2, 2).title(format!(
        "Single-trajectory LCN traces ({trace_len} collisions, θ₀ = {THETA0}, u₀ = {U0}, finite differences)"
    ));
    let mut csv = String::from("table,alpha,collisions,time,lambda\n");
    let mut finals = Vec::new();
    for (spec, title, p) in TRACE_TABLES {
        let table: Table = spec.parse()?;
        let start = State::new(DVec2::from(p), DVec2::from_angle(THETA0), U0);
        let mut plot = LinePlot::new()
            .title(title)
            .x_label("time t   (speed |v₀| = 1)")
            .y_label("running λ(t) (1/time)")
            .log_x(true)
            .log_y(true)
            .legend(Legend::LowerLeft);
        let mut t_max: f64 = 1.0;
        for (k, alpha) in TRACE_ALPHAS.into_iter().enumerate() {
            let trace = table.visit(Trace {
                law: SpinLaw::new(alpha)?,
                start,
                collisions: trace_len,
                seed: args.seed,
            })?;
            for p in &trace.points {
                let _ = writeln!(
                    csv,
                    "\"{spec}\",{alpha},{},{:.8e},{:.8e}",
                    p.collisions, p.time, p.exponent
                );
            }
            t_max = t_max.max(trace.points.last().map_or(1.0, |p| p.time));
            finals.push(
                json!({"table": spec, "alpha": alpha, "collisions": trace.collisions,
                               "final_lambda": trace.exponent}),
            );
            plot = plot.series(
                Series::new(
                    format!("α = {alpha}"),
                    trace.points.iter().map(|p| (p.time, p.exponent)),
                )
                .line_only()
                .line_width(3)
                .color(viridis(k as f64 / 4.0 * 0.9)),
            );
        }
        if matches!(table, Table::Circle(_) | Table::Rectangle(_)) {
            // A 1/t guide through λ = 1 at t = 1.
            plot = plot.series(
                Series::new("∝ 1/t", [(1.0, 1.0), (t_max, 1.0 / t_max)])
                    .line_only()
                    .kind(LineKind::Dashed)
                    .color(RGBColor(120, 120, 120)),
            );
        }
        grid.push(plot);
    }
    let png = args.output("lcn_traces.png")?;
    let (w, h) = args.pick((1400, 1050), (1800, 1350), (2200, 1650));
    grid.save_png(&png, w, h)?;
    std::fs::write(args.output("lcn_traces.csv")?, csv)?;
    println!("  traces done in {:.1} s", t0.elapsed().as_secs_f64());

    // 2. Table I.
    let mut rows: Vec<(&str, &str, f64, Vec<LyapunovEstimate>, f64)> = Vec::new();
    for (spec, name) in TABLE_TABLES {
        let table: Table = spec.parse()?;
        for alpha in TABLE_ALPHAS {
            let ensemble = Ensemble::new(table, SpinLaw::new(alpha)?)
                .with_ics(ics)
                .with_seed(args.seed);
            let clock = Instant::now();
            let columns = convergence_estimates(&ensemble, &checkpoints)?;
            let seconds = clock.elapsed().as_secs_f64();
            println!(
                "  {name:<7} α = {alpha:<3}: {}  ({:.1} s)",
                columns
                    .iter()
                    .map(|e| format_mean_sem(e.mean, e.sem, 4))
                    .collect::<Vec<_>>()
                    .join("  "),
                seconds
            );
            rows.push((spec, name, alpha, columns, seconds));
        }
    }

    let mut table_csv =
        String::from("table,alpha,collisions,ics,mean,sem,median,chaotic_fraction,paper\n");
    let paper_for = |spec: &str, alpha: f64, c: u64| -> Option<&'static str> {
        let col = PAPER_COLLISIONS.iter().position(|&p| p == c)?;
        PAPER_TABLE
            .iter()
            .find(|(s, a, _)| *s == spec && *a == alpha)
            .map(|(_, _, v)| v[col])
    };
    for (spec, _, alpha, columns, _) in &rows {
        for e in columns {
            let _ = writeln!(
                table_csv,
                "\"{spec}\",{alpha},{},{},{:.6},{:.6},{:.6},{:.5},{}",
                e.collisions_per_ic,
                e.n_ics,
                e.mean,
                e.sem,
                e.median,
                e.chaotic_fraction,
                paper_for(spec, *alpha, e.collisions_per_ic).unwrap_or("")
            );
        }
    }
    std::fs::write(args.output("convergence_table.csv")?, table_csv)?;

    // Markdown: ours (3 decimals, the paper's notation, then 4) beside the paper's.
    let header: Vec<String> = checkpoints.iter().map(|c| c.to_string()).collect();
    let mut md = format!(
        "Ensemble-averaged LCN ± SEM (in units of the last digit) vs number of collisions; \
         ours: {ics} ICs per entry, seed {}, finite differences δ0 = 1e-7, paper sampler; \
         paper: 10 000 ICs per entry.\n\n\
         | Geometry | α | source | {} |\n|---|---|---|{}\n",
        args.seed,
        header.join(" | "),
        "---|".repeat(checkpoints.len())
    );
    for (spec, name, alpha, columns, _) in &rows {
        let ours3: Vec<String> = columns
            .iter()
            .map(|e| format_mean_sem(e.mean, e.sem, 3))
            .collect();
        let ours4: Vec<String> = columns
            .iter()
            .map(|e| format_mean_sem(e.mean, e.sem, 4))
            .collect();
        let _ = writeln!(md, "| {name} | {alpha} | ours | {} |", ours3.join(" | "));
        let _ = writeln!(md, "| | | ours (4 d.) | {} |", ours4.join(" | "));
        let paper: Vec<&str> = columns
            .iter()
            .map(|e| paper_for(spec, *alpha, e.collisions_per_ic).unwrap_or("–"))
            .collect();
        let _ = writeln!(md, "| | | paper | {} |", paper.join(" | "));
    }
    std::fs::write(args.output("convergence_table.md")?, &md)?;

    // Figure of Table I: ours minus the paper's entry (at the same length;
    // for lengths the paper does not list, its 5·10⁵ entry), in 10⁻³.
    let mut tgrid = Grid::new(1, 2).title(format!(
        "Table I: our λ minus the paper's ({ics} ICs per point, ± our SEM; paper rounds to ±0.0005)"
    ));
    for (spec, name) in TABLE_TABLES {
        let mut plot = LinePlot::new()
            .title(name)
            .x_label("collisions per trajectory")
            .y_label("⟨λ⟩ − λ_paper (10⁻³/time)")
            .log_x(true)
            .legend(Legend::UpperRight)
            .hline(0.0, "");
        for (k, (_, _, alpha, columns, _)) in rows.iter().filter(|r| r.0 == spec).enumerate() {
            let reference = |c: u64| {
                paper_for(spec, *alpha, c)
                    .or_else(|| paper_for(spec, *alpha, 500_000))
                    .map_or(f64::NAN, parse_paper)
            };
            plot = plot.series(
                Series::new(
                    format!("α = {alpha}"),
                    columns.iter().map(|e| {
                        let c = e.collisions_per_ic;
                        (c as f64, 1e3 * (e.mean - reference(c)))
                    }),
                )
                .errors(columns.iter().map(|e| 1e3 * e.sem))
                .color(viridis(k as f64 / 2.0 * 0.85))
                .marker_radius(5),
            );
        }
        tgrid.push(plot);
    }
    let tpng = args.output("convergence_table.png")?;
    let (w, h) = args.pick((1400, 650), (1800, 800), (2200, 1000));
    tgrid.save_png(&tpng, w, h)?;

    let table_json: Vec<_> = rows
        .iter()
        .map(|(spec, _, alpha, columns, seconds)| {
            json!({
                "table": spec, "alpha": alpha,
                "columns": columns.iter().map(|e| json!({
                    "collisions": e.collisions_per_ic, "ics": e.n_ics, "mean": e.mean,
                    "sem": e.sem, "median": e.median, "chaotic_fraction": e.chaotic_fraction,
                    "paper": paper_for(spec, *alpha, e.collisions_per_ic),
                })).collect::<Vec<_>>(),
                "wall_time_s": seconds,
            })
        })
        .collect();
    let doc = json!({
        "figure": NAME, "mode": args.mode.to_string(), "seed": args.seed,
        "traces": {"collisions": trace_len, "theta0": THETA0, "u0": U0, "alphas": TRACE_ALPHAS,
                   "final": finals},
        "table_i": {"ics": ics, "checkpoints": checkpoints, "method": "fd", "delta0": 1e-7,
                    "sampler": "paper", "rows": table_json},
        "version": env!("CARGO_PKG_VERSION"),
    });
    std::fs::write(
        args.output("convergence.json")?,
        serde_json::to_string_pretty(&doc)? + "\n",
    )?;
    print!("{md}");
    println!(
        "{NAME} ({} mode): wrote {}, {} and CSV/JSON/MD in {:.1} s",
        args.mode,
        png.display(),
        tpng.display(),
        t0.elapsed().as_secs_f64()
    );
    Ok(())
}

/// `0.183(1)` → 0.183.
fn parse_paper(s: &str) -> f64 {
    s.split('(')
        .next()
        .and_then(|v| v.parse().ok())
        .unwrap_or(f64::NAN)
}
