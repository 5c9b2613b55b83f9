//! `spinball ftle`: the distribution of finite-time exponents, per initial
//! condition and as a histogram, beside the λ estimate.

use std::path::{Path, PathBuf};

use clap::Args;
use spinball_analysis::estimators::Histogram;
use spinball_analysis::report::trajectories_csv;

use crate::commands::lyapunov::{LyapunovArgs, Outcome, run_ensembles};
use crate::error::CliError;
use crate::files::check_creatable;
use crate::output::write_text;
use crate::pictures::{check_png, ftle_png};

/// The arguments of `spinball ftle`.
#[derive(Debug, Clone, Args)]
pub struct FtleArgs {
    #[command(flatten)]
    pub lyapunov: LyapunovArgs,
    /// Write every initial condition's values as CSV
    /// (`alpha,index,exponent,per_collision,time,collisions`); with several α,
    /// one file per α, named by its value: `x.csv` becomes `x.alpha-0.5.csv`
    /// for α = 0.5.
    #[arg(long)]
    pub per_ic: Option<PathBuf>,
    /// Write the histogram of the exponents as CSV (`lo,hi,count,density`);
    /// with several α, one file per α named as `--per-ic`'s.
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

/// The file of α = `alphas[k]` for the output `path`: `path` itself if
/// there is one α, else `.alpha-VALUE` before the extension (`x.csv` →
/// `x.alpha-0.5.csv`). An α listed twice gets its position too
/// (`x.alpha-0.5-3.csv`), so no file overwrites another.
fn for_alpha(path: &Path, alphas: &[f64], k: usize) -> PathBuf {
    if alphas.len() == 1 {
        return path.to_path_buf();
    }
    let alpha = alphas[k];
    let twice = alphas
        .iter()
        .filter(|a| a.to_bits() == alpha.to_bits())
        .count()
        > 1;
    let tag = if twice {
        format!("alpha-{alpha}-{k}")
    } else {
        format!("alpha-{alpha}")
    };
    let stem = path
        .file_stem()
        .map(|s| s.to_string_lossy())
        .unwrap_or_default();
    let name = match path.extension() {
        Some(e) => format!("{stem}.{tag}.{}", e.to_string_lossy()),
        None => format!("{stem}.{tag}"),
    };
    path.with_file_name(name)
}

/// `spinball ftle`.
///
/// # Errors
/// As `spinball lyapunov`; a histogram that cannot be formed.
pub fn ftle(args: &FtleArgs) -> Result<(), CliError> {
    let l = &args.lyapunov;
    // Every file is checked before the run, so that a path that cannot be
    // written does not lose it.
    let alphas = &l.run.alpha;
    for k in 0..alphas.len() {
        if let Some(path) = &args.per_ic {
            check_creatable("per-ic", &for_alpha(path, alphas, k))?;
        }
        if let Some(path) = &args.histogram {
            check_creatable("histogram", &for_alpha(path, alphas, k))?;
        }
        if let Some(path) = &l.png {
            check_png(&for_alpha(path, alphas, k))?;
        }
    }
    if l.png.is_some() && l.run.shard().count > 1 {
        return Err(CliError::Usage(
            "--png draws a whole run: a shard has no distribution yet (draw after `spinball merge`)"
                .into(),
        ));
    }
    let estimates = match run_ensembles(&l.run, &l.out, &l.checkpoint)? {
        Outcome::Finished(e) => e,
        Outcome::Shard => return Ok(()),
    };
    // Every file is written even if stdout failed (full, or closed by
    // `| head`); that failure is the command's once they are.
    let shown = l.out.show(&estimates);
    l.out.write_files(&estimates)?;
    for (k, e) in estimates.iter().enumerate() {
        if let Some(path) = &args.per_ic {
            let csv = trajectories_csv(std::slice::from_ref(e)).map_err(CliError::failed)?;
            write_text(&for_alpha(path, alphas, k), &csv)?;
        }
        if let Some(path) = &args.histogram {
            let hist = e
                .ftle()
                .and_then(|d| d.auto_histogram(args.bins))
                .map_err(CliError::usage)?;
            write_text(&for_alpha(path, alphas, k), &hist.to_csv())?;
        }
        if let Some(path) = &l.png {
            let ftle = e.ftle().map_err(CliError::failed)?;
            ftle_png(&for_alpha(path, alphas, k), e, &ftle, args.bins)?;
        }
    }
    shown
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn per_alpha_files_are_named_by_the_value() {
        let p = Path::new("out/x.csv");
        assert_eq!(for_alpha(p, &[0.5], 0), PathBuf::from("out/x.csv"));
        let alphas = [0.0, 0.5, 1.0];
        assert_eq!(
            for_alpha(p, &alphas, 1),
            PathBuf::from("out/x.alpha-0.5.csv")
        );
        assert_eq!(for_alpha(p, &alphas, 2), PathBuf::from("out/x.alpha-1.csv"));
        assert_eq!(
            for_alpha(Path::new("x"), &alphas, 0),
            PathBuf::from("x.alpha-0")
        );
        // An α given twice: the position keeps the files apart.
        let twice = [0.5, 0.5];
        assert_ne!(for_alpha(p, &twice, 0), for_alpha(p, &twice, 1));
    }
}
