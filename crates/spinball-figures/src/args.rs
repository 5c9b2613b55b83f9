//! The arguments every figure example shares:
//! `--out DIR`, `--quick`, `--paper`, `--seed N`, `--threads N`, `--help`,
//! plus any options of its own, read by clap.
//!
//! A figure has three sizes: `--quick` (seconds, what CI runs), the default
//! (statistics that finish in minutes on a laptop, with error bars) and
//! `--paper` (the paper's sizes). [`FigureArgs::pick`] chooses a value per
//! mode so the examples stay thin.
//!
//! An example's own options are a `#[derive(clap::Args)]` struct, read
//! beside the shared ones ([`FigureArgs::try_parse_with`],
//! [`run_figure_with`](crate::run_figure_with)); an option whose default
//! depends on the mode is an `Option` resolved with [`FigureArgs::pick`].
//!
//! ```
//! use spinball_figures::{FigureArgs, Mode};
//! let args = FigureArgs::try_parse_from("fig_energy", "", ["--quick", "--out", "/tmp/e"]).unwrap();
//! assert_eq!(args.mode, Mode::Quick);
//! assert_eq!(args.pick(500, 5_000, 5_000), 500);
//!
//! // An example's own options come after the shared ones.
//! #[derive(Debug, clap::Args)]
//! struct Own {
//!     /// spin parameter
//!     #[arg(long, default_value_t = 0.5)]
//!     alpha: f64,
//! }
//! let (args, own) = FigureArgs::try_parse_with::<Own, _, _>("traj", "", ["--alpha", "0.3"]).unwrap();
//! assert_eq!((args.seed, own.alpha), (2024, 0.3));
//! ```

use std::fmt;
use std::num::NonZeroUsize;
use std::path::{Path, PathBuf};

use clap::{Args, CommandFactory, FromArgMatches, Parser};
use spinball_analysis::run::Threads;

use crate::error::FigureError;

/// How large a run is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Mode {
    /// Seconds: smallest statistics that still draw the figure (CI).
    Quick,
    /// Minutes on two cores, error bars shown.
    #[default]
    Default,
    /// The paper's sizes.
    Paper,
}

impl fmt::Display for Mode {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Mode::Quick => "quick",
            Mode::Default => "default",
            Mode::Paper => "paper",
        })
    }
}

/// The default seed.
pub const DEFAULT_SEED: u64 = 2024;

/// The options every figure example takes, as clap reads them.
#[derive(Debug, Clone, Args)]
struct SharedOptions {
    /// small run, seconds (what CI runs)
    #[arg(long, conflicts_with = "paper")]
    quick: bool,
    /// the paper's sizes
    #[arg(long)]
    paper: bool,
    /// where to write PNG and CSV/JSON (default out/<example>)
    #[arg(long, short, value_name = "DIR")]
    out: Option<PathBuf>,
    /// seed of the initial conditions
    #[arg(long, value_name = "N", default_value_t = DEFAULT_SEED)]
    seed: u64,
    /// worker threads (default: all cores); results do not depend on it
    #[arg(long, value_name = "N")]
    threads: Option<NonZeroUsize>,
}

// A command line: the shared options and the example's own. (Not a doc
// comment: clap would show it as the about line.)
#[derive(Debug, Parser)]
struct Line<E: Args> {
    #[command(flatten)]
    shared: SharedOptions,
    #[command(flatten)]
    own: E,
}

/// No options beyond the shared ones.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Args)]
pub struct NoOptions {}

/// The arguments of a figure example.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct FigureArgs {
    /// Output directory (default `out/<name>`).
    pub out: PathBuf,
    /// Run size.
    pub mode: Mode,
    /// Seed of the initial conditions (default 2024).
    pub seed: u64,
    /// Worker threads (default all cores); results do not depend on it.
    pub threads: Threads,
}

impl FigureArgs {
    /// Read the arguments from `args` (without the program name) for the
    /// figure `name`; `about` is one line for `--help`.
    ///
    /// # Errors
    /// The [`clap::Error`] saying what is wrong (or holding the help text,
    /// for `--help`; [`clap::Error::exit`] prints either).
    pub fn try_parse_from<I, S>(name: &str, about: &str, args: I) -> Result<FigureArgs, clap::Error>
    where
        I: IntoIterator<Item = S>,
        S: Into<std::ffi::OsString> + Clone,
    {
        Self::try_parse_with::<NoOptions, I, S>(name, about, args).map(|(a, _)| a)
    }

    /// As [`try_parse_from`](Self::try_parse_from), also reading the
    /// example's own options `E`.
    ///
    /// # Errors
    /// As [`try_parse_from`](Self::try_parse_from).
    pub fn try_parse_with<E, I, S>(
        name: &str,
        about: &str,
        args: I,
    ) -> Result<(FigureArgs, E), clap::Error>
    where
        E: Args + FromArgMatches,
        I: IntoIterator<Item = S>,
        S: Into<std::ffi::OsString> + Clone,
    {
        let matches = command::<E>(name, about).try_get_matches_from(
            std::iter::once(name.into()).chain(args.into_iter().map(Into::into)),
        )?;
        let line = Line::<E>::from_arg_matches(&matches)?;
        let s = line.shared;
        let mode = if s.quick {
            Mode::Quick
        } else if s.paper {
            Mode::Paper
        } else {
            Mode::Default
        };
        let args = FigureArgs {
            out: s.out.unwrap_or_else(|| Path::new("out").join(name)),
            mode,
            seed: s.seed,
            threads: s.threads.map_or(Threads::All, |n| Threads::Fixed(n.get())),
        };
        Ok((args, line.own))
    }

    /// Read the process's arguments; on `--help` print the usage and exit 0,
    /// on a bad argument print the error and the usage to stderr and exit 2.
    /// `about` is one line saying what the figure shows.
    pub fn parse_or_exit(name: &str, about: &str) -> FigureArgs {
        Self::parse_or_exit_with::<NoOptions>(name, about).0
    }

    /// [`parse_or_exit`](Self::parse_or_exit) with the example's own
    /// options `E`.
    pub fn parse_or_exit_with<E: Args + FromArgMatches>(
        name: &str,
        about: &str,
    ) -> (FigureArgs, E) {
        Self::try_parse_with(name, about, std::env::args_os().skip(1)).unwrap_or_else(|e| e.exit())
    }

    /// `quick`, `default` or `paper` by the mode.
    pub fn pick<T>(&self, quick: T, default: T, paper: T) -> T {
        match self.mode {
            Mode::Quick => quick,
            Mode::Default => default,
            Mode::Paper => paper,
        }
    }

    /// The number of worker threads `threads` means on this machine.
    pub fn thread_count(&self) -> usize {
        self.threads.count()
    }

    /// The path of `file` in the output directory, creating the directory.
    ///
    /// # Errors
    /// [`FigureError::Io`] if the directory cannot be created.
    pub fn output(&self, file: &str) -> Result<PathBuf, FigureError> {
        std::fs::create_dir_all(&self.out).map_err(|source| FigureError::Io {
            path: self.out.clone(),
            source,
        })?;
        Ok(self.out.join(file))
    }
}

/// The clap command of the figure example `name` with its own options `E`.
fn command<E: Args>(name: &str, about: &str) -> clap::Command {
    // The about line is `about`, never a doc comment of the option structs.
    let command = Line::<E>::command()
        .name(name.to_string())
        .bin_name(format!("cargo run --release --example {name} --"))
        .long_about(None::<&str>);
    if about.is_empty() {
        command.about(None::<&str>)
    } else {
        command.about(about.to_string())
    }
}

/// The usage text of a figure example with its own options `E`.
pub fn usage<E: Args>(name: &str, about: &str) -> String {
    command::<E>(name, about).render_help().to_string()
}

#[cfg(test)]
mod tests {
    use clap::error::ErrorKind;

    use super::*;

    fn run(args: &[&str]) -> Result<FigureArgs, clap::Error> {
        FigureArgs::try_parse_from("fig", "", args.iter().copied())
    }

    fn kind(args: &[&str]) -> ErrorKind {
        run(args).unwrap_err().kind()
    }

    #[test]
    fn defaults() {
        let a = run(&[]).unwrap();
        assert_eq!(a.out, Path::new("out/fig"));
        assert_eq!(a.mode, Mode::Default);
        assert_eq!(a.seed, DEFAULT_SEED);
        assert_eq!(a.threads, Threads::All);
    }

    #[test]
    fn all_options() {
        let a = run(&["--paper", "--out=/tmp/x", "--seed", "7", "--threads", "3"]).unwrap();
        assert_eq!(
            (a.mode, a.out, a.seed, a.threads),
            (Mode::Paper, PathBuf::from("/tmp/x"), 7, Threads::Fixed(3))
        );
        assert_eq!(run(&["--quick", "-o", "d"]).unwrap().mode, Mode::Quick);
        assert_eq!(kind(&["--help"]), ErrorKind::DisplayHelp);
    }

    #[test]
    fn errors() {
        assert_eq!(kind(&["--fast"]), ErrorKind::UnknownArgument);
        assert_eq!(kind(&["--quick", "--paper"]), ErrorKind::ArgumentConflict);
        // Every bad command line is a usage error: message, exit code 2.
        for bad in [
            &["--fast"][..],
            &["--out"],
            &["--out="],
            &["--seed", "-1"],
            &["--seed", "x"],
            &["--threads", "0"],
            &["--quick", "--paper"],
            &["--quick=1"],
            &["--quick", "--quick"],
        ] {
            let e = run(bad).unwrap_err();
            assert_eq!(e.exit_code(), 2, "{bad:?}: {e}");
        }
    }

    #[derive(Debug, Args)]
    struct Own {
        /// spin parameter
        #[arg(long, value_name = "A", allow_negative_numbers = true)]
        alpha: Option<f64>,
    }

    #[test]
    fn own_options_and_usage() {
        let (a, own) =
            FigureArgs::try_parse_with::<Own, _, _>("traj", "", ["--quick", "--alpha=-0.25"])
                .unwrap();
        assert_eq!((a.mode, own.alpha), (Mode::Quick, Some(-0.25)));
        assert!(run(&["--alpha", "1"]).is_err());
        let u = usage::<Own>("traj", "Trajectories.");
        assert!(u.starts_with("Trajectories.\n"), "{u}");
        assert!(!usage::<Own>("traj", "").contains("command line"), "{u}");
        assert!(u.contains("cargo run --release --example traj --"), "{u}");
        for option in [
            "--threads <N>",
            "--alpha <A>",
            "-o, --out <DIR>",
            "-h, --help",
        ] {
            assert!(u.contains(option), "{option} missing from\n{u}");
        }
    }
}
