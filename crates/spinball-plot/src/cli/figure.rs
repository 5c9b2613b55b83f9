//! The arguments every figure example shares:
//! `--out DIR`, `--quick`, `--paper`, `--seed N`, `--threads N`, `--help`,
//! plus any options of its own.
//!
//! A figure has three sizes: `--quick` (seconds, what CI runs), the default
//! (statistics that finish in minutes on a laptop, with error bars) and
//! `--paper` (the paper's sizes). [`FigureArgs::pick`] chooses a value per
//! mode so the examples stay thin.
//!
//! ```
//! use spinball_plot::cli::{FigureArgs, Mode, Opt, Parsed};
//! let parsed = FigureArgs::try_parse_from("fig_energy", ["--quick", "--out", "/tmp/e"]).unwrap();
//! let Parsed::Run(args) = parsed else { panic!() };
//! assert_eq!(args.mode, Mode::Quick);
//! assert_eq!(args.pick(500, 5_000, 5_000), 500);
//!
//! // An example's own options come after the shared ones.
//! const ALPHA: Opt = Opt::value("alpha", "A", "spin parameter (default 0.5)");
//! let Parsed::Run(args) = FigureArgs::try_parse_with("traj", &[ALPHA], ["--alpha", "0.3"]).unwrap()
//! else { panic!() };
//! assert_eq!(args.extra.get_or("alpha", 0.5), Ok(0.3));
//! ```

use std::fmt;
use std::path::{Path, PathBuf};

use spinball_analysis::run::Threads;

use super::options::{ArgError, Matches, Opt, Parsed, exit_on_error, parse_options, usage_text};
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

/// The default seed.
pub const DEFAULT_SEED: u64 = 2024;

/// The options every figure example takes.
pub const FIGURE_OPTIONS: [Opt; 5] = [
    Opt::flag("quick", "small run, seconds (what CI runs)"),
    Opt::flag("paper", "the paper's sizes"),
    Opt::value(
        "out",
        "DIR",
        "where to write PNG and CSV/JSON (default out/<example>)",
    )
    .short('o'),
    Opt::value("seed", "N", "seed of the initial conditions (default 2024)"),
    Opt::value(
        "threads",
        "N",
        "worker threads (default: all cores); results do not depend on it",
    ),
];

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
    /// The example's own options (see [`FigureArgs::try_parse_with`]).
    pub extra: Matches,
}

impl FigureArgs {
    /// Read the arguments from `args` (without the program name) for the
    /// figure `name`.
    ///
    /// # Errors
    /// An [`ArgError`] saying what is wrong.
    pub fn try_parse_from<I, S>(name: &str, args: I) -> Result<Parsed<FigureArgs>, ArgError>
    where
        I: IntoIterator<Item = S>,
        S: Into<String>,
    {
        Self::try_parse_with(name, &[], args)
    }

    /// As [`try_parse_from`](Self::try_parse_from), also accepting the
    /// example's own options `extra` (found in [`FigureArgs::extra`]).
    ///
    /// # Errors
    /// An [`ArgError`] saying what is wrong.
    pub fn try_parse_with<I, S>(
        name: &str,
        extra: &[Opt],
        args: I,
    ) -> Result<Parsed<FigureArgs>, ArgError>
    where
        I: IntoIterator<Item = S>,
        S: Into<String>,
    {
        let options: Vec<Opt> = FIGURE_OPTIONS.iter().chain(extra).copied().collect();
        let m = match parse_options(&options, args)? {
            Parsed::Run(m) => m,
            Parsed::Help => return Ok(Parsed::Help),
        };
        if m.flag("quick") && m.flag("paper") {
            return Err(ArgError::Conflict("quick", "paper"));
        }
        let mode = if m.flag("quick") {
            Mode::Quick
        } else if m.flag("paper") {
            Mode::Paper
        } else {
            Mode::Default
        };
        let out = match m.value("out") {
            Some("") => return Err(ArgError::invalid("out", "", "needs a directory name")),
            Some(dir) => PathBuf::from(dir),
            None => Path::new("out").join(name),
        };
        let seed = m
            .get::<u64>("seed")
            .map_err(|_| not_integer("seed", &m, "non-negative"))?
            .unwrap_or(DEFAULT_SEED);
        let threads = match m.get::<usize>("threads") {
            Ok(None) => Threads::All,
            Ok(Some(n)) if n >= 1 => Threads::Fixed(n),
            _ => return Err(not_integer("threads", &m, "positive")),
        };
        Ok(Parsed::Run(FigureArgs {
            out,
            mode,
            seed,
            threads,
            extra: m,
        }))
    }

    /// Read the process's arguments; on `--help` print the usage and exit 0,
    /// on a bad argument print the error and the usage to stderr and exit 2.
    /// `about` is one line saying what the figure shows.
    pub fn parse_or_exit(name: &str, about: &str) -> FigureArgs {
        Self::parse_or_exit_with(name, about, &[])
    }

    /// [`parse_or_exit`](Self::parse_or_exit) with the example's own
    /// options `extra`.
    pub fn parse_or_exit_with(name: &str, about: &str, extra: &[Opt]) -> FigureArgs {
        let parsed = Self::try_parse_with(name, extra, std::env::args().skip(1));
        exit_on_error(name, &usage_with(name, about, extra), parsed)
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
    /// [`PlotError::Io`] if the directory cannot be created.
    pub fn output(&self, file: &str) -> Result<PathBuf, PlotError> {
        std::fs::create_dir_all(&self.out).map_err(|source| PlotError::Io {
            path: self.out.clone(),
            source,
        })?;
        Ok(self.out.join(file))
    }
}

fn not_integer(option: &'static str, m: &Matches, kind: &str) -> ArgError {
    ArgError::invalid(
        option,
        m.value(option).unwrap_or_default(),
        format!("not a {kind} integer"),
    )
}

/// The usage text of a figure example.
pub fn usage(name: &str, about: &str) -> String {
    usage_with(name, about, &[])
}

/// The usage text of a figure example with its own options `extra`.
pub fn usage_with(name: &str, about: &str, extra: &[Opt]) -> String {
    let options: Vec<Opt> = FIGURE_OPTIONS.iter().chain(extra).copied().collect();
    usage_text(
        about,
        &format!("cargo run --release --example {name} --"),
        &options,
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
        assert_eq!(
            FigureArgs::try_parse_from("fig", ["--help"]).unwrap(),
            Parsed::Help
        );
    }

    #[test]
    fn errors() {
        assert_eq!(run(&["--fast"]), Err(ArgError::Unknown("--fast".into())));
        assert_eq!(run(&["--out"]), Err(ArgError::MissingValue("out")));
        assert_eq!(
            run(&["--seed", "-1"]),
            Err(ArgError::invalid(
                "seed",
                "-1",
                "not a non-negative integer"
            ))
        );
        assert_eq!(
            run(&["--threads", "0"]),
            Err(ArgError::invalid("threads", "0", "not a positive integer"))
        );
        assert_eq!(
            run(&["--quick", "--paper"]),
            Err(ArgError::Conflict("quick", "paper"))
        );
        assert!(matches!(
            run(&["--out="]),
            Err(ArgError::Invalid { option: "out", .. })
        ));
        assert_eq!(run(&["--quick=1"]), Err(ArgError::UnexpectedValue("quick")));
    }

    #[test]
    fn extra_options_and_usage() {
        let extra = [Opt::value("alpha", "A", "spin parameter")];
        let Parsed::Run(a) =
            FigureArgs::try_parse_with("traj", &extra, ["--quick", "--alpha=0.25"]).unwrap()
        else {
            panic!("help")
        };
        assert_eq!(a.extra.get::<f64>("alpha"), Ok(Some(0.25)));
        assert!(a.extra.flag("quick"));
        assert!(FigureArgs::try_parse_from("traj", ["--alpha", "1"]).is_err());
        let u = usage_with("traj", "Trajectories.", &extra);
        assert!(u.starts_with(
            "Trajectories.\n\nusage: cargo run --release --example traj -- [--quick] [--paper]"
        ));
        for option in ["--threads N", "--alpha A", "-o, --out DIR", "-h, --help"] {
            assert!(u.contains(option), "{option} missing from\n{u}");
        }
    }
}
