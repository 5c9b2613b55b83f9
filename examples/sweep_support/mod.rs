//! Plumbing shared by the λ(α) examples (`stadium_sweep` and the `fig_*`
//! sweeps): the command line (the figure arguments plus `--threads`),
//! progress on stderr, result tables on stdout as points finish, and the
//! CSV/JSON files. The physics and statistics live in
//! `spinball_analysis::sweep`; this module only moves their results around.
//!
//! Each example includes it with `mod sweep_support;` (a
//! directory without `main.rs` is not an example itself).

use std::error::Error;
use std::io::{IsTerminal, Write as _};
use std::path::PathBuf;
use std::time::Instant;

use serde_json::{Value, json};
use spinball_analysis::{
    AlphaSweep, CurvedShare, Ensemble, LyapunovEstimate, Measurement, StopRule, SweepEvent,
    SweepRow, Threads, curved_share, sweep_rows, write_csv,
};
use spinball_plot::Series;
use spinball_plot::cli::{self, FigureArgs, Parsed};

/// A boxed error for `main`.
pub type BoxError = Box<dyn Error + Send + Sync>;

/// x-axis label of every λ(α) plot.
pub const ALPHA_LABEL: &str = "spin parameter α = I/(m r²)";
/// y-axis label of λ per unit time (E = ½, so |V| = 1: time in units of
/// length over that speed).
pub const LAMBDA_LABEL: &str = "λ (per unit time, E = ½)";

/// The paper's stadium (a = 1) values, (α, λ): §IV and Table I.
pub const PAPER_STADIUM: [(f64, f64); 5] = [
    (0.0, 0.43),
    (0.1, 0.280),
    (0.4, 0.20),
    (0.5, 0.183),
    (1.0, 0.147),
];
/// The paper's Sinai (L = 2, R = 1) values, (α, λ): §IV and Table I.
pub const PAPER_SINAI: [(f64, f64); 5] = [
    (0.0, 0.43),
    (0.1, 0.211),
    (0.4, 0.12),
    (0.5, 0.119),
    (1.0, 0.102),
];

/// The command line: the shared figure arguments and `--threads N`.
pub struct Cli {
    /// `--out`, `--quick`/`--paper`, `--seed`.
    pub fig: FigureArgs,
    /// `--threads N` (default: all cores). Results do not depend on it.
    pub threads: Threads,
    /// Example name.
    pub name: &'static str,
}

impl Cli {
    /// Read the process's arguments; `--help` prints the usage and exits 0,
    /// a bad argument prints the error and exits 2.
    pub fn parse(name: &'static str, about: &str) -> Cli {
        let usage = || {
            format!(
                "{}\n  --threads N worker threads (default: all cores); results do not depend on it",
                cli::usage(name, about)
            )
        };
        let fail = |msg: String| -> ! {
            eprintln!("{name}: {msg}\n\n{}", usage());
            std::process::exit(2)
        };
        let mut rest = Vec::new();
        let mut threads = Threads::All;
        let mut it = std::env::args().skip(1);
        while let Some(arg) = it.next() {
            let value = if arg == "--threads" {
                Some(
                    it.next()
                        .unwrap_or_else(|| fail("`--threads` needs a value".into())),
                )
            } else {
                arg.strip_prefix("--threads=").map(str::to_string)
            };
            match value {
                Some(v) => match v.trim().parse::<usize>() {
                    Ok(n) if n >= 1 => threads = Threads::Fixed(n),
                    _ => fail(format!("`--threads {v}`: not a positive integer")),
                },
                None => rest.push(arg),
            }
        }
        match FigureArgs::try_parse_from(name, rest) {
            Ok(Parsed::Run(fig)) => Cli { fig, threads, name },
            Ok(Parsed::Help) => {
                println!("{}", usage());
                std::process::exit(0)
            }
            Err(e) => fail(e.to_string()),
        }
    }

    /// `quick`, `default` or `paper` by the mode.
    pub fn pick<T>(&self, quick: T, default: T, paper: T) -> T {
        self.fig.pick(quick, default, paper)
    }

    /// The path of `file` in the output directory (created).
    pub fn output(&self, file: &str) -> Result<PathBuf, BoxError> {
        Ok(self.fig.output(file)?)
    }

    /// The mode's name: `quick`, `default` or `paper`.
    pub fn mode(&self) -> String {
        self.fig.mode.to_string()
    }

    /// Threads as a number for reports.
    pub fn thread_count(&self) -> usize {
        self.threads.count()
    }
}

/// How big each ensemble of a figure is, per mode.
#[derive(Debug, Clone, Copy)]
pub struct Plan {
    /// Most initial conditions per point (all of them without a stop rule).
    pub ics: u64,
    /// Collisions per initial condition.
    pub collisions: u64,
    /// Batches until SEM/λ reaches a target (`None`: run all `ics`).
    pub stop: Option<StopRule>,
}

impl Plan {
    /// Exactly `ics` initial conditions.
    pub fn fixed(ics: u64, collisions: u64) -> Plan {
        Plan {
            ics,
            collisions,
            stop: None,
        }
    }

    /// Batches of `batch` until `SEM ≤ target · λ` (at least `min_ics`, at
    /// most `ics`).
    pub fn until(target: f64, batch: u64, min_ics: u64, ics: u64, collisions: u64) -> Plan {
        Plan {
            ics,
            collisions,
            stop: Some(StopRule::new(batch, target).with_min_ics(min_ics)),
        }
    }

    /// The plan applied to an ensemble template.
    pub fn apply(&self, template: Ensemble) -> Ensemble {
        template.with_ics(self.ics).with_collisions(self.collisions)
    }

    /// A sweep of `template` (sized by this plan) over `alphas`.
    pub fn sweep(&self, template: Ensemble, alphas: &[f64]) -> Result<AlphaSweep, BoxError> {
        Ok(AlphaSweep::new(self.apply(template), alphas)?.with_stop(self.stop))
    }

    /// A JSON description.
    pub fn json(&self) -> Value {
        json!({
            "max_ics": self.ics,
            "collisions": self.collisions,
            "stop_rule": self.stop.map(|r| json!({
                "target_rel_sem": r.target_rel_sem,
                "batch": r.batch,
                "min_ics": r.min_ics,
            })),
        })
    }

    /// One line for the terminal.
    pub fn describe(&self) -> String {
        match self.stop {
            Some(r) => format!(
                "batches of {} ICs until SEM <= {}% of lambda ({}..{} ICs) x {} collisions",
                r.batch,
                100.0 * r.target_rel_sem,
                r.min_ics,
                self.ics,
                self.collisions
            ),
            None => format!("{} ICs x {} collisions", self.ics, self.collisions),
        }
    }
}

/// One labelled sweep of a figure.
pub struct Job {
    /// Legend label and section title (e.g. `stadium a = 1, fd`).
    pub label: String,
    /// The sweep.
    pub sweep: AlphaSweep,
}

/// The results of one [`Job`].
pub struct Curve {
    /// Its label.
    pub label: String,
    /// One estimate per α, in order.
    pub estimates: Vec<LyapunovEstimate>,
}

impl Curve {
    /// The α values.
    pub fn alphas(&self) -> Vec<f64> {
        self.estimates.iter().map(|e| e.alpha).collect()
    }

    /// `(α, f(e))` points and `g(e)` errors as a plot series.
    pub fn series(
        &self,
        label: impl Into<String>,
        value: impl Fn(&LyapunovEstimate) -> Measurement,
    ) -> Series {
        let m: Vec<Measurement> = self.estimates.iter().map(value).collect();
        Series::new(
            label,
            self.estimates
                .iter()
                .zip(&m)
                .map(|(e, m)| (e.alpha, m.value)),
        )
        .errors(m.iter().map(|m| m.sem))
    }

    /// λ(α) ± SEM as a plot series labelled with the curve's label.
    pub fn lambda_series(&self) -> Series {
        self.series(self.label.clone(), Measurement::lambda)
    }

    /// The records of the estimates.
    pub fn rows(&self) -> Result<Vec<SweepRow>, BoxError> {
        Ok(sweep_rows(&self.estimates)?)
    }
}

/// Run `jobs` in order: a section per job on stdout with a row per point
/// as it finishes, one progress line over all points on stderr.
pub fn run_jobs(cli: &Cli, jobs: Vec<Job>) -> Result<Vec<Curve>, BoxError> {
    let total: usize = jobs.iter().map(|j| j.sweep.laws.len()).sum();
    let mut progress = Progress::new(total);
    let mut curves = Vec::with_capacity(jobs.len());
    for job in jobs {
        let t = &job.sweep.template;
        println!(
            "\n{} | {} | {} | sampler {} | seed {} | {} threads",
            job.label,
            t.table,
            t.method.name(),
            t.starts.sampler().map_or("states", |s| s.name()),
            t.seed,
            cli.thread_count()
        );
        println!("{}", SweepRow::table_header());
        let label = job.label.clone();
        let mut row_error = None;
        let estimates = job.sweep.run_with(|event| match event {
            SweepEvent::Batch(p) => progress.batch(&label, p),
            SweepEvent::Finished { estimate, .. } => {
                progress.point_done();
                match SweepRow::from_estimate(estimate) {
                    Ok(row) => progress.println(&row.table_line()),
                    Err(e) => {
                        row_error.get_or_insert(e);
                    }
                }
            }
            _ => {}
        })?;
        if let Some(e) = row_error {
            return Err(e.into());
        }
        curves.push(Curve {
            label: job.label,
            estimates,
        });
    }
    progress.finish();
    Ok(curves)
}

/// A progress line on stderr: redrawn in place on a terminal, one line
/// per finished point otherwise (logs stay short).
struct Progress {
    total: usize,
    done: usize,
    start: Instant,
    tty: bool,
    drawn: bool,
}

impl Progress {
    fn new(total: usize) -> Self {
        Progress {
            total,
            done: 0,
            start: Instant::now(),
            tty: std::io::stderr().is_terminal(),
            drawn: false,
        }
    }

    fn bar(&self, fraction: f64) -> String {
        const WIDTH: usize = 24;
        let filled = ((fraction.clamp(0.0, 1.0) * WIDTH as f64).round() as usize).min(WIDTH);
        format!("[{}{}]", "#".repeat(filled), "-".repeat(WIDTH - filled))
    }

    fn eta(&self, fraction: f64) -> String {
        let elapsed = self.start.elapsed().as_secs_f64();
        if fraction <= 0.0 {
            return format!("{elapsed:.0} s");
        }
        let left = elapsed * (1.0 - fraction) / fraction;
        format!("{elapsed:.0} s, ~{left:.0} s left")
    }

    fn batch(&mut self, label: &str, p: &spinball_analysis::BatchProgress) {
        if !self.tty {
            return;
        }
        // Within a point, count ICs against the cap (a stop rule usually
        // stops earlier, so this is a lower bound on progress).
        let within = p.ics_done as f64 / p.ics_max.max(1) as f64;
        let fraction = (self.done as f64 + within) / self.total.max(1) as f64;
        let target = p
            .target_rel_sem
            .map_or(String::new(), |t| format!(" (target {:.1}%)", 100.0 * t));
        let line = format!(
            "{} {}/{} {label} α={:.3}: {} ICs, SEM/λ {:.2}%{target} | {}",
            self.bar(fraction),
            self.done + 1,
            self.total,
            p.alpha,
            p.ics_done,
            100.0 * p.rel_sem(),
            self.eta(fraction)
        );
        eprint!("\r\x1b[2K{line}");
        let _ = std::io::stderr().flush();
        self.drawn = true;
    }

    fn point_done(&mut self) {
        self.done += 1;
        if !self.tty {
            let fraction = self.done as f64 / self.total.max(1) as f64;
            eprintln!(
                "{} {}/{} points | {}",
                self.bar(fraction),
                self.done,
                self.total,
                self.eta(fraction)
            );
        }
    }

    /// Print a stdout line without tearing the progress line.
    fn println(&mut self, line: &str) {
        if self.drawn {
            eprint!("\r\x1b[2K");
            self.drawn = false;
        }
        println!("{line}");
    }

    fn finish(&mut self) {
        if self.drawn {
            eprintln!();
        }
        eprintln!(
            "{} {} points in {:.1} s",
            self.bar(1.0),
            self.total,
            self.start.elapsed().as_secs_f64()
        );
    }
}

/// Write every curve's rows to `<stem>.csv` and a JSON document
/// `<stem>.json` with the run's settings (`settings`), the curves (label and
/// points) and `extra` fields merged at the top level. Returns the paths.
pub fn write_results(
    cli: &Cli,
    stem: &str,
    curves: &[Curve],
    settings: Value,
    extra: Value,
) -> Result<(PathBuf, PathBuf), BoxError> {
    let csv_path = cli.output(&format!("{stem}.csv"))?;
    let mut rows = Vec::new();
    let mut series = Vec::new();
    for c in curves {
        let r = c.rows()?;
        series.push(json!({"label": c.label, "points": r}));
        rows.extend(r);
    }
    let mut file = std::io::BufWriter::new(std::fs::File::create(&csv_path)?);
    write_csv(&mut file, &rows)?;
    file.flush()?;

    let total_wall: f64 = curves
        .iter()
        .flat_map(|c| &c.estimates)
        .map(|e| e.wall_time_s)
        .sum();
    let mut doc = json!({
        "figure": cli.name,
        "mode": cli.mode(),
        "seed": cli.fig.seed,
        "threads": cli.thread_count(),
        "version": env!("CARGO_PKG_VERSION"),
        "settings": settings,
        "total_wall_time_s": total_wall,
        "series": series,
    });
    if let (Some(map), Value::Object(more)) = (doc.as_object_mut(), extra) {
        map.extend(more);
    }
    let json_path = cli.output(&format!("{stem}.json"))?;
    std::fs::write(&json_path, serde_json::to_string_pretty(&doc)? + "\n")?;
    Ok((csv_path, json_path))
}

/// `0, step, 2·step, …, 1` with exact decimal values (e.g. 0.05 → 21 points).
pub fn unit_grid(points: usize) -> Vec<f64> {
    let n = points.max(2) - 1;
    (0..=n)
        .map(|i| ((i as f64 / n as f64) * 1e6).round() / 1e6)
        .collect()
}

/// A template ensemble on `table` (a spec) with the CLI's seed and threads.
pub fn template(cli: &Cli, table: &str) -> Result<Ensemble, BoxError> {
    let table: spinball_geometry::Table = table.parse()?;
    Ok(Ensemble::new(table, spinball_core::SpinLaw::specular())
        .with_seed(cli.fig.seed)
        .with_threads(cli.threads))
}

/// The final line of every example.
pub fn report_done(cli: &Cli, files: &[&PathBuf], start: Instant) {
    let names: Vec<String> = files.iter().map(|p| p.display().to_string()).collect();
    println!(
        "\n{} ({} mode, {} threads): wrote {} in {:.1} s",
        cli.name,
        cli.mode(),
        cli.thread_count(),
        names.join(", "),
        start.elapsed().as_secs_f64()
    );
}

/// The share of collisions on curved walls of `table` at each α (paper
/// sampler, the CLI's seed and threads, `ics` × `collisions`).
pub fn curved_shares(
    cli: &Cli,
    table: &str,
    alphas: &[f64],
    ics: u64,
    collisions: u64,
) -> Result<Vec<CurvedShare>, BoxError> {
    let table: spinball_geometry::Table = table.parse()?;
    alphas
        .iter()
        .map(|&a| {
            Ok(curved_share(
                &table,
                spinball_core::SpinLaw::new(a)?,
                spinball_core::Sampler::Paper,
                cli.fig.seed,
                0..ics,
                collisions,
                cli.threads,
            )?)
        })
        .collect()
}

/// `"61%"` or `"58–63%"`: the range of the per-IC mean curved share over α.
pub fn share_range(shares: &[CurvedShare]) -> String {
    let v: Vec<f64> = shares.iter().map(|s| 100.0 * s.per_ic.value).collect();
    let lo = v.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = v.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    if hi.round() == lo.round() {
        format!("{lo:.0}%")
    } else {
        format!("{lo:.0}–{hi:.0}%")
    }
}

/// Curved shares as JSON records (without the full wall statistics).
pub fn shares_json(shares: &[CurvedShare]) -> Value {
    Value::Array(
        shares
            .iter()
            .map(|s| {
                json!({
                    "table": s.table,
                    "alpha": s.alpha,
                    "curved_share": s.per_ic.value,
                    "curved_share_sem": s.per_ic.sem,
                    "pooled": s.pooled,
                    "perimeter_share": s.perimeter_share,
                    "n_ics": s.n_ics,
                    "collisions_per_ic": s.collisions_per_ic,
                    "wall_time_s": s.wall_time_s,
                })
            })
            .collect(),
    )
}

/// Curved shares as CSV text.
pub fn shares_csv(shares: &[CurvedShare]) -> String {
    let mut s = String::from(
        "table,alpha,curved_share,curved_share_sem,pooled,perimeter_share,n_ics,collisions_per_ic\n",
    );
    for c in shares {
        s.push_str(&format!(
            "\"{}\",{},{},{},{},{},{},{}\n",
            c.table,
            c.alpha,
            c.per_ic.value,
            c.per_ic.sem,
            c.pooled,
            c.perimeter_share,
            c.n_ics,
            c.collisions_per_ic
        ));
    }
    s
}

/// Published values drawn as large markers without a line.
pub fn paper_markers(
    label: &str,
    points: impl IntoIterator<Item = (f64, f64)>,
    color: spinball_plot::RGBColor,
) -> Series {
    Series::new(label, points)
        .markers_only()
        .marker_radius(7)
        .color(color)
}

/// Run `f` and turn its error into a message and exit code 1.
pub fn main_with(name: &str, f: impl FnOnce() -> Result<(), BoxError>) -> std::process::ExitCode {
    match f() {
        Ok(()) => std::process::ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("{name}: {e}");
            std::process::ExitCode::FAILURE
        }
    }
}

/// A scan over tables (one λ(α) curve each) with the curved share of each
/// table at every α in its legend label: `"<label> (61–63% curved)"`.
pub struct Scan {
    /// One curve per table.
    pub curves: Vec<Curve>,
    /// Curved shares per table, one per α.
    pub shares: Vec<Vec<CurvedShare>>,
}

/// Run a [`Scan`]: the curved shares first (`share_ics` × `share_collisions`
/// per α, cheap), then the sweeps.
pub fn run_scan(
    cli: &Cli,
    tables: &[(String, String)],
    alphas: &[f64],
    plan: &Plan,
    share_ics: u64,
    share_collisions: u64,
) -> Result<Scan, BoxError> {
    println!(
        "\ncurved share (paper sampler, {share_ics} ICs x {share_collisions} collisions per alpha):"
    );
    let mut shares = Vec::new();
    let mut jobs = Vec::new();
    for (spec, label) in tables {
        let s = curved_shares(cli, spec, alphas, share_ics, share_collisions)?;
        println!(
            "  {label:<22} perimeter share {:.3} | alpha 0: {:.3} ± {:.3} | alpha {}: {:.3} ± {:.3}",
            s[0].perimeter_share,
            s[0].per_ic.value,
            s[0].per_ic.sem,
            s.last().map_or(0.0, |x| x.alpha),
            s.last().map_or(0.0, |x| x.per_ic.value),
            s.last().map_or(0.0, |x| x.per_ic.sem),
        );
        jobs.push(Job {
            label: format!("{label} ({} curved)", share_range(&s)),
            sweep: plan.sweep(template(cli, spec)?, alphas)?,
        });
        shares.push(s);
    }
    let curves = run_jobs(cli, jobs)?;
    Ok(Scan { curves, shares })
}

/// Write the curved shares of a scan to `<stem>_curved.csv`.
pub fn write_shares(cli: &Cli, stem: &str, scan: &Scan) -> Result<PathBuf, BoxError> {
    let path = cli.output(&format!("{stem}_curved.csv"))?;
    let all: Vec<CurvedShare> = scan.shares.iter().flatten().cloned().collect();
    std::fs::write(&path, shares_csv(&all))?;
    Ok(path)
}
