//! The paper's full-spectrum figure (appendix E): the five Lyapunov
//! exponents against α for the stadium (a = 1) and the Sinai table (L = 2,
//! R = 1), with exact tangent dynamics and with the paper's five-shadow
//! finite-difference method.
//!
//! ```text
//! cargo run --release --example fig_spectrum -- [--quick | --paper] [--out DIR] [--seed N]
//! ```
//!
//! | mode      | α values          | ICs | collisions |
//! |-----------|-------------------|-----|------------|
//! | `--quick` | 0, 0.3, 0.7, 1    | 4   | 2 000      |
//! | default   | 0, 0.1, …, 1 (11) | 50  | 5·10⁴      |
//! | `--paper` | 0, 0.05, …, 1 (21)| 50  | 5·10⁴      |
//!
//! Paper sampler; QR (modified Gram–Schmidt) after every collision; δ0 =
//! 1e-7 for finite differences. The exact spectrum is `(λ, 0, 0, 0, −λ)`;
//! the finite-difference one is `(λ, ≈0, ≈0, −λ, λ₅)` with `λ₅` the flow
//! direction collapsed by comparing states at collisions, a number set by
//! `δ0` and the floating-point format, not by the dynamics (see
//! `spinball_analysis::lyapunov_spectrum`).
//!
//! Writes `spectrum.png` (rows: exact spectrum, its middle exponents
//! enlarged, the finite-difference leading four, the finite-difference
//! fifth; columns: stadium, Sinai), `spectrum.csv` and `spectrum.json`.

use std::error::Error;
use std::fmt::Write as _;
use std::process::ExitCode;
use std::time::Instant;

use serde_json::json;
use spinball_analysis::{Method, SpectrumEstimate, SpectrumOptions, Threads, spectrum_ensemble};
use spinball_core::{Billiard, Sampler, SpinLaw};
use spinball_geometry::{Boundary, Table, TableVisitor};
use spinball_plot::cli::FigureArgs;
use spinball_plot::{Grid, Legend, LineKind, LinePlot, Plot, RGBColor, Series, palette};

const NAME: &str = "fig_spectrum";
const ABOUT: &str = "Full Lyapunov spectrum vs α, stadium and Sinai, exact tangent and the paper's finite differences (paper appendix E).";
const TABLES: [(&str, &str); 2] = [
    ("stadium:a=1", "stadium a = 1"),
    ("sinai:L=2,R=1", "Sinai L = 2, R = 1"),
];

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

/// `spectrum_ensemble` with the concrete table type.
struct Run {
    law: SpinLaw,
    seed: u64,
    ics: u64,
    options: SpectrumOptions,
}

impl TableVisitor for Run {
    type Output = Result<SpectrumEstimate, spinball_analysis::AnalysisError>;
    fn visit<B: Boundary + Clone + Send + Sync>(self, table: &B) -> Self::Output {
        spectrum_ensemble(
            &Billiard::new(table.clone(), self.law),
            Sampler::Paper,
            self.seed,
            0..self.ics,
            &self.options,
            Threads::All,
        )
    }
}

struct Point {
    alpha: f64,
    exact: SpectrumEstimate,
    fd: SpectrumEstimate,
}

fn run(args: &FigureArgs) -> Result<(), Box<dyn Error>> {
    let t0 = Instant::now();
    let alphas: Vec<f64> = args.pick(
        vec![0.0, 0.3, 0.7, 1.0],
        (0..=10).map(|k| k as f64 / 10.0).collect(),
        (0..=20).map(|k| k as f64 / 20.0).collect(),
    );
    let ics: u64 = args.pick(4, 50, 50);
    let collisions: u64 = args.pick(2_000, 50_000, 50_000);

    let mut results: Vec<(&str, Vec<Point>)> = Vec::new();
    for (spec, _) in TABLES {
        let table: Table = spec.parse()?;
        let mut points = Vec::new();
        for &alpha in &alphas {
            let law = SpinLaw::new(alpha)?;
            let go = |method| {
                table.visit(Run {
                    law,
                    seed: args.seed,
                    ics,
                    options: SpectrumOptions::new(collisions, method),
                })
            };
            let exact = go(Method::Tangent)?;
            let fd = go(Method::default())?;
            println!(
                "  {spec:<14} α = {alpha:<4} exact [{}]  fd [{}]  ({:.1} s + {:.1} s)",
                fmt5(&exact),
                fmt5(&fd),
                exact.wall_time_s,
                fd.wall_time_s
            );
            points.push(Point { alpha, exact, fd });
        }
        results.push((spec, points));
    }

    // Figure: rows = views, columns = tables.
    let mut grid = Grid::new(4, 2).title(format!(
        "Lyapunov spectrum vs α ({ics} ICs × {collisions} collisions, mean ± SEM)"
    ));
    let rows: [(&str, &str); 4] = [
        ("exact tangent: λ₁ … λ₅", "λᵢ (1/time)"),
        (
            "exact tangent: middle three, enlarged",
            "λ₂, λ₃, λ₄ (1/time)",
        ),
        ("finite differences: leading four", "λᵢ (1/time)"),
        (
            "finite differences: fifth (collapsed flow direction)",
            "λ₅ (1/time)",
        ),
    ];
    for (r, (what, y_label)) in rows.into_iter().enumerate() {
        for (spec, title) in TABLES {
            let points = &results.iter().find(|(s, _)| *s == spec).ok_or("table")?.1;
            let mut plot = LinePlot::new()
                .title(format!("{title}: {what}"))
                .x_label("spin parameter α")
                .y_label(y_label)
                .legend(Legend::UpperRight);
            let series = |k: usize, fd: bool, label: String| {
                let pick = |p: &Point| if fd { p.fd.clone() } else { p.exact.clone() };
                Series::new(label, points.iter().map(|p| (p.alpha, pick(p).mean[k])))
                    .errors(points.iter().map(|p| pick(p).sem[k]))
                    .color(palette(k))
                    .marker_radius(4)
            };
            match r {
                0 => {
                    for k in 0..5 {
                        plot = plot.series(series(k, false, format!("λ{}", sub(k + 1))));
                    }
                    plot = plot.hline(0.0, "").y_range(-0.5, 0.85);
                }
                1 => {
                    for k in 1..4 {
                        plot = plot.series(series(k, false, format!("λ{}", sub(k + 1))));
                    }
                    plot = plot.hline(0.0, "");
                }
                2 => {
                    for k in 0..4 {
                        plot = plot.series(series(k, true, format!("λ{} (fd)", sub(k + 1))));
                    }
                    plot = plot
                        .series(
                            Series::new(
                                "exact ±λ₁",
                                points.iter().map(|p| (p.alpha, p.exact.mean[0])),
                            )
                            .line_only()
                            .kind(LineKind::Dashed)
                            .color(RGBColor(90, 90, 90)),
                        )
                        .series(
                            Series::unlabelled(points.iter().map(|p| (p.alpha, p.exact.mean[4])))
                                .line_only()
                                .kind(LineKind::Dashed)
                                .color(RGBColor(90, 90, 90)),
                        )
                        .hline(0.0, "")
                        .y_range(-0.5, 0.85);
                }
                _ => {
                    plot = plot
                        .series(series(4, true, "λ₅ (fd, δ0 = 10⁻⁷)".into()))
                        .legend(Legend::LowerLeft);
                }
            }
            grid.push(plot);
        }
    }
    let png = args.output("spectrum.png")?;
    let (w, h) = args.pick((1400, 1700), (1800, 2200), (2200, 2700));
    grid.save_png(&png, w, h)?;

    // Data.
    let mut csv = String::from(
        "table,alpha,method,ics,collisions,l1,l2,l3,l4,l5,sem1,sem2,sem3,sem4,sem5,sum_mean,floored,wall_s\n",
    );
    let mut rows_json = Vec::new();
    for (spec, points) in &results {
        for p in points {
            for (name, e) in [("tangent", &p.exact), ("fd", &p.fd)] {
                let _ = writeln!(
                    csv,
                    "\"{spec}\",{},{name},{},{},{},{},{:.3e},{},{:.2}",
                    p.alpha,
                    e.n_ics,
                    e.options.collisions,
                    e.mean.map(|x| format!("{x:.6e}")).join(","),
                    e.sem.map(|x| format!("{x:.3e}")).join(","),
                    e.sum_mean,
                    e.floored,
                    e.wall_time_s
                );
            }
            let (pair_exact, pair_exact_sem) = p.exact.pair_sum(0, 4);
            let (pair_fd, pair_fd_sem) = p.fd.pair_sum(0, 3);
            rows_json.push(json!({
                "table": spec, "alpha": p.alpha,
                "exact": {"mean": p.exact.mean, "sem": p.exact.sem,
                          "per_collision": p.exact.per_collision_mean,
                          "sum_mean": p.exact.sum_mean, "sum_max_abs": p.exact.sum_max_abs,
                          "l1_plus_l5": [pair_exact, pair_exact_sem],
                          "middle_max_abs": p.exact.middle_max_abs(),
                          "wall_time_s": p.exact.wall_time_s},
                "fd": {"mean": p.fd.mean, "sem": p.fd.sem,
                       "per_collision": p.fd.per_collision_mean,
                       "sum_mean": p.fd.sum_mean, "floored": p.fd.floored,
                       "l1_plus_l4": [pair_fd, pair_fd_sem],
                       "middle_max_abs": p.fd.mean[1].abs().max(p.fd.mean[2].abs()),
                       "wall_time_s": p.fd.wall_time_s},
            }));
        }
    }
    std::fs::write(args.output("spectrum.csv")?, csv)?;
    let doc = json!({
        "figure": NAME, "mode": args.mode.to_string(), "ics": ics, "collisions": collisions,
        "sampler": "paper", "seed": args.seed, "qr_interval": 1, "delta0": 1e-7,
        "results": rows_json, "version": env!("CARGO_PKG_VERSION"),
    });
    std::fs::write(
        args.output("spectrum.json")?,
        serde_json::to_string_pretty(&doc)? + "\n",
    )?;
    println!(
        "{NAME} ({} mode): wrote {} and CSV/JSON in {:.1} s",
        args.mode,
        png.display(),
        t0.elapsed().as_secs_f64()
    );
    Ok(())
}

fn fmt5(e: &SpectrumEstimate) -> String {
    e.mean
        .iter()
        .map(|x| format!("{x:+.4}"))
        .collect::<Vec<_>>()
        .join(" ")
}

fn sub(k: usize) -> &'static str {
    ["₀", "₁", "₂", "₃", "₄", "₅"][k]
}
