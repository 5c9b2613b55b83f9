//! What the phase-space commands (`section`, `ftle-map`, `kac`) share: one
//! table at one α, a seed and threads (their outputs are the `OutputArgs`
//! of every command).

use clap::Args;
use spinball_analysis::run::{RunDefaults, Threads};
use spinball_core::{SpinLaw, SpinLawError};
use spinball_geometry::Built;

use crate::error::CliError;
use crate::run_args::parse_threads;
use crate::table_arg::read_table;

/// One table at one α: what every command on a single scene takes.
#[derive(Debug, Clone, Args)]
pub struct SceneArgs {
    /// The table: a built-in spec (`stadium:a=1`, `sinai:L=2,R=1`, `circle`,
    /// `rectangle:L=1,H=1`) or a table file (`.toml` or `.json`).
    #[arg(long)]
    pub table: String,
    /// Spin parameter α = I/(m r²), in [0, 1] unless --extended.
    #[arg(long, allow_negative_numbers = true)]
    pub alpha: f64,
    /// Allow α > 1 (the mathematical extension of the law).
    #[arg(long)]
    pub extended: bool,
}

impl SceneArgs {
    /// The table and the spin law.
    ///
    /// # Errors
    /// [`CliError::Usage`] for a table or α that cannot work.
    pub fn setup(&self) -> Result<(Built, SpinLaw), CliError> {
        let table = read_table(&self.table)?;
        let law = if self.extended {
            SpinLaw::extended(self.alpha)
        } else {
            SpinLaw::new(self.alpha)
        }
        .map_err(|e| match e {
            SpinLawError::Unphysical(_) => CliError::Usage(format!(
                "--alpha {}: outside [0, 1]; pass --extended to allow it",
                self.alpha
            )),
            e => CliError::Usage(format!("--alpha {}: {e}", self.alpha)),
        })?;
        Ok((table, law))
    }
}

/// One table at one α, a seed and threads.
#[derive(Debug, Clone, Args)]
pub struct PhaseArgs {
    /// The table and α.
    #[command(flatten)]
    pub scene: SceneArgs,
    /// Seed (of the starts, or of the tangent directions of a map).
    #[arg(long, default_value_t = RunDefaults::SEED)]
    pub seed: u64,
    /// Worker threads, 1..=1024 (default: all cores); results do not
    /// depend on it.
    #[arg(long, value_name = "T", value_parser = parse_threads)]
    pub threads: Option<usize>,
}

impl PhaseArgs {
    /// The table, the spin law and the threads.
    ///
    /// # Errors
    /// [`CliError::Usage`] for a table or α that cannot work.
    pub fn setup(&self) -> Result<(Built, SpinLaw, Threads), CliError> {
        let (table, law) = self.scene.setup()?;
        let threads = self.threads.map_or(RunDefaults::THREADS, Threads::Fixed);
        Ok((table, law, threads))
    }
}

/// Rows of numbers as CSV under `header` (shortest round-trip form; `NaN`
/// for a missing value).
pub fn csv_rows<const N: usize>(header: &[&str; N], rows: &[[f64; N]]) -> String {
    let mut out = header.join(",");
    out.push('\n');
    for r in rows {
        let cells: Vec<String> = r.iter().map(f64::to_string).collect();
        out.push_str(&cells.join(","));
        out.push('\n');
    }
    out
}

/// A `LO,HI` pair of numbers with `LO < HI`, for `--flag`.
///
/// # Errors
/// The form that works, for anything else.
pub fn parse_range(s: &str) -> Result<(f64, f64), String> {
    let bad = || format!("`{s}` is not a range: expected LO,HI with finite LO < HI, e.g. 0,2");
    let (lo, hi) = s.split_once(',').ok_or_else(bad)?;
    let lo: f64 = lo.trim().parse().map_err(|_| bad())?;
    let hi: f64 = hi.trim().parse().map_err(|_| bad())?;
    if lo.is_finite() && hi.is_finite() && lo < hi {
        Ok((lo, hi))
    } else {
        Err(bad())
    }
}
