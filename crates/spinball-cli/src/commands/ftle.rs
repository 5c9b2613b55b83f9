//! `spinball ftle`: the distribution of finite-time exponents, per initial
//! condition and as a histogram, beside the λ estimate.

use std::path::PathBuf;

use clap::Args;
use spinball_analysis::estimators::Histogram;
use spinball_analysis::report::trajectories_csv;

use crate::commands::lyapunov::{LyapunovArgs, Outcome, run_ensembles};
use crate::error::CliError;
use crate::output::write_text;

/// The arguments of `spinball ftle`.
#[derive(Debug, Clone, Args)]
pub struct FtleArgs {
    #[command(flatten)]
    pub lyapunov: LyapunovArgs,
    /// Write every initial condition's values as CSV
    /// (`alpha,index,exponent,per_collision,time,collisions`); with several α,
    /// one file per α with `.alpha-K` before the extension.
    #[arg(long)]
    pub per_ic: Option<PathBuf>,
    /// Write the histogram of the exponents as CSV (`lo,hi,count,density`).
    #[arg(long)]
    pub histogram: Option<PathBuf>,
    /// Bins of the histogram (over the range of the exponents), 1..=1048576.
    #[arg(long, default_value_t = 60, value_parser = parse_bins)]
    pub bins: usize,
}

/// Parse `--bins`: a whole number in `1..=`[`Histogram::MAX_BINS`],
/// checked before the run.
///
/// # Errors
/// The range that works, for anything else.
pub fn parse_bins(s: &str) -> Result<usize, String> {
    match s.trim().parse::<usize>() {
        Ok(n) if (1..=Histogram::MAX_BINS).contains(&n) => Ok(n),
        _ => Err(format!(
            "the histogram's bins must be a whole number in 1..={}",
            Histogram::MAX_BINS
        )),
    }
}

/// `path` for point `k` of `n`: itself if there is one point.
fn nth(path: &std::path::Path, k: usize, n: usize) -> PathBuf {
    if n == 1 {
        return path.to_path_buf();
    }
    let stem = path
        .file_stem()
        .map(|s| s.to_string_lossy())
        .unwrap_or_default();
    let name = match path.extension() {
        Some(e) => format!("{stem}.alpha-{k}.{}", e.to_string_lossy()),
        None => format!("{stem}.alpha-{k}"),
    };
    path.with_file_name(name)
}

/// `spinball ftle`.
///
/// # Errors
/// As `spinball lyapunov`; a histogram that cannot be formed.
pub fn ftle(args: &FtleArgs) -> Result<(), CliError> {
    let l = &args.lyapunov;
    let estimates = match run_ensembles(&l.run, &l.out, &l.checkpoint)? {
        Outcome::Finished(e) => e,
        Outcome::Shard => return Ok(()),
    };
    // Every file is written even if stdout failed (full, or closed by
    // `| head`); that failure is the command's once they are.
    let shown = l.out.show(&estimates);
    l.out.write_files(&estimates)?;
    let n = estimates.len();
    for (k, e) in estimates.iter().enumerate() {
        if let Some(path) = &args.per_ic {
            let csv = trajectories_csv(std::slice::from_ref(e)).map_err(CliError::failed)?;
            write_text(&nth(path, k, n), &csv)?;
        }
        if let Some(path) = &args.histogram {
            let hist = e
                .ftle()
                .and_then(|d| d.auto_histogram(args.bins))
                .map_err(CliError::usage)?;
            write_text(&nth(path, k, n), &hist.to_csv())?;
        }
    }
    shown
}
