//! What the open-table commands (`escape`, `diffuse`) share: one table at
//! one α, the initial conditions and how they are drawn, and the progress
//! bar and exit codes of a run.

use clap::Args;
use indicatif::ProgressBar;
use spinball_analysis::AnalysisError;
use spinball_analysis::escape::EscapeError;
use spinball_analysis::report::OpenRun;
use spinball_analysis::run::RunDefaults;
use spinball_analysis::transport::TransportError;
use spinball_core::Billiard;
use spinball_geometry::Built;

use crate::error::CliError;
use crate::phase_args::PhaseArgs;
use crate::run_args::SamplerArg;

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

/// A progress callback driving `bar` (`done` of `of` initial conditions).
pub fn progress(bar: &ProgressBar) -> impl FnMut(u64, u64) + '_ {
    |done, of| {
        bar.set_length(of);
        bar.set_position(done);
    }
}

/// The exit code of a failed open-table run: a table or option that cannot
/// work is bad usage (2), anything else a failed run (1).
pub fn open_error(e: AnalysisError) -> CliError {
    match e {
        AnalysisError::InvalidOption { .. }
        | AnalysisError::Escape(EscapeError::NoHole | EscapeError::InvalidOption { .. })
        | AnalysisError::Transport(TransportError::NotPeriodic | TransportError::UnknownHorizon) => {
            CliError::usage(e)
        }
        e => CliError::failed(e),
    }
}
