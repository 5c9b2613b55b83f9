//! `spinball orbits`: the periodic orbits of one period on a table, their
//! stability through a range of α, and the α where it changes.

use std::path::PathBuf;

use clap::Args;
use spinball_analysis::orbits::{
    IslandOptions, IslandPoint, ORBIT_CSV_HEADER, SearchOptions, StabilityDiagram, islands_along,
    stability_diagram,
};
use spinball_analysis::report::{Document, OrbitsDocument};

use crate::documents::write_document;
use crate::error::CliError;
use crate::files::check_outputs;
use crate::output::write_text;
use crate::stdout::print;
use crate::table_arg::read_table;

/// The arguments of `spinball orbits`.
#[derive(Debug, Clone, Args)]
pub struct OrbitsArgs {
    /// The table (spec or table file, as for `lyapunov`).
    #[arg(long)]
    pub table: String,
    /// Collisions per period.
    #[arg(long, default_value_t = 2)]
    pub period: u32,
    /// The α range `FROM,TO,STEPS`: STEPS + 1 equally spaced values; the
    /// orbits are found at FROM and followed to TO.
    #[arg(
        long,
        value_delimiter = ',',
        default_value = "0,1,20",
        allow_negative_numbers = true
    )]
    pub alpha_range: Vec<f64>,
    /// Locate each change of stability to this precision in α.
    #[arg(long, default_value_t = 1e-8)]
    pub precision: f64,
    /// Arc-length samples of the normal-incidence seeds (0: none).
    #[arg(long, default_value_t = 4096)]
    pub normal_samples: u32,
    /// Grid seeds `NS,NV,NW` over (s, sin θ, √α u) (default none).
    #[arg(long, value_delimiter = ',', default_value = "0,0,0")]
    pub grid: Vec<u32>,
    /// Also measure the regular island around each orbit at each α where
    /// it is elliptic (FTLE map of a window centred on the orbit, flood
    /// fill from its cell): adds `island_area`, `island_error` to the CSV
    /// and `islands` to the JSON.
    #[arg(long)]
    pub islands: bool,
    /// Cells per side of the island window (odd).
    #[arg(long, default_value_t = 41)]
    pub island_cells: usize,
    /// Collisions per cell of the island window.
    #[arg(long, default_value_t = 2000)]
    pub island_collisions: u64,
    /// Seed of the island maps' tangent directions.
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
    /// Write the diagram as JSON here.
    #[arg(long)]
    pub json: Option<PathBuf>,
    /// Write one row per orbit and α as CSV here.
    #[arg(long)]
    pub csv: Option<PathBuf>,
    /// No summary on stdout.
    #[arg(long, short)]
    pub quiet: bool,
}

impl OrbitsArgs {
    fn alphas(&self) -> Result<Vec<f64>, CliError> {
        let [from, to, steps] = self.alpha_range[..] else {
            return Err(CliError::Usage(format!(
                "--alpha-range takes FROM,TO,STEPS (got {} numbers)",
                self.alpha_range.len()
            )));
        };
        if !(from.is_finite() && to.is_finite() && from >= 0.0 && to >= 0.0) {
            return Err(CliError::Usage(format!(
                "--alpha-range: FROM and TO must be finite and >= 0 (got {from}, {to})"
            )));
        }
        if !(steps >= 0.0 && steps.fract() == 0.0 && steps <= 100_000.0) {
            return Err(CliError::Usage(format!(
                "--alpha-range: STEPS must be a whole number in [0, 100000] (got {steps})"
            )));
        }
        let n = steps as u32;
        Ok((0..=n)
            .map(|i| {
                if n == 0 {
                    from
                } else {
                    from + (to - from) * f64::from(i) / f64::from(n)
                }
            })
            .collect())
    }
}

/// `spinball orbits`.
///
/// # Errors
/// [`CliError::Usage`] for a bad table or option; [`CliError::Failed`] if
/// an output (stdout included) cannot be written.
pub fn orbits(args: &OrbitsArgs) -> Result<(), CliError> {
    let table = read_table(&args.table)?;
    let alphas = args.alphas()?;
    let [ns, nv, nw] = args.grid[..] else {
        return Err(CliError::Usage(format!(
            "--grid takes NS,NV,NW (got {} numbers)",
            args.grid.len()
        )));
    };
    check_outputs(args.json.as_deref(), &[("csv", args.csv.as_deref())])?;
    let search = SearchOptions {
        normal_samples: args.normal_samples,
        grid: [ns, nv, nw],
        ..SearchOptions::default()
    };
    let diagram = stability_diagram(&table, args.period, &alphas, args.precision, &search)
        .map_err(CliError::usage)?;
    let islands = if args.islands {
        let options = IslandOptions::default()
            .with_cells(args.island_cells)
            .with_collisions(args.island_collisions)
            .with_seed(args.seed);
        let per_branch = diagram
            .branches
            .iter()
            .map(|b| islands_along(&table, b, &options))
            .collect::<Result<Vec<_>, _>>()
            .map_err(CliError::usage)?;
        Some(per_branch)
    } else {
        None
    };
    if let Some(path) = &args.json {
        let doc = Document::Orbits(OrbitsDocument {
            table: args.table.clone(),
            diagram: diagram.clone(),
            islands: islands.clone(),
        });
        write_document(path, &doc, false)?;
    }
    if let Some(path) = &args.csv {
        write_text(path, &csv(&diagram, islands.as_deref()))?;
    }
    if args.quiet {
        return Ok(());
    }
    let mut text = summary(&args.table, &diagram);
    if let Some(islands) = &islands {
        text.push_str(&island_summary(islands));
    }
    print(&text)
}

/// The diagram's rows as CSV, with the island's area and error at the end
/// of each row when measured (empty where not known).
fn csv(diagram: &StabilityDiagram, islands: Option<&[Vec<IslandPoint>]>) -> String {
    let mut text = String::from(ORBIT_CSV_HEADER);
    if islands.is_some() {
        text.push_str(",island_area,island_error");
    }
    text.push('\n');
    let points = islands.map(|i| i.iter().flatten().collect::<Vec<_>>());
    let opt = |x: Option<f64>| x.map_or(String::new(), |x| x.to_string());
    for (k, row) in diagram.rows().iter().enumerate() {
        text.push_str(&row.csv_line());
        if let Some(p) = points.as_ref().map(|p| p[k]) {
            text.push_str(&format!(",{},{}", opt(p.area), opt(p.error)));
        }
        text.push('\n');
    }
    text
}

/// One line per orbit: its island area at each α where it is known.
fn island_summary(islands: &[Vec<IslandPoint>]) -> String {
    let mut out = String::new();
    for (i, points) in islands.iter().enumerate() {
        let known: Vec<String> = points
            .iter()
            .filter_map(|p| match (p.area, p.error) {
                (Some(a), Some(e)) if a > 0.0 => Some(format!("{}: {a:.4e} +- {e:.1e}", p.alpha)),
                _ => None,
            })
            .collect();
        if !known.is_empty() {
            out.push_str(&format!(
                "orbit {i}: island area (s, sin theta) at alpha {}\n",
                known.join(", ")
            ));
        }
        for p in points.iter().filter(|p| p.failure.is_some()) {
            out.push_str(&format!(
                "orbit {i}: no island at alpha = {}: {}\n",
                p.alpha,
                p.failure.as_deref().unwrap_or_default()
            ));
        }
    }
    out
}

/// One line per orbit (at the first and last α) and per change.
fn summary(table: &str, d: &StabilityDiagram) -> String {
    let mut out = format!(
        "{table}: {} orbit(s) of period {} at alpha = {}, followed to {}\n",
        d.branches.len(),
        d.period,
        d.alphas[0],
        d.alphas[d.alphas.len() - 1]
    );
    for (i, b) in d.branches.iter().enumerate() {
        let (first, last) = (&b.orbits[0], &b.orbits[b.orbits.len() - 1]);
        let walls: Vec<String> = first.walls.iter().map(u32::to_string).collect();
        out.push_str(&format!(
            "orbit {i}: s = {:.6}, walls {}, T = {:.6} ({}) -> T = {:.6} ({})\n",
            first.points[0].s,
            walls.join("-"),
            first.stability.pair_trace,
            first.stability.class.name(),
            last.stability.pair_trace,
            last.stability.class.name(),
        ));
        for c in &b.changes {
            out.push_str(&format!(
                "  T = {:+} at alpha = {:.10} +- {:.1e} ({} -> {})\n",
                c.crossing,
                c.alpha,
                c.error,
                c.before.name(),
                c.after.name()
            ));
        }
    }
    for (s, why) in &d.lost {
        out.push_str(&format!("lost: the orbit from s = {s:.6}: {why}\n"));
    }
    out
}
