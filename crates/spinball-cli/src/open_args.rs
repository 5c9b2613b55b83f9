//! What the open-table commands (`escape`, `diffuse`) share: one table at
//! one α, the initial conditions and how they are drawn, and the progress
//! bar and exit codes of a run.

use clap::Args;
use indicatif::ProgressBar;
use spinball_analysis::AnalysisError;
use spinball_analysis::escape::EscapeError;
use spinball_analysis::report::{Document, OpenRun};
use spinball_analysis::run::{RunDefaults, Shard};
use spinball_analysis::transport::TransportError;
use spinball_core::Billiard;
use spinball_geometry::Built;

use crate::error::CliError;
use crate::output::OutputArgs;
use crate::phase_args::PhaseArgs;
use crate::run_args::SamplerArg;
use crate::watch::progress_bar;

/// One table at one α, the starts, the seed and the threads.
#[derive(Debug, Clone, Args)]
pub struct OpenArgs {
    /// The table, α, seed and threads.
    #[command(flatten)]
    pub phase: PhaseArgs,
    /// How the starts are drawn.
    #[arg(long, value_enum, default_value_t = RunDefaults::SAMPLER.into())]
    pub sampler: SamplerArg,
}

impl OpenArgs {
    /// The run over initial conditions `0..ics`.
    ///
    /// # Errors
    /// [`CliError::Usage`] for a table or α that cannot work.
    pub fn run(&self, ics: u64) -> Result<OpenRun<Built>, CliError> {
        let (table, law, threads) = self.phase.setup()?;
        Ok(OpenRun {
            billiard: Billiard::new(table, law),
            sampler: self.sampler.into(),
            seed: self.phase.seed,
            ics: 0..ics,
            threads,
        })
    }
}

/// Run one shard of an open-table command (`shard`, or the whole run)
/// behind a progress bar named `name`: `run` computes the part; a whole
/// run's part goes to `finish` (merge and write the outputs), a shard's to
/// `--json` as the document `partial` makes of it (with the words saying
/// which block it holds).
///
/// # Errors
/// [`CliError::Usage`] for a shard without `--json`, an output that cannot
/// be written, or a table or option the run refuses ([`open_error`]);
/// [`CliError::Failed`] for a run or a write that fails.
pub fn run_shard<P>(
    out: &OutputArgs,
    shard: Option<Shard>,
    name: &str,
    run: impl FnOnce(Shard, &mut dyn FnMut(u64, u64)) -> Result<P, AnalysisError>,
    finish: impl FnOnce(P) -> Result<(), CliError>,
    partial: impl FnOnce(P) -> (Document, String),
) -> Result<(), CliError> {
    let shard = shard.unwrap_or(Shard::WHOLE);
    let shard_path = out.shard_path(shard)?;
    out.check()?;
    let bar = progress_bar(out.quiet);
    bar.set_prefix(name.to_string());
    let part = run(shard, &mut progress(&bar)).map_err(open_error);
    bar.finish_and_clear();
    let part = part?;
    match shard_path {
        None => finish(part),
        Some(path) => {
            let (doc, done) = partial(part);
            out.write_shard(path, &doc, shard, &done)
        }
    }
}

/// A progress callback driving `bar` (`done` of `of` initial conditions).
fn progress(bar: &ProgressBar) -> impl FnMut(u64, u64) + '_ {
    |done, of| {
        bar.set_length(of);
        bar.set_position(done);
    }
}

/// The exit code of a failed open-table run: a table or option that cannot
/// work is bad usage (2), anything else a failed run (1).
fn open_error(e: AnalysisError) -> CliError {
    match e {
        AnalysisError::InvalidOption { .. }
        | AnalysisError::Escape(EscapeError::NoHole | EscapeError::InvalidOption { .. })
        | AnalysisError::Transport(TransportError::NotPeriodic | TransportError::UnknownHorizon) => {
            CliError::usage(e)
        }
        e => CliError::failed(e),
    }
}
