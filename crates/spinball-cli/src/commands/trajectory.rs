//! `spinball trajectory`: the collisions of one start, as CSV or NPY.

use std::path::PathBuf;

use clap::Args;
use spinball_analysis::diagnostics::{COLLISION_COLUMNS, collision_log};
use spinball_analysis::run::{RunDefaults, Starts};
use spinball_core::{Billiard, SpinLaw, State};
use spinball_geometry::DVec2;

use crate::error::CliError;
use crate::output::{write_npy, write_text};
use crate::pictures::{check_png, trajectory_png};
use crate::run_args::SamplerArg;
use crate::stdout::print;
use crate::table_arg::read_table;

/// The arguments of `spinball trajectory`.
#[derive(Debug, Clone, Args)]
pub struct TrajectoryArgs {
    /// The table (spec or table file, as for `lyapunov`).
    #[arg(long)]
    pub table: String,
    /// Spin parameter α.
    #[arg(long, allow_negative_numbers = true)]
    pub alpha: f64,
    /// Allow α > 1.
    #[arg(long)]
    pub extended: bool,
    /// Number of collisions.
    #[arg(long, default_value_t = 100)]
    pub collisions: u64,
    /// Start position `x,y` (with --velocity; else the start is drawn).
    #[arg(long, value_delimiter = ',', allow_negative_numbers = true)]
    pub position: Option<Vec<f64>>,
    /// Start velocity `vx,vy`.
    #[arg(long, value_delimiter = ',', allow_negative_numbers = true)]
    pub velocity: Option<Vec<f64>>,
    /// Start spin u = rω.
    #[arg(long, default_value_t = 0.0, allow_negative_numbers = true)]
    pub spin: f64,
    /// Draw the start as initial condition INDEX of --seed (when no
    /// position is given).
    #[arg(long, default_value_t = 0)]
    pub index: u64,
    /// Seed of the drawn start.
    #[arg(long, default_value_t = RunDefaults::SEED)]
    pub seed: u64,
    /// Sampler of the drawn start.
    #[arg(long, value_enum, default_value_t = RunDefaults::SAMPLER.into())]
    pub sampler: SamplerArg,
    /// Write CSV here (default: stdout).
    #[arg(long)]
    pub csv: Option<PathBuf>,
    /// Write an NPY array of shape (collisions, 10) here; columns as the CSV
    /// header: time, x, y, vx, vy, u, wall, s, v_par, q.
    #[arg(long)]
    pub npy: Option<PathBuf>,
    /// Draw the path on the table to this PNG, 1200 × 800 px, each flight
    /// coloured by the spin u it carries, with a colour bar (checked
    /// before the run; with --png and no --csv/--npy nothing goes to
    /// stdout).
    #[arg(long)]
    pub png: Option<PathBuf>,
}

/// `spinball trajectory`.
///
/// # Errors
/// [`CliError::Usage`] for a bad table, α or start; [`CliError::Failed`]
/// if a step fails or an output (stdout included) cannot be written;
/// [`CliError::StdoutClosed`] if stdout's reader went away.
pub fn trajectory(args: &TrajectoryArgs) -> Result<(), CliError> {
    let table = read_table(&args.table)?;
    let law = if args.extended {
        SpinLaw::extended(args.alpha)
    } else {
        SpinLaw::new(args.alpha)
    }
    .map_err(|e| CliError::Usage(format!("--alpha {}: {e}", args.alpha)))?;
    let pair = |v: &[f64], name: &str| match v {
        [x, y] => Ok(DVec2::new(*x, *y)),
        _ => Err(CliError::Usage(format!(
            "--{name} takes two numbers, x,y (got {})",
            v.len()
        ))),
    };
    let start = match (&args.position, &args.velocity) {
        (Some(p), Some(v)) => State::new(pair(p, "position")?, pair(v, "velocity")?, args.spin),
        (None, None) => {
            Starts::Sampled(args.sampler.into())
                .draw(&table, &law, args.seed, args.index)
                .map_err(CliError::usage)?
                .0
        }
        _ => {
            return Err(CliError::Usage(
                "give both --position and --velocity, or neither (to draw the start)".into(),
            ));
        }
    };
    if let Some(path) = &args.png {
        check_png(path)?;
    }
    let title = format!(
        "{table} at α = {}: {} collisions",
        law.alpha(),
        args.collisions
    );
    let billiard = Billiard::new(table, law);
    let log = collision_log(&billiard, start, args.collisions).map_err(|e| match e {
        spinball_analysis::AnalysisError::Launch { source, .. } => {
            CliError::Usage(format!("the start cannot be launched: {source}"))
        }
        e => CliError::failed(e),
    })?;
    if let Some(path) = &args.npy {
        let values: Vec<f64> = log.rows.iter().flatten().copied().collect();
        write_npy(
            path,
            &[log.rows.len() as u64, COLLISION_COLUMNS.len() as u64],
            &values,
        )?;
    }
    if let Some(path) = &args.png {
        // The path: the start, then every collision point; the flight
        // from point i carries the spin after collision i − 1 (the start's
        // spin for the first).
        let mut points = vec![start.position];
        let mut spins = vec![start.spin];
        for r in &log.rows {
            points.push(DVec2::new(r[1], r[2]));
            spins.push(r[5]);
        }
        spins.pop();
        trajectory_png(path, billiard.table(), title, points, spins)?;
    }
    match &args.csv {
        Some(path) => write_text(path, &log.to_csv())?,
        None if args.npy.is_none() && args.png.is_none() => print(&log.to_csv())?,
        None => {}
    }
    Ok(())
}
