//! The command line every figure example shares:
//! `--out DIR`, `--quick`, `--paper`, `--seed N`, `--help`.
//!
//! A figure has three sizes: `--quick` (seconds, what CI runs), the default
//! (statistics that finish in minutes on a laptop, with error bars) and
//! `--paper` (the paper's sizes). [`FigureArgs::pick`] chooses a value per
//! mode so the examples stay thin.
//!
//! ```
//! use spinball_plot::cli::{FigureArgs, Mode, Parsed};
//! let parsed = FigureArgs::try_parse_from("fig_energy", ["--quick", "--out", "/tmp/e"]).unwrap();
//! let Parsed::Run(args) = parsed else { panic!() };
//! assert_eq!(args.mode, Mode::Quick);
//! assert_eq!(args.pick(500, 5_000, 5_000), 500);
//! ```

use std::fmt;
use std::path::{Path, PathBuf};

use thiserror::Error;

use crate::error::PlotError;

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

/// The arguments of a figure example.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct FigureArgs {
    /// Output directory (default `out/<name>`).
    pub out: PathBuf,
    /// Run size.
    pub mode: Mode,
    /// Seed of the initial conditions (default 2024).
    pub seed: u64,
}

/// The default seed.
pub const DEFAULT_SEED: u64 = 2024;

/// What the command line asked for.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Parsed {
    /// Run the figure with these arguments.
    Run(FigureArgs),
    /// Print the usage and stop (`--help`).
    Help,
}

/// A command line that cannot be read.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
#[non_exhaustive]
pub enum ArgError {
    /// An option that is not one of ours.
    #[error("unknown argument `{0}`")]
    Unknown(String),
    /// An option that needs a value came last.
    #[error("`{0}` needs a value")]
    MissingValue(&'static str),
    /// The seed is not a non-negative integer.
    #[error("`--seed {0}`: not a non-negative integer")]
    BadSeed(String),
    /// `--quick` and `--paper` together.
    #[error("`--quick` and `--paper` exclude each other")]
    ConflictingModes,
    /// An empty output directory.
    #[error("`--out` needs a non-empty directory name")]
    EmptyOut,
}

impl FigureArgs {
    /// Read the arguments from `args` (without the program name) for the
    /// figure `name`.
    ///
    /// # Errors
    /// An [`ArgError`] saying what is wrong.
    pub fn try_parse_from<I, S>(name: &str, args: I) -> Result<Parsed, ArgError>
    where
        I: IntoIterator<Item = S>,
        S: Into<String>,
    {
        let mut out = None;
        let mut seed = DEFAULT_SEED;
        let (mut quick, mut paper) = (false, false);
        let mut it = args.into_iter().map(Into::into);
        while let Some(arg) = it.next() {
            let (key, inline) = match arg.split_once('=') {
                Some((k, v)) if k.starts_with("--") => (k.to_string(), Some(v.to_string())),
                _ => (arg.clone(), None),
            };
            let mut value = |flag: &'static str| {
                inline
                    .clone()
                    .or_else(|| it.next())
                    .ok_or(ArgError::MissingValue(flag))
            };
            match key.as_str() {
                "-h" | "--help" => return Ok(Parsed::Help),
                "--quick" if inline.is_none() => quick = true,
                "--paper" if inline.is_none() => paper = true,
                "--out" | "-o" => {
                    let v = value("--out")?;
                    if v.is_empty() {
                        return Err(ArgError::EmptyOut);
                    }
                    out = Some(PathBuf::from(v));
                }
                "--seed" => {
                    let v = value("--seed")?;
                    seed = v.trim().parse().map_err(|_| ArgError::BadSeed(v.clone()))?;
                }
                _ => return Err(ArgError::Unknown(arg)),
            }
        }
        if quick && paper {
            return Err(ArgError::ConflictingModes);
        }
        let mode = if quick {
            Mode::Quick
        } else if paper {
            Mode::Paper
        } else {
            Mode::Default
        };
        Ok(Parsed::Run(FigureArgs {
            out: out.unwrap_or_else(|| Path::new("out").join(name)),
            mode,
            seed,
        }))
    }

    /// Read the process's arguments; on `--help` print the usage and exit 0,
    /// on a bad argument print the error and the usage to stderr and exit 2.
    /// `about` is one line saying what the figure shows.
    pub fn parse_or_exit(name: &str, about: &str) -> FigureArgs {
        match Self::try_parse_from(name, std::env::args().skip(1)) {
            Ok(Parsed::Run(args)) => args,
            Ok(Parsed::Help) => {
                println!("{}", usage(name, about));
                std::process::exit(0);
            }
            Err(e) => {
                eprintln!("{name}: {e}\n\n{}", usage(name, about));
                std::process::exit(2);
            }
        }
    }

    /// `quick`, `default` or `paper` by the mode.
    pub fn pick<T>(&self, quick: T, default: T, paper: T) -> T {
        match self.mode {
            Mode::Quick => quick,
            Mode::Default => default,
            Mode::Paper => paper,
        }
    }

    /// The path of `file` in the output directory, creating the directory.
    ///
    /// # Errors
    /// [`PlotError::Io`] if the directory cannot be created.
    pub fn output(&self, file: &str) -> Result<PathBuf, PlotError> {
        std::fs::create_dir_all(&self.out).map_err(|source| PlotError::Io {
            path: self.out.clone(),
            source,
        })?;
        Ok(self.out.join(file))
    }
}

/// The usage text of a figure example.
pub fn usage(name: &str, about: &str) -> String {
    format!(
        "{about}\n\n\
         usage: cargo run --release --example {name} -- [--quick | --paper] [--out DIR] [--seed N]\n\n\
         options:\n  \
         --out DIR   where to write PNG and CSV/JSON (default out/{name})\n  \
         --quick     small run, seconds (what CI runs)\n  \
         --paper     the paper's sizes\n  \
         --seed N    seed of the initial conditions (default {DEFAULT_SEED})\n  \
         -h, --help  this text"
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    fn run(args: &[&str]) -> Result<FigureArgs, ArgError> {
        match FigureArgs::try_parse_from("fig", args.iter().copied())? {
            Parsed::Run(a) => Ok(a),
            Parsed::Help => panic!("help"),
        }
    }

    #[test]
    fn defaults() {
        let a = run(&[]).unwrap();
        assert_eq!(a.out, Path::new("out/fig"));
        assert_eq!(a.mode, Mode::Default);
        assert_eq!(a.seed, DEFAULT_SEED);
    }

    #[test]
    fn all_options() {
        let a = run(&["--paper", "--out=/tmp/x", "--seed", "7"]).unwrap();
        assert_eq!(
            (a.mode, a.out, a.seed),
            (Mode::Paper, PathBuf::from("/tmp/x"), 7)
        );
        assert_eq!(run(&["--quick", "-o", "d"]).unwrap().mode, Mode::Quick);
        assert_eq!(
            FigureArgs::try_parse_from("fig", ["--help"]).unwrap(),
            Parsed::Help
        );
    }

    #[test]
    fn errors() {
        assert_eq!(run(&["--fast"]), Err(ArgError::Unknown("--fast".into())));
        assert_eq!(run(&["--out"]), Err(ArgError::MissingValue("--out")));
        assert_eq!(run(&["--seed", "-1"]), Err(ArgError::BadSeed("-1".into())));
        assert_eq!(
            run(&["--quick", "--paper"]),
            Err(ArgError::ConflictingModes)
        );
        assert_eq!(run(&["--out="]), Err(ArgError::EmptyOut));
        assert_eq!(
            run(&["--quick=1"]),
            Err(ArgError::Unknown("--quick=1".into()))
        );
    }
}
