//! The arguments of the `sweep` example, the machine interface for scripts:
//! one table, a list of α, an ensemble size, a method, a seed and a JSON
//! file, all given explicitly (no modes, no defaults for what changes a
//! result), read by the same reader as the figure arguments.
//!
//! ```
//! use spinball_plot::cli::{Parsed, SweepArgs};
//! let args = "--table stadium:a=1 --alphas 0,0.5 --ics 8 --collisions 2000 \
//!             --method fd --seed 1 --json out.json";
//! let Parsed::Run(a) = SweepArgs::try_parse_from(args.split(' ')).unwrap() else { panic!() };
//! assert_eq!(a.alphas(), vec![0.0, 0.5]);
//! assert_eq!((a.ics, a.collisions, a.seed), (8, 2_000, 1));
//! ```

use std::path::PathBuf;

use spinball_analysis::estimators::Method;
use spinball_analysis::run::{Ensemble, Threads};
use spinball_core::{Sampler, SpinLaw, SpinLawError};
use spinball_geometry::Table;

use super::options::{ArgError, Matches, Opt, Parsed, exit_on_error, parse_options, usage_text};

/// The options of the `sweep` example.
pub const SWEEP_OPTIONS: [Opt; 10] = [
    Opt::value(
        "table",
        "SPEC",
        "circle | rectangle:L=1,H=1 | stadium:a=1 | sinai:L=2,R=1 (any values)",
    )
    .required(),
    Opt::value(
        "alphas",
        "LIST",
        "comma-separated spin parameters, 0 <= alpha <= 1",
    )
    .required(),
    Opt::value("ics", "N", "initial conditions per alpha (>= 2)").required(),
    Opt::value("collisions", "M", "collisions per initial condition (>= 1)").required(),
    Opt::value(
        "method",
        "fd|tangent",
        "fd (the paper's finite differences, delta0 = 1e-7) or tangent (exact)",
    )
    .required(),
    Opt::value(
        "seed",
        "S",
        "seed of the initial conditions (unsigned integer)",
    )
    .required(),
    Opt::value("json", "PATH", "where to write the results").required(),
    Opt::value(
        "sampler",
        "paper|microcanonical",
        "initial conditions: paper (default) or microcanonical",
    ),
    Opt::value(
        "threads",
        "T",
        "worker threads (default: all cores); results do not depend on it",
    ),
    Opt::flag(
        "extended",
        "allow alpha > 1 (mathematical extension towards no-slip)",
    ),
];

/// The `sweep` example's command line, read and checked.
#[derive(Debug, Clone, PartialEq)]
pub struct SweepArgs {
    /// The table.
    pub table: Table,
    /// One spin law per α, in order.
    pub laws: Vec<SpinLaw>,
    /// Initial conditions per α (indices `0..ics`).
    pub ics: u64,
    /// Collisions per initial condition.
    pub collisions: u64,
    /// How the exponent is measured.
    pub method: Method,
    /// Seed of the initial conditions.
    pub seed: u64,
    /// Where the JSON document goes.
    pub json: PathBuf,
    /// How initial conditions are drawn.
    pub sampler: Sampler,
    /// Worker threads.
    pub threads: Threads,
}

impl SweepArgs {
    /// Read `args` (without the program name).
    ///
    /// # Errors
    /// An [`ArgError`] naming the option: unknown, repeated or missing
    /// options, a table spec, α, number, method or sampler that cannot be
    /// read, fewer than 2 initial conditions, no collisions, zero threads,
    /// α outside `[0, 1]` without `--extended`.
    pub fn try_parse_from<I, S>(args: I) -> Result<Parsed<SweepArgs>, ArgError>
    where
        I: IntoIterator<Item = S>,
        S: Into<String>,
    {
        let m = match parse_options(&SWEEP_OPTIONS, args)? {
            Parsed::Run(m) => m,
            Parsed::Help => return Ok(Parsed::Help),
        };
        let extended = m.flag("extended");
        let alphas = m.value("alphas").unwrap_or_default();
        let laws = alphas
            .split(',')
            .map(|a| {
                let a = a.trim();
                let alpha: f64 = a.parse().map_err(|_| {
                    ArgError::invalid("alphas", alphas, format!("`{a}` is not a number"))
                })?;
                let law = if extended {
                    SpinLaw::extended(alpha)
                } else {
                    SpinLaw::new(alpha)
                };
                law.map_err(|e| match e {
                    SpinLawError::Unphysical(_) => ArgError::invalid(
                        "alphas",
                        alphas,
                        format!("alpha = {alpha} is outside [0, 1]; pass --extended to allow it"),
                    ),
                    e => ArgError::invalid("alphas", alphas, e),
                })
            })
            .collect::<Result<Vec<SpinLaw>, ArgError>>()?;
        let threads = match m.get::<usize>("threads") {
            Ok(None) => Threads::All,
            _ => Threads::Fixed(at_least(&m, "threads", 1)? as usize),
        };
        Ok(Parsed::Run(SweepArgs {
            table: required(&m, "table")?,
            laws,
            ics: at_least(&m, "ics", 2)?,
            collisions: at_least(&m, "collisions", 1)?,
            method: required(&m, "method")?,
            seed: at_least(&m, "seed", 0)?,
            json: PathBuf::from(m.value("json").unwrap_or_default()),
            sampler: m.get("sampler")?.unwrap_or(Sampler::Paper),
            threads,
        }))
    }

    /// Read the process's arguments; on `--help` print the usage and exit 0,
    /// on a bad argument print the error and the usage to stderr and exit 2.
    pub fn parse_or_exit() -> SweepArgs {
        let parsed = Self::try_parse_from(std::env::args().skip(1));
        exit_on_error("sweep", &sweep_usage(), parsed)
    }

    /// The α of each point.
    pub fn alphas(&self) -> Vec<f64> {
        self.laws.iter().map(SpinLaw::alpha).collect()
    }

    /// The ensemble of one point: the table, `law` and every other setting.
    pub fn ensemble(&self, law: SpinLaw) -> Ensemble {
        Ensemble::new(self.table, law)
            .with_sampler(self.sampler)
            .with_seed(self.seed)
            .with_ics(self.ics)
            .with_collisions(self.collisions)
            .with_method(self.method)
            .with_threads(self.threads)
    }
}

/// The value of a required option read as a `T`.
fn required<T>(m: &Matches, option: &'static str) -> Result<T, ArgError>
where
    T: std::str::FromStr,
    T::Err: std::fmt::Display,
{
    m.get(option)?.ok_or(ArgError::Missing(option))
}

/// An integer option that must be at least `min`.
fn at_least(m: &Matches, option: &'static str, min: u64) -> Result<u64, ArgError> {
    let v = m.value(option).unwrap_or_default();
    let n: u64 = m
        .get(option)
        .map_err(|_| ArgError::invalid(option, v, "not a non-negative integer"))?
        .ok_or(ArgError::Missing(option))?;
    if n < min {
        return Err(ArgError::invalid(
            option,
            v,
            format!("must be at least {min}"),
        ));
    }
    Ok(n)
}

/// The usage text of the `sweep` example.
pub fn sweep_usage() -> String {
    usage_text(
        "λ(α) on one table, written as JSON after every point.",
        "sweep",
        &SWEEP_OPTIONS,
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    const GOOD: &str = "--table stadium:a=1 --alphas 0,0.5 --ics 8 --collisions 2000 --method fd --seed 1 --json s.json";

    fn parse(line: &str) -> Result<SweepArgs, ArgError> {
        match SweepArgs::try_parse_from(line.split_whitespace())? {
            Parsed::Run(a) => Ok(a),
            Parsed::Help => panic!("help"),
        }
    }

    #[test]
    fn reads_every_option() {
        let a = parse(GOOD).unwrap();
        assert_eq!(a.table, "stadium:a=1".parse::<Table>().unwrap());
        assert_eq!(a.alphas(), vec![0.0, 0.5]);
        assert_eq!((a.ics, a.collisions, a.seed), (8, 2_000, 1));
        assert_eq!(a.method, Method::default());
        assert_eq!((a.sampler, a.threads), (Sampler::Paper, Threads::All));
        assert_eq!(a.json, PathBuf::from("s.json"));
        let b = parse(&format!("{GOOD} --sampler microcanonical --threads 2")).unwrap();
        assert_eq!(
            (b.sampler, b.threads),
            (Sampler::Microcanonical, Threads::Fixed(2))
        );
        let e = b.ensemble(b.laws[1]);
        assert_eq!(
            (e.n_ics(), e.collisions, e.seed, e.alpha()),
            (8, 2_000, 1, 0.5)
        );
        assert_eq!(
            parse(&GOOD.replace("0,0.5", "0,1.5"))
                .map(|_| ())
                .unwrap_err()
                .to_string(),
            "`--alphas 0,1.5`: alpha = 1.5 is outside [0, 1]; pass --extended to allow it"
        );
        let x = parse(&format!("{} --extended", GOOD.replace("0,0.5", "0,1.5"))).unwrap();
        assert_eq!(x.alphas(), vec![0.0, 1.5]);
    }

    #[test]
    fn bad_arguments_are_errors() {
        let err = |line: String| parse(&line).map(|_| ()).unwrap_err();
        assert_eq!(
            err(GOOD.replace("--json s.json", "")),
            ArgError::Missing("json")
        );
        assert_eq!(
            err(GOOD.replace("8", "1")),
            ArgError::invalid("ics", "1", "must be at least 2")
        );
        assert_eq!(
            err(GOOD.replace("--seed 1", "--seed x")),
            ArgError::invalid("seed", "x", "not a non-negative integer")
        );
        assert!(matches!(
            err(GOOD.replace("fd", "rk4")),
            ArgError::Invalid {
                option: "method",
                ..
            }
        ));
        assert!(matches!(
            err(GOOD.replace("stadium:a=1", "oval")),
            ArgError::Invalid {
                option: "table",
                ..
            }
        ));
        assert!(matches!(
            err(GOOD.replace("0,0.5", "0,x")),
            ArgError::Invalid {
                option: "alphas",
                ..
            }
        ));
        assert_eq!(
            err(format!("{GOOD} --threads 0")),
            ArgError::invalid("threads", "0", "must be at least 1")
        );
        assert_eq!(err(format!("{GOOD} --ics 9")), ArgError::Repeated("ics"));
        assert_eq!(
            err(format!("{GOOD} --extended=1")),
            ArgError::UnexpectedValue("extended")
        );
        assert_eq!(SweepArgs::try_parse_from(["--help"]), Ok(Parsed::Help));
        assert!(sweep_usage().contains("--json PATH"));
    }
}
