//! `spinball sweep`: λ(α) on one table, the machine interface for scripts
//! and other tools.
//!
//! ```text
//! spinball sweep --table stadium:a=1 --alphas 0,0.5,1 --ics 1000 \
//!     --collisions 10000 --method fd --seed 1 --json sweep.json \
//!     [--sampler paper|microcanonical] [--threads T] [--extended]
//! ```
//!
//! Everything that changes a result is given explicitly (no modes, no
//! defaults). For every α it runs an ensemble of `--ics` initial conditions
//! (indices `0..N` of seed `--seed`) for `--collisions` collisions each,
//! prints a row of a table, and (re)writes the JSON document
//! ([`SweepDocument`], pretty-printed) after each point so a long sweep
//! leaves its finished points behind.
//!
//! Each point's error budget ([`ErrorBudget::for_estimate`]) adds to its SEM
//! the finite-time bias, fitted on its first 64 initial conditions read at
//! T/8, T/4, T/2 and T, and for finite differences the method bias against
//! a tangent run of those initial conditions; a second table prints it with
//! the stop reason. A point whose budget cannot be measured is written
//! without one (the reason on stderr).
//!
//! SPEC is `circle`, `rectangle:L=1,H=1`, `stadium:a=1` or `sinai:L=2,R=1`
//! (any values). α must lie in [0, 1] unless `--extended` is given. Bad
//! arguments and an unwritable `--json` path exit with code 2, a failure
//! while computing with code 1. Results are bitwise the same for any
//! `--threads`.

use std::io::Write;
use std::path::{Path, PathBuf};

use clap::Args;
use spinball_analysis::estimators::Method;
use spinball_analysis::precision::ErrorBudget;
use spinball_analysis::report::{BudgetRow, Document, SweepDocument};
use spinball_analysis::run::{Ensemble, Threads};
use spinball_core::{Sampler, SpinLaw, SpinLawError};
use spinball_geometry::Table;

use crate::error::CliError;
use crate::estimator_args::{EstimatorArgs, run_multilevel, write_multilevel};

use crate::documents::write_document;
use crate::files::check_writable;
use crate::stdout::print;

/// Initial conditions each point's bias estimate is fitted on.
const BIAS_ICS: u64 = 64;

/// The arguments of `spinball sweep`.
#[derive(Debug, Clone, Args)]
pub struct SweepArgs {
    /// The table: `circle`, `rectangle:L=1,H=1`, `stadium:a=1` or
    /// `sinai:L=2,R=1` (any values).
    #[arg(long, value_name = "SPEC")]
    pub table: Table,
    /// Spin parameters α, comma-separated (in [0, 1] unless --extended).
    #[arg(
        long,
        value_name = "LIST",
        value_delimiter = ',',
        required = true,
        allow_negative_numbers = true
    )]
    pub alphas: Vec<f64>,
    /// Initial conditions per α (at least 2).
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u64).range(2..))]
    pub ics: u64,
    /// Collisions per initial condition (at least 1).
    #[arg(long, value_name = "M", value_parser = clap::value_parser!(u64).range(1..))]
    pub collisions: u64,
    /// `fd` (the paper's finite differences, δ0 = 1e-7) or `tangent`
    /// (exact).
    #[arg(long, value_name = "fd|tangent")]
    pub method: Method,
    /// Seed of the initial conditions.
    #[arg(long, value_name = "S")]
    pub seed: u64,
    /// Where to write the results (rewritten after every α).
    #[arg(long, value_name = "PATH")]
    pub json: PathBuf,
    /// How initial conditions are drawn: `paper` or `microcanonical`.
    #[arg(long, value_name = "paper|microcanonical", default_value = "paper")]
    pub sampler: Sampler,
    /// Worker threads (default: all cores); results do not depend on it.
    #[arg(long, value_name = "T", value_parser = crate::run_args::parse_threads)]
    pub threads: Option<usize>,
    /// Allow α > 1 (the mathematical extension towards no-slip).
    #[arg(long)]
    pub extended: bool,
    #[command(flatten)]
    pub estimator: EstimatorArgs,
}

impl SweepArgs {
    /// One spin law per α, in order.
    ///
    /// # Errors
    /// [`CliError::Usage`] for an α the law refuses.
    fn laws(&self) -> Result<Vec<SpinLaw>, CliError> {
        self.alphas
            .iter()
            .map(|&alpha| {
                let law = if self.extended {
                    SpinLaw::extended(alpha)
                } else {
                    SpinLaw::new(alpha)
                };
                law.map_err(|e| match e {
                    SpinLawError::Unphysical(_) => CliError::Usage(format!(
                        "--alphas: alpha = {alpha} is outside [0, 1]; pass --extended to allow it"
                    )),
                    e => CliError::Usage(format!("--alphas: alpha = {alpha}: {e}")),
                })
            })
            .collect()
    }

    /// The ensemble of one point: the table, `law` and every other setting.
    fn ensemble(&self, law: SpinLaw) -> Ensemble {
        let threads = self.threads.map_or(Threads::All, Threads::Fixed);
        Ensemble::new(self.table, law)
            .with_sampler(self.sampler)
            .with_seed(self.seed)
            .with_ics(self.ics)
            .with_collisions(self.collisions)
            .with_method(self.method)
            .with_threads(threads)
    }
}

/// Write `doc` to `path` as a `spinball.sweep` document, pretty-printed,
/// replacing it whole (a path that exists and is not a regular file is
/// refused).
fn write_sweep(path: &Path, doc: &SweepDocument) -> Result<(), CliError> {
    write_document(path, &Document::Sweep(doc.clone()), true)
}

/// Run `spinball sweep`.
///
/// # Errors
/// [`CliError::Usage`] for an α out of range or an unwritable `--json`
/// path (checked before any computing), [`CliError::Failed`] for a failed
/// run or a write that fails later.
pub fn sweep(args: &SweepArgs) -> Result<(), CliError> {
    let laws = args.laws()?;
    // Fail on an unwritable path now, not after the computation.
    check_writable("json", &args.json)?;
    if let Some(options) = args.estimator.multilevel()? {
        if args.estimator.allocation.is_some() {
            return Err(CliError::Usage(
                "--allocation is for one alpha: run it with spinball lyapunov".into(),
            ));
        }
        let mut points = Vec::new();
        for law in laws {
            let point = run_multilevel(&args.ensemble(law), &options)?;
            print(&format!("alpha = {}\n{}\n", point.alpha, point.estimate))?;
            points.push(point);
            write_multilevel(&args.json, &points)?;
        }
        return print(&format!("wrote {}\n", args.json.display()));
    }
    let mut doc = SweepDocument::new(&args.table, args.method, args.sampler, args.seed);
    write_sweep(&args.json, &doc).map_err(|e| CliError::Usage(format!("--json: {e}")))?;
    // The rows on stdout; the document is written whatever becomes of
    // them (a full or closed stdout is reported after the run).
    let mut shown: Result<(), CliError> = Ok(());
    let mut say = |text: String| {
        if shown.is_ok() {
            shown = print(&text);
        }
    };
    say(format!(
        "{} | {} | sampler {} | seed {} | {} ICs x {} collisions\n",
        args.table,
        args.method.name(),
        args.sampler,
        args.seed,
        args.ics,
        args.collisions
    ));
    say(format!(
        "{:>8} {:>10} {:>9} {:>10} {:>7} {:>9}\n",
        "alpha", "lambda", "SEM", "median", "f_ch", "time/s"
    ));
    let mut budgets = Vec::new();
    for law in laws {
        let ensemble = args.ensemble(law);
        let est = ensemble
            .run()
            .map_err(|e| CliError::Failed(format!("alpha = {}: {e}", law.alpha())))?;
        say(format!(
            "{:>8} {:>10.5} {:>9.5} {:>10.5} {:>7.3} {:>9.2}\n",
            est.alpha(),
            est.mean(),
            est.sem(),
            est.median(),
            est.chaotic_fraction(),
            est.wall_time_s()
        ));
        // The budget needs a bias fit (at least 8 collisions); a point
        // without one is still written, with the reason on stderr.
        match ErrorBudget::for_estimate(&ensemble, &est, BIAS_ICS) {
            Ok(budget) => {
                let row = BudgetRow::new(&est, &budget);
                budgets.push(row.table_line());
                doc.push_with_budget(&est, row);
            }
            Err(e) => {
                // A warning: a full stderr must not stop the run.
                let _ = writeln!(
                    std::io::stderr(),
                    "spinball sweep: alpha = {}: no error budget: {e}",
                    law.alpha()
                );
                doc.push(&est);
            }
        }
        write_sweep(&args.json, &doc)?;
    }
    say(format!(
        "\nerror budget (bias from the first {BIAS_ICS} ICs):\n"
    ));
    let mut table = BudgetRow::table_header() + "\n";
    for line in budgets {
        table += &(line + "\n");
    }
    say(format!("{table}wrote {}\n", args.json.display()));
    shown
}
